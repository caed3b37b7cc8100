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

// One step of the chain: drops the top points of hull[0..k) (never below `floor`) that make no left
// turn to `p`, then pushes `p`.
inline void hull_push(std::span<glm::dvec2> hull, size_t& k, const glm::dvec2& p, size_t floor) {
  while (k >= floor && cross(hull[k - 2], hull[k - 1], p) <= 0.0) --k;
  hull[k++] = p;
}

// The hull of `sorted` (ascending x, then y; repeats allowed) into `hull`, counter-clockwise from
// the first point, collinear and repeated points dropped. `hull` needs sorted.size() + 1 entries.
// Returns the vertex count, or 0 when fewer than 3 remain.
inline uint32_t monotone_chain_sorted(std::span<const glm::dvec2> sorted, std::span<glm::dvec2> hull) {
  const size_t n = sorted.size();
  if (n < 3) return 0;
  size_t k = 0;
  for (size_t i = 0; i < n; ++i) hull_push(hull, k, sorted[i], 2);                       // lower hull
  for (size_t i = n - 1, lower = k + 1; i-- > 0;) hull_push(hull, k, sorted[i], lower);  // upper hull
  // The last point repeats the first.
  return k >= 4 ? static_cast<uint32_t>(k - 1) : 0;
}

}  // namespace lintel::detail
