// The two ways cell_volume_contains counts how often a closed volume winds around a point, kept
// visible to the tests that prove they agree (tests/visibility/test_point_in_volume.cpp), and the
// ray's steps that CellVolumeIndex (cell_volume_index.cpp) shares with it.
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

// The ray's direction off the x axis. In the sheared coordinates (u, v) = (y - kShearY x,
// z - kShearZ x) the ray from p is the single point sheared(p).
inline constexpr double kShearY = 0.0123456789, kShearZ = 0.0314159265;
inline glm::dvec2 sheared(const glm::dvec3& p) { return {p.y - kShearY * p.x, p.z - kShearZ * p.x}; }

// The ray from p (cell space) with its margins, relative to the volume's size: a point this close
// to a face, or a ray this close to an edge or vertex, goes to the exact sum instead (the parity of
// a ray through an edge is ambiguous; the solid angle is not).
struct ContainmentRay {
  glm::dvec3 p;
  double pu, pv;  // sheared(p)
  double margin_x, margin_area;
};
ContainmentRay containment_ray(const Cell& cell, const glm::dvec3& p);

// One triangle (cell space) against the ray: crossed with a positive (Up) or negative (Down)
// signed (u, v) area, missed, or too close to an edge, a vertex or p to tell (Ambiguous). A
// triangle whose (u, v) bounds do not hold (pu, pv) is always a Miss.
enum class RayStep { Miss, Up, Down, Ambiguous };
RayStep ray_meets_triangle(const ContainmentRay& r, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

// Adds a step to the signed crossing count; false when the step is ambiguous.
inline bool count_step(RayStep step, int& crossings) {
  if (step == RayStep::Ambiguous) return false;
  crossings += step == RayStep::Up ? 1 : step == RayStep::Down ? -1 : 0;
  return true;
}

// Whether the volume box alone decides containment of p_world: outside the box (widened by a
// relative hair, so that points on a face still reach the winding test) is out, inside a volume
// given by its box alone is in. Otherwise nothing, and `p` is the point in cell space.
std::optional<bool> box_decides(const Cell& cell, const glm::dvec3& p_world, glm::dvec3& p);

}  // namespace lintel
