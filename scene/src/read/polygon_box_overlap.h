// Whether a convex polygon touches an axis-aligned box: how the loader proves that both cells of
// a two-way portal reach the portal (each cell's volume box, in that cell's space).
#pragma once

#include <glm/glm.hpp>

#include <vector>

namespace lintel::scene_read {

// True when the convex planar polygon `poly` and the box [lo - tolerance, hi + tolerance]
// intersect (touching counts). Separating-axis test over the box axes, the polygon's normal and
// the cross products of its edges with the box axes.
bool polygon_touches_box(const std::vector<glm::dvec3>& poly, const glm::dvec3& lo, const glm::dvec3& hi,
                         double tolerance);

}  // namespace lintel::scene_read
