// Shared by the scene tests: where the fixtures are, and how to run the `lintel` CLI and capture
// its exit code and stderr.
#pragma once

#include <string>
#include <vector>

namespace lintel::test {

// Absolute path of tests/scene/fixtures/<relative>.
std::string fixture(const std::string& relative);

struct CliResult {
  int exit_code = -1;
  std::vector<std::string> stderr_lines;
};

// Runs "$LINTEL_BIN <args>" (arguments single-quoted for the shell) with stdout discarded.
CliResult run_lintel(const std::vector<std::string>& args);

// The lines joined with newlines, for failure messages.
std::string joined(const std::vector<std::string>& lines);

// A fresh empty directory under the system temp dir, for files a test writes.
std::string scratch_dir(const std::string& name);

}  // namespace lintel::test
