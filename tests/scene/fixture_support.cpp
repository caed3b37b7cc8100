// Fixture paths from LINTEL_SOURCE_DIR (set by lintel_add_test) and a popen-free CLI runner: the
// command's stderr goes to a file that is read back line by line.
#include "fixture_support.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace lintel::test {

std::string fixture(const std::string& relative) {
  return std::string(LINTEL_SOURCE_DIR) + "/tests/scene/fixtures/" + relative;
}

static std::string quoted(const std::string& arg) {
  std::string out = "'";
  for (char c : arg) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& l : lines) out += l + "\n";
  return out;
}

std::string scratch_dir(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("lintel_scene_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

CliResult run_lintel(const std::vector<std::string>& args) {
  const char* bin = std::getenv("LINTEL_BIN");
  if (!bin) throw std::runtime_error("LINTEL_BIN is not set (run the test through ctest)");
  const std::string err_file = scratch_dir("cli") + "/stderr.txt";
  std::string command = quoted(bin);
  for (const std::string& a : args) command += " " + quoted(a);
  command += " >/dev/null 2>" + quoted(err_file);
  const int status = std::system(command.c_str());
  CliResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(err_file);
  for (std::string line; std::getline(in, line);) result.stderr_lines.push_back(line);
  return result;
}

}  // namespace lintel::test
