// A linear pre-scan of the JSON text (depth and value count, strings skipped), then nlohmann's
// parser, whose exceptions stop here.
#include "read/json_bounded.h"

#include <exception>

namespace lintel::scene_read {
namespace {

struct ScanResult {
  size_t max_depth = 0;
  size_t deepest_at = 0;  // byte offset where max_depth was first reached
  size_t values = 1;
};

// Counts '{', '[' and ',' outside strings: each starts at least one value (or key/value pair).
// Malformed text is left for the real parser to report; the scan only has to be bounded.
ScanResult scan(const char* text, size_t size) {
  ScanResult r;
  size_t depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < size; ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        in_string = false;
      continue;
    }
    switch (c) {
      case '"':
        in_string = true;
        break;
      case '{':
      case '[':
        ++depth;
        ++r.values;
        if (depth > r.max_depth) {
          r.max_depth = depth;
          r.deepest_at = i;
        }
        break;
      case '}':
      case ']':
        if (depth > 0) --depth;
        break;
      case ',':
        ++r.values;
        break;
      default:
        break;
    }
  }
  return r;
}

}  // namespace

std::string parse_json_bounded(const char* text, size_t size, nlohmann::json& out) {
  const ScanResult r = scan(text, size);
  if (r.max_depth > kMaxJsonDepth)
    return "JSON nesting is deeper than " + std::to_string(kMaxJsonDepth) + " levels (" + std::to_string(r.max_depth) +
           " at byte " + std::to_string(r.deepest_at) + ")";
  if (r.values > kMaxJsonValues) return "JSON has more than " + std::to_string(kMaxJsonValues) + " values";
  try {
    out = nlohmann::json::parse(text, text + size);
  } catch (const nlohmann::json::exception& e) {
    // nlohmann's text ("[json.exception.parse_error.101] parse error at line 3, column 7: ...")
    // already says where; drop the bracketed id, which means nothing to a scene author.
    std::string what = e.what();
    const size_t close = what.find("] ");
    if (what.rfind("[json.exception", 0) == 0 && close != std::string::npos) what = what.substr(close + 2);
    return "not valid JSON: " + what;
  } catch (const std::exception& e) {
    return std::string("not valid JSON: ") + e.what();
  }
  return {};
}

}  // namespace lintel::scene_read
