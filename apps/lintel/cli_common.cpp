// Error printing and argument parsing shared by every subcommand.
#include "cli_common.h"

#include <lintel/scene_io.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace lintel::cli {

int fail(const std::string& message) {
  std::fprintf(stderr, "lintel: error: %s\n", message.c_str());
  return kExitBadInput;
}

int fail(const Status& status) {
  fail(status.message());
  return exit_code_of(status);
}

void warn(const std::string& message) { std::fprintf(stderr, "lintel: warning: %s\n", message.c_str()); }

Status load_scene(const std::string& path, World& world, std::vector<std::string>* warnings, bool quiet) {
  std::vector<std::string> local;
  std::vector<std::string>& sink = warnings ? *warnings : local;
  Status status = load_world(path, world, &sink);
  if (status && !quiet)
    for (const std::string& w : sink) warn(w);
  return status;
}

Status parse_vec3(const std::string& text, const std::string& what, glm::vec3& out) {
  std::istringstream in(text);
  double v[3];
  char comma = 0;
  for (int i = 0; i < 3; ++i) {
    if (!(in >> v[i]) || !(std::abs(v[i]) <= std::numeric_limits<float>::max()))  // finite as a float too
      return Status::error(what + ": expected three finite numbers X,Y,Z, got '" + text + "'");
    if (i < 2 && (!(in >> comma) || comma != ','))
      return Status::error(what + ": expected three numbers separated by commas, got '" + text + "'");
  }
  std::string rest;
  if (in >> rest) return Status::error(what + ": trailing text after X,Y,Z in '" + text + "'");
  out = glm::vec3(float(v[0]), float(v[1]), float(v[2]));
  return {};
}

}  // namespace lintel::cli
