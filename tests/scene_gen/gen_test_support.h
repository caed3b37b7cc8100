// Shared helpers of the generator tests: scenes built through the writer and the loader, world
// space triangles with their owning cell, brute-force ray and segment tests, and the portal
// graph's cycle count.
#pragma once

#include <lintel/scene_desc.h>
#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace lintel::gen_test {

// SceneDesc -> GLB -> validating loader. Fails the current test (ADD_FAILURE) on an error or a
// warning; `lone_cell` accepts the one warning a scene of a single cell must get (no portals).
bool load(const SceneDesc& scene, const std::string& label, World& out, bool lone_cell = false);

struct OwnedTriangle {
  glm::dvec3 a, b, c;
  uint32_t cell = 0;
  int instance = -1;  // -1: the cell's shell
};

// World-space triangles of every shell (and, when asked, every instance).
std::vector<OwnedTriangle> world_triangles(const World& world, bool with_instances);

// Möller-Trumbore in double, both faces: the ray parameter of the hit, or -1.
double ray_triangle(const glm::dvec3& origin, const glm::dvec3& dir, const OwnedTriangle& tri);

// Where the segment p->q crosses the portal's plane inside its polygon: the distance from the
// crossing point to the polygon's outline (> 0), or -1 when it does not cross inside.
double portal_crossing_margin(const Portal& portal, const glm::dvec3& p, const glm::dvec3& q);

// Ray parameter where origin + t dir crosses the portal inside its polygon (with its distance to
// the outline in `margin`), or -1.
double ray_portal(const Portal& portal, const glm::dvec3& origin, const glm::dvec3& dir, double& margin);

// Whether a world point lies in a cell's volume box (cell space), with a relative tolerance.
bool in_volume_box(const Cell& cell, const glm::dvec3& p_world);

// Point-in-volume by ray parity against the cell's volume triangles (which must be present).
bool in_volume(const Cell& cell, const glm::dvec3& p_world);

// True when the rotation part of the matrix is not a multiple of 90 degrees about every axis
// (some entry of the normalized 3x3 is far from 0 and +-1).
bool has_odd_rotation(const glm::mat4& m);

}  // namespace lintel::gen_test
