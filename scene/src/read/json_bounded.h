// JSON parsing with limits checked before the DOM is built: nesting depth (recursive consumers,
// tinygltf's extras conversion among them, must not overflow the stack) and value count (the DOM
// costs tens of bytes per value, so the count bounds memory for any input).
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <exception>
#include <string>

namespace lintel::scene_read {

inline constexpr size_t kMaxJsonDepth = 64;                // glTF needs about 8; extras get the rest
inline constexpr size_t kMaxJsonValues = size_t{1} << 23;  // 8 M values: well under 1 GiB of DOM

// Parses `size` bytes of JSON into `out`. Returns an empty string on success, otherwise a one-line
// reason ("JSON nesting is deeper than 64 levels", "invalid JSON at byte 12: ..."). Never throws.
std::string parse_json_bounded(const char* text, size_t size, nlohmann::json& out);

// The two halves of parse_json_bounded, for parsers of their own (gltf_json.h): the limits
// checked on the text (empty when within them), and the reason given for an exception the parse
// threw.
std::string json_bounds_error(const char* text, size_t size);
std::string json_parse_error_text(const std::exception& e);

}  // namespace lintel::scene_read
