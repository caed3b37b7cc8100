// The random numbers and sample warps of the path tracer: a per-pixel PCG32 stream, cosine-weighted
// hemisphere directions, an orthonormal basis about a normal, and the self-intersection offset.
// Header-only because they sit in the innermost loop.
//   PCG32: M. O'Neill, "PCG: A Family of Simple Fast Space-Efficient Statistically Good
//          Algorithms for Random Number Generation", 2014 (pcg-random.org, pcg32_random_r).
//   Basis: T. Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017.
//   Offset: C. Waechter, N. Binder, "A Fast and Robust Method for Avoiding Self-Intersection",
//           Ray Tracing Gems, ch. 6, 2019.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace lintel::pathtrace_detail {

inline constexpr float kPi = 3.14159265358979323846f;

// SplitMix64 finalizer (Steele et al., 2014): spreads (seed, pixel) so neighbouring pixels get
// unrelated PCG streams.
inline uint64_t mix64(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// One stream per pixel, seeded from (seed, pixel index) only: the image does not depend on which
// thread renders which pixel.
class PixelRng {
 public:
  PixelRng(uint64_t seed, uint64_t pixel) {
    const uint64_t stream = mix64(pixel + 0x9e3779b97f4a7c15ull);
    inc_ = (stream << 1u) | 1u;
    state_ = 0;
    next();
    state_ += mix64(seed ^ mix64(pixel));
    next();
  }
  uint32_t next() {
    const uint64_t old = state_;
    state_ = old * 6364136223846793005ull + inc_;
    const uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    const uint32_t rot = static_cast<uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }
  // Uniform in [0, 1): the top 24 bits, so 1.0f is never returned.
  float uniform() { return static_cast<float>(next() >> 8) * (1.0f / 16777216.0f); }

 private:
  uint64_t state_ = 0, inc_ = 0;
};

// Tangent t and bitangent b with (t, b, n) right-handed and orthonormal, for unit n.
inline void orthonormal_basis(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  const float c = n.x * n.y * a;
  t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
  b = glm::vec3(c, sign + n.y * n.y * a, -n.y);
}

// Direction with pdf cos(theta) / pi about unit n (Malley's method: a uniform disk point lifted).
inline glm::vec3 cosine_hemisphere(const glm::vec3& n, float u1, float u2) {
  const float r = std::sqrt(u1);
  const float phi = 2.0f * kPi * u2;
  glm::vec3 t, b;
  orthonormal_basis(n, t, b);
  const float z = std::sqrt(std::max(0.0f, 1.0f - u1));
  return glm::normalize(r * std::cos(phi) * t + r * std::sin(phi) * b + z * n);
}

// Moves a surface point p off its surface along the normal n (the side the next ray leaves from)
// by a few ulps of p, so the offset stays tiny near the origin and still works 1e4 m away.
inline glm::vec3 offset_from_surface(const glm::vec3& p, const glm::vec3& n) {
  constexpr float kOrigin = 1.0f / 32.0f, kFloatScale = 1.0f / 65536.0f, kIntScale = 256.0f;
  glm::vec3 out;
  for (int i = 0; i < 3; ++i) {
    const int of = static_cast<int>(kIntScale * n[i]);
    const float moved = std::bit_cast<float>(std::bit_cast<int32_t>(p[i]) + (p[i] < 0.0f ? -of : of));
    out[i] = std::fabs(p[i]) < kOrigin ? p[i] + kFloatScale * n[i] : moved;
  }
  return out;
}

}  // namespace lintel::pathtrace_detail
