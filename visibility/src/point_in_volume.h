// The two ways cell_volume_contains counts how often a closed volume winds around a point, kept
// visible to the tests that prove they agree (tests/visibility/point_in_volume_test.cpp).
#pragma once

#include <lintel/world.h>

#include <glm/glm.hpp>

#include <optional>

namespace lintel {

// Generalized winding number of the volume triangles around p (cell space): the sum of signed
// solid angles over 4 pi. Exact for any p off the surface; costs an atan2 per triangle.
double volume_winding_exact(const Cell& cell, const glm::dvec3& p);

// The signed number of crossings of the ray from p along (1, 0.0123456789, 0.0314159265) -- just
// off the x axis, so that it does not run along axis-aligned faces -- with the volume triangles (cell
// space), or nothing when the ray passes within a small relative margin of an edge or vertex or
// p lies within it of a face. Equal to the winding number of a closed volume when it answers.
std::optional<int> volume_winding_by_ray(const Cell& cell, const glm::dvec3& p);

}  // namespace lintel
