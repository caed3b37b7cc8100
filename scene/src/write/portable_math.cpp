// Portable elementary functions: Cody-Waite range reduction (fdlibm's split of pi/2 and ln 2)
// followed by Taylor polynomials long enough for double precision on the reduced range.
#include "write/portable_math.h"

#include <cassert>
#include <cmath>

namespace lintel::gen {
namespace {

// pi/2 and ln 2 in two parts: the high parts have trailing zero bits, so k * high is exact.
constexpr double kPiOver2High = 1.57079632673412561417e+00;
constexpr double kPiOver2Low = 6.07710050650619224932e-11;
constexpr double kLn2High = 6.93147180369123816490e-01;
constexpr double kLn2Low = 1.90821492927058770002e-10;

// sin and cos on [-pi/4, pi/4]; the next Taylor terms are below 1e-17.
double sin_reduced(double r) {
  const double r2 = r * r;
  double term = r, sum = r;
  for (int n = 1; n <= 9; ++n) {
    term *= -r2 / double((2 * n) * (2 * n + 1));
    sum += term;
  }
  return sum;
}

double cos_reduced(double r) {
  const double r2 = r * r;
  double term = 1.0, sum = 1.0;
  for (int n = 1; n <= 9; ++n) {
    term *= -r2 / double((2 * n - 1) * (2 * n));
    sum += term;
  }
  return sum;
}

// Quadrant k and remainder r with x = k * pi/2 + r, |r| <= pi/4 (for |x| well below 1e9).
double reduce_quadrant(double x, long& k) {
  const double q = std::floor(x / (kPi / 2) + 0.5);
  k = long(q);
  return (x - q * kPiOver2High) - q * kPiOver2Low;
}

}  // namespace

double portable_sin(double x) {
  long k = 0;
  const double r = reduce_quadrant(x, k);
  switch (((k % 4) + 4) % 4) {
    case 0:
      return sin_reduced(r);
    case 1:
      return cos_reduced(r);
    case 2:
      return -sin_reduced(r);
    default:
      return -cos_reduced(r);
  }
}

double portable_cos(double x) {
  long k = 0;
  const double r = reduce_quadrant(x, k);
  switch (((k % 4) + 4) % 4) {
    case 0:
      return cos_reduced(r);
    case 1:
      return -sin_reduced(r);
    case 2:
      return -cos_reduced(r);
    default:
      return sin_reduced(r);
  }
}

double portable_exp(double x) {
  assert(std::fabs(x) < 700.0);
  const double k = std::floor(x / 0.69314718055994530942 + 0.5);
  const double r = (x - k * kLn2High) - k * kLn2Low;  // |r| <= ln2 / 2
  double term = 1.0, sum = 1.0;
  for (int n = 1; n <= 18; ++n) {
    term *= r / double(n);
    sum += term;
  }
  return std::ldexp(sum, int(k));
}

double portable_log(double x) {
  assert(x > 0.0 && std::isfinite(x));
  int e = 0;
  double m = std::frexp(x, &e);  // x = m * 2^e, m in [0.5, 1)
  if (m < 0.70710678118654752440) {
    m *= 2.0;
    --e;
  }
  // ln m = 2 atanh(s), s = (m - 1) / (m + 1), |s| <= 0.172: 20 odd terms reach double precision.
  const double s = (m - 1.0) / (m + 1.0), s2 = s * s;
  double power = s, sum = 0.0;
  for (int n = 0; n < 20; ++n) {
    sum += power / double(2 * n + 1);
    power *= s2;
  }
  return 2.0 * sum + double(e) * kLn2High + double(e) * kLn2Low;
}

double degrees(double deg) { return deg * (kPi / 180.0); }

glm::dquat rotation_about(const glm::dvec3& axis, double radians) {
  const glm::dvec3 a = glm::normalize(axis);
  const double s = portable_sin(0.5 * radians);
  return glm::dquat(portable_cos(0.5 * radians), s * a.x, s * a.y, s * a.z);
}

glm::dquat rotation_between(const glm::dvec3& from, const glm::dvec3& to) {
  const double d = glm::dot(from, to);
  if (d < -0.999999) {
    // Opposite: half a turn about any axis perpendicular to `from`.
    glm::dvec3 axis = glm::cross(glm::dvec3(1, 0, 0), from);
    if (glm::dot(axis, axis) < 1e-6) axis = glm::cross(glm::dvec3(0, 1, 0), from);
    axis = glm::normalize(axis);
    return glm::dquat(0.0, axis.x, axis.y, axis.z);
  }
  const glm::dvec3 c = glm::cross(from, to);
  return glm::normalize(glm::dquat(1.0 + d, c.x, c.y, c.z));
}

}  // namespace lintel::gen
