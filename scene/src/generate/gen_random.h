// The generators' only source of randomness: splitmix64 seeding and xoshiro256** (Blackman and
// Vigna, "Scrambled linear pseudorandom number generators", 2018), with our own mappings to
// doubles, because std:: distributions differ between standard libraries and a seed must give
// the same scene bytes everywhere.
#pragma once

#include "write/portable_math.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstdint>

namespace lintel::gen {

class GenRandom {
 public:
  explicit GenRandom(uint64_t seed) {
    uint64_t x = seed;
    for (uint64_t& word : state_) word = splitmix64(x);
  }

  uint64_t next_u64() {
    const uint64_t result = rotl(state_[1] * 5, 7) * 9;
    const uint64_t t = state_[1] << 17;
    state_[2] ^= state_[0];
    state_[3] ^= state_[1];
    state_[1] ^= state_[2];
    state_[0] ^= state_[3];
    state_[2] ^= t;
    state_[3] = rotl(state_[3], 45);
    return result;
  }

  // Uniform in [0, 1): the top 53 bits scaled, exact in any IEEE double arithmetic.
  double uniform01() { return double(next_u64() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }
  // Log-uniform in [lo, hi], lo > 0: scales spread evenly over orders of magnitude.
  double log_uniform(double lo, double hi) { return lo * portable_exp(uniform01() * portable_log(hi / lo)); }
  bool chance(double p) { return uniform01() < p; }

  // Uniform in [0, n), n > 0, without modulo bias (rejection on the top of the range).
  uint32_t below(uint32_t n) {
    const uint64_t limit = UINT64_MAX - UINT64_MAX % n;
    uint64_t x;
    do x = next_u64();
    while (x >= limit);
    return uint32_t(x % n);
  }

  // Uniform random rotation: a point uniform in the unit 4-ball, normalized. Rejection instead of
  // Shoemake's formula keeps libm's sin/cos (not bit-identical across platforms) out of it.
  glm::dquat rotation() {
    for (;;) {
      const glm::dvec4 v(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      const double len2 = glm::dot(v, v);
      if (len2 > 1e-4 && len2 <= 1.0) {
        const glm::dvec4 u = v / std::sqrt(len2);
        return glm::dquat(u.w, u.x, u.y, u.z);
      }
    }
  }

 private:
  static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  static uint64_t splitmix64(uint64_t& x) {
    uint64_t z = (x += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  uint64_t state_[4];
};

}  // namespace lintel::gen
