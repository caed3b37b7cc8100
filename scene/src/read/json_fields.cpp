// Strict member reads: a wrong JSON type is a fault, never a silent default.
#include "read/json_fields.h"

#include "read/load_context.h"

#include <cfloat>
#include <cmath>

namespace lintel::scene_read {

const nlohmann::json* member(const nlohmann::json& obj, const char* key) {
  if (!obj.is_object()) return nullptr;
  const auto it = obj.find(key);
  return it == obj.end() ? nullptr : &*it;
}

std::string json_kind(const nlohmann::json& value) {
  if (value.is_number_integer()) return "integer";
  if (value.is_number()) return "number";
  return value.type_name();
}

static std::string wrong_kind(const char* wanted, const nlohmann::json& got) {
  return std::string("must be ") + wanted + ", got " + json_kind(got);
}

std::string read_integer(const nlohmann::json& value, int64_t& out) {
  if (value.is_number_unsigned()) {
    const uint64_t u = value.get<uint64_t>();
    if (u > uint64_t(INT64_MAX)) return "integer " + value.dump() + " is out of range";
    out = static_cast<int64_t>(u);
    return {};
  }
  if (value.is_number_integer()) {
    out = value.get<int64_t>();
    return {};
  }
  return wrong_kind("an integer", value);
}

std::string read_int(const nlohmann::json& value, int& out) {
  int64_t v = 0;
  if (std::string why = read_integer(value, v); !why.empty()) return why;
  if (v < INT32_MIN || v > INT32_MAX) return "integer " + value.dump() + " is out of the 32-bit range";
  out = static_cast<int>(v);
  return {};
}

std::string read_index(const nlohmann::json& value, size_t count, size_t& out) {
  int64_t v = 0;
  if (std::string why = read_integer(value, v); !why.empty()) return why;
  if (v < 0 || uint64_t(v) >= count)
    return "index " + std::to_string(v) + " is out of range (" + std::to_string(count) + " elements)";
  out = static_cast<size_t>(v);
  return {};
}

std::string read_string(const nlohmann::json& value, std::string& out) {
  if (!value.is_string()) return wrong_kind("a string", value);
  const std::string& text = value.get_ref<const std::string&>();
  // A NUL ends the name in every C API and terminal that later shows it: refuse it here.
  if (text.find('\0') != std::string::npos) return "contains a NUL byte (\\u0000)";
  out = text;
  return {};
}

std::string read_bool(const nlohmann::json& value, bool& out) {
  if (!value.is_boolean()) return wrong_kind("true or false", value);
  out = value.get<bool>();
  return {};
}

std::string read_number(const nlohmann::json& value, double& out) {
  if (!value.is_number()) return wrong_kind("a number", value);
  out = value.get<double>();
  if (!std::isfinite(out)) return "is not finite";
  return {};
}

std::string read_float(const nlohmann::json& value, float& out) {
  double d = 0.0;
  if (std::string why = read_number(value, d); !why.empty()) return why;
  if (std::fabs(d) > double(FLT_MAX)) return "value " + number_text(d) + " is not finite as a 32-bit float";
  out = static_cast<float>(d);
  return {};
}

std::string read_float_array(const nlohmann::json& value, size_t n, float* out) {
  if (!value.is_array()) return wrong_kind("an array", value);
  if (value.size() != n) return "must have " + std::to_string(n) + " numbers, has " + std::to_string(value.size());
  for (size_t i = 0; i < n; ++i)
    if (std::string why = read_float(value[i], out[i]); !why.empty()) return "element " + std::to_string(i) + " " + why;
  return {};
}

std::string read_vec3(const nlohmann::json& value, glm::vec3& out) {
  float v[3] = {0, 0, 0};
  if (std::string why = read_float_array(value, 3, v); !why.empty()) return why;
  out = glm::vec3(v[0], v[1], v[2]);
  return {};
}

}  // namespace lintel::scene_read
