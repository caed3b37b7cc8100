// The convex hull of a room's vertices: the volume of a room that has no '-bound' (what Godot 3
// does for such rooms). Incremental hull in double precision, checked closed before it is used.
#pragma once

#include <glm/glm.hpp>

#include <vector>

namespace lintel::rooms {

// Distinct input points above this use the room's box instead (the incremental hull is
// O(points x faces); no hand-made room shell comes near it).
inline constexpr size_t kMaxHullPoints = 8192;

// Appends the hull's triangles (3 vertices each, wound outwards, vertices taken exactly from
// `points` so that shared edges match by position) to `triangles`. Returns false, appending
// nothing, when the points are fewer than 4 distinct ones, (nearly) flat or collinear within
// `tolerance`, more than kMaxHullPoints, or the result is not closed.
bool convex_hull_3d(const std::vector<glm::dvec3>& points, double tolerance, std::vector<glm::dvec3>& triangles);

}  // namespace lintel::rooms
