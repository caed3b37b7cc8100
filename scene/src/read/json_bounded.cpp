// A linear pre-scan of the JSON text (depth and value count, strings skipped), then nlohmann's
// parser, whose exceptions stop here.
#include "read/json_bounded.h"

#include <array>
#include <exception>

namespace lintel::scene_read {
namespace {

struct ScanResult {
  size_t max_depth = 0;
  size_t deepest_at = 0;  // byte offset where max_depth was first reached
  size_t values = 1;
};

// Counts '{', '[' and ',' outside strings: each starts at least one value (or key/value pair).
// Malformed text is left for the real parser to report; the scan only has to be bounded. Bytes
// that open or close nothing (digits, letters, spaces, ':') are skipped in a tight loop.
ScanResult scan(const char* text, size_t size) {
  static constexpr std::array<bool, 256> kStructural = [] {
    std::array<bool, 256> t{};
    for (const char c : {'"', '{', '[', '}', ']', ','}) t[static_cast<unsigned char>(c)] = true;
    return t;
  }();
  ScanResult r;
  size_t depth = 0;
  size_t i = 0;
  while (i < size) {
    while (i < size && !kStructural[static_cast<unsigned char>(text[i])]) ++i;
    if (i == size) break;
    const size_t at = i++;
    switch (text[at]) {
      case '"':  // to past the closing quote; a backslash escapes the byte after it
        while (i < size && text[i] != '"') i += text[i] == '\\' ? 2 : 1;
        ++i;
        break;
      case '{':
      case '[':
        ++depth;
        ++r.values;
        if (depth > r.max_depth) {
          r.max_depth = depth;
          r.deepest_at = at;
        }
        break;
      case '}':
      case ']':
        if (depth > 0) --depth;
        break;
      default:  // ','
        ++r.values;
        break;
    }
  }
  return r;
}

}  // namespace

std::string json_bounds_error(const char* text, size_t size) {
  const ScanResult r = scan(text, size);
  if (r.max_depth > kMaxJsonDepth)
    return "JSON nesting is deeper than " + std::to_string(kMaxJsonDepth) + " levels (" + std::to_string(r.max_depth) +
           " at byte " + std::to_string(r.deepest_at) + ")";
  if (r.values > kMaxJsonValues) return "JSON has more than " + std::to_string(kMaxJsonValues) + " values";
  return {};
}

std::string json_parse_error_text(const std::exception& e) {
  // nlohmann's text ("[json.exception.parse_error.101] parse error at line 3, column 7: ...")
  // already says where; drop the bracketed id, which means nothing to a scene author.
  std::string what = e.what();
  const size_t close = what.find("] ");
  if (dynamic_cast<const nlohmann::json::exception*>(&e) && what.rfind("[json.exception", 0) == 0 &&
      close != std::string::npos)
    what = what.substr(close + 2);
  return "not valid JSON: " + what;
}

std::string parse_json_bounded(const char* text, size_t size, nlohmann::json& out) {
  if (std::string why = json_bounds_error(text, size); !why.empty()) return why;
  try {
    out = nlohmann::json::parse(text, text + size);
  } catch (const std::exception& e) {
    return json_parse_error_text(e);
  }
  return {};
}

}  // namespace lintel::scene_read
