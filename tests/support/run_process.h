// Runs a command line through the shell and captures its exit code, stdout and stderr: how the
// CLI tests observe `lintel` exactly as a user would.
#pragma once

#include <string>

namespace lintel::test {

struct ProcessResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// `command` is passed to /bin/sh; stdout and stderr are captured separately.
ProcessResult run_process(const std::string& command);

// The built CLI (env LINTEL_BIN, set by lintel_add_test).
std::string lintel_bin();

// A fresh empty directory under the system temp dir, unique per call.
std::string make_temp_dir();

// Number of '\n'-terminated lines in `text`.
int count_lines(const std::string& text);

}  // namespace lintel::test
