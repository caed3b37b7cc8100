// sin, cos, exp and log from +, *, / and ldexp only, so that generated scenes are the same bytes
// on every platform: libm results may differ in the last bit between C libraries, and GCC folds
// constant calls with MPFR, so even one binary could disagree with itself across build types.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace lintel::gen {

inline constexpr double kPi = 3.14159265358979323846;

double portable_sin(double radians);
double portable_cos(double radians);
double portable_exp(double x);
double portable_log(double x);  // x > 0

double degrees(double deg);  // degrees -> radians
// Rotation by `radians` about `axis` (any length > 0), right-handed.
glm::dquat rotation_about(const glm::dvec3& axis, double radians);
// Shortest rotation taking unit vector `from` to unit vector `to`.
glm::dquat rotation_between(const glm::dvec3& from, const glm::dvec3& to);

}  // namespace lintel::gen
