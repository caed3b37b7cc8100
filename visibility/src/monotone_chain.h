// Internal: Andrew's monotone chain (1979) over points already in (x, y) order, in double: the
// convex hull of the lattice snap (ndc_snap.cpp) and of the merged clip windows
// (pending_merge.cpp). Exact when the coordinates are lattice points or floats of small range, as
// both callers' are, so the same points give the same hull bit for bit.
#pragma once

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <span>

namespace lintel::detail {

inline double cross(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// The hull of `sorted` (ascending x, then y; repeats allowed) into `hull`, counter-clockwise from
// the first point, collinear and repeated points dropped. `hull` needs sorted.size() + 1 entries.
// Returns the vertex count, or 0 when fewer than 3 remain.
inline uint32_t monotone_chain_sorted(std::span<const glm::dvec2> sorted, std::span<glm::dvec2> hull) {
  const size_t n = sorted.size();
  if (n < 3) return 0;
  size_t k = 0;
  for (size_t i = 0; i < n; ++i) {  // lower hull
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], sorted[i]) <= 0.0) --k;
    hull[k++] = sorted[i];
  }
  for (size_t i = n - 1, lower = k + 1; i-- > 0;) {  // upper hull
    while (k >= lower && cross(hull[k - 2], hull[k - 1], sorted[i]) <= 0.0) --k;
    hull[k++] = sorted[i];
  }
  // The last point repeats the first.
  return k >= 4 ? static_cast<uint32_t>(k - 1) : 0;
}

}  // namespace lintel::detail
