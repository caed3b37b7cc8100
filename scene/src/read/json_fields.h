// Typed reads of JSON members with the checks the scene format needs (integer vs number, finite
// as a 32-bit float, fixed-length arrays). Each returns an empty string on success, otherwise the
// fault in words ("must be an integer, got string"); callers add the file and element.
#pragma once

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <string>

namespace lintel::scene_read {

// The member `key` of object `obj`, or null when absent (or when obj is not an object).
const nlohmann::json* member(const nlohmann::json& obj, const char* key);

// "string", "number", "object", ... for messages.
std::string json_kind(const nlohmann::json& value);

std::string read_integer(const nlohmann::json& value, int64_t& out);
// An integer that fits an int: glTF indices and enums as the model (tinygltf's types) holds them.
std::string read_int(const nlohmann::json& value, int& out);
// An integer in [0, count): an index into an array of `count` elements.
std::string read_index(const nlohmann::json& value, size_t count, size_t& out);
std::string read_string(const nlohmann::json& value, std::string& out);
std::string read_bool(const nlohmann::json& value, bool& out);
std::string read_number(const nlohmann::json& value, double& out);
// A number that is finite once converted to float (|v| <= FLT_MAX); JSON cannot spell NaN or
// Inf, so "1e39" is how they reach a float field.
std::string read_float(const nlohmann::json& value, float& out);
// An array of exactly n numbers, each finite as float.
std::string read_float_array(const nlohmann::json& value, size_t n, float* out);
std::string read_vec3(const nlohmann::json& value, glm::vec3& out);

}  // namespace lintel::scene_read
