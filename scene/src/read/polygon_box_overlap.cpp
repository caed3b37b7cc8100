// Separating-axis test of a convex polygon against an AABB (Ericson, "Real-Time Collision
// Detection", 2005, section 5.2.1, extended from triangles to convex polygons).
#include "read/polygon_box_overlap.h"

#include <cmath>

namespace lintel::scene_read {
namespace {

// True when `axis` separates the polygon from the box (centre c, half extents h).
bool separates(const glm::dvec3& axis, const std::vector<glm::dvec3>& poly, const glm::dvec3& c, const glm::dvec3& h) {
  const double length = glm::length(axis);
  if (!(length > 1e-12)) return false;  // a degenerate axis separates nothing
  const glm::dvec3 a = axis / length;
  double lo = INFINITY, hi = -INFINITY;
  for (const glm::dvec3& p : poly) {
    const double d = glm::dot(p - c, a);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  const double r = h.x * std::fabs(a.x) + h.y * std::fabs(a.y) + h.z * std::fabs(a.z);
  return lo > r || hi < -r;
}

}  // namespace

bool polygon_touches_box(const std::vector<glm::dvec3>& poly, const glm::dvec3& lo, const glm::dvec3& hi,
                         double tolerance) {
  if (poly.size() < 3) return false;
  const glm::dvec3 c = 0.5 * (lo + hi);
  const glm::dvec3 h = 0.5 * (hi - lo) + glm::dvec3(tolerance);
  const glm::dvec3 box_axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const glm::dvec3& axis : box_axes)
    if (separates(axis, poly, c, h)) return false;
  glm::dvec3 normal(0.0);
  for (size_t i = 0; i < poly.size(); ++i) normal += glm::cross(poly[i], poly[(i + 1) % poly.size()]);
  if (separates(normal, poly, c, h)) return false;
  for (size_t i = 0; i < poly.size(); ++i) {
    const glm::dvec3 edge = poly[(i + 1) % poly.size()] - poly[i];
    for (const glm::dvec3& axis : box_axes)
      if (separates(glm::cross(edge, axis), poly, c, h)) return false;
  }
  return true;
}

}  // namespace lintel::scene_read
