// Shell-out helper for CLI tests (popen for stdout, a temp file for stderr).
#include "run_process.h"

#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace lintel::test {

std::string make_temp_dir() {
  std::string pattern = (std::filesystem::temp_directory_path() / "lintel-test-XXXXXX").string();
  if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
  return pattern;
}

ProcessResult run_process(const std::string& command) {
  const std::string dir = make_temp_dir();
  const std::string err_path = dir + "/stderr";
  ProcessResult result;
  FILE* pipe = popen((command + " 2>'" + err_path + "'").c_str(), "r");
  if (!pipe) throw std::runtime_error("popen failed: " + command);
  char buffer[4096];
  size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.out.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  std::ifstream err(err_path);
  std::stringstream ss;
  ss << err.rdbuf();
  result.err = ss.str();
  std::filesystem::remove_all(dir);
  return result;
}

std::string lintel_bin() {
  const char* bin = std::getenv("LINTEL_BIN");
  if (!bin) throw std::runtime_error("LINTEL_BIN is not set (run through ctest)");
  return bin;
}

int count_lines(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

}  // namespace lintel::test
