// Error printing and argument parsing shared by every subcommand.
#include "cli_common.h"

#include "resource_budget.h"

#include <lintel/scene_io.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <limits>
#include <sstream>
#include <thread>

namespace lintel::cli {

int fail(const std::string& message) {
  std::fprintf(stderr, "lintel: error: %s\n", printable(message).c_str());
  return kExitBadInput;
}

int fail(const Status& status) {
  fail(status.message());
  return exit_code_of(status);
}

void warn(const std::string& message) { std::fprintf(stderr, "lintel: warning: %s\n", printable(message).c_str()); }

Status load_scene(const std::string& path, const LoadOptions& options, World& world, std::vector<std::string>* warnings,
                  bool quiet) {
  std::vector<std::string> local;
  std::vector<std::string>& sink = warnings ? *warnings : local;
  Status status = load_world(path, options, world, &sink);
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

void add_load_options(CLI::App* cmd, LoadOptions& options) {
  cmd->add_flag("--allow-outside-paths", options.allow_outside_paths,
                "Let buffer/image URIs point outside the scene's folder (refused by default)");
  options.max_memory_bytes = physical_memory_bytes() / 2;
  cmd->add_option_function<std::string>(
         "--max-memory",
         [&options](const std::string& text) {
           if (Status s = parse_byte_size(text, options.max_memory_bytes); !s) throw CLI::ValidationError(s.message());
         },
         "Refuse work estimated to need more memory than this: bytes, or with K/M/G (default: half of physical memory)")
      ->type_name("BYTES");
}

CLI::Validator finite_range(double lo, double hi) {
  std::ostringstream range;
  range << "[" << lo << ", " << hi << "]";
  return CLI::Validator(
      [lo, hi, text = range.str()](std::string& value) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(value.c_str(), &end);
        if (end == value.c_str() || *end != '\0') return "'" + value + "' is not a number";
        if (!std::isfinite(v)) return "'" + value + "' is not a finite number";
        if (v < lo || v > hi) return value + " is outside " + text;
        return {};
      },
      "FINITE in " + range.str());
}

CLI::Validator thread_count() {
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  return CLI::Validator(
      [hardware](std::string& value) -> std::string {
        char* end = nullptr;
        const long long v = std::strtoll(value.c_str(), &end, 10);
        if (end == value.c_str() || *end != '\0') return "'" + value + "' is not a whole number";
        if (v < 1 || v > (long long)hardware)
          return value + " threads: expected 1 to " + std::to_string(hardware) + " (this machine's hardware threads)";
        return {};
      },
      "1.." + std::to_string(hardware));
}

std::string printable(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '\n')
      out += "\\n";
    else if (c == '\r')
      out += "\\r";
    else if (c == '\t')
      out += "\\t";
    else if (c < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    } else {
      out += ch;
    }
  }
  return out;
}

std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace lintel::cli
