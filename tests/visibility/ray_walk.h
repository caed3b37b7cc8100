// Test oracle: walks a view ray through the world's open portals (Möller-Trumbore against cell
// volumes, point-in-polygon at portals; a closed door is a wall) and lists the cells it sees
// between the near and far planes. Any cell on that list must be visible with the ray's pixel
// inside its region: the traversal may over-estimate (conservative) but must never miss one.
#pragma once

#include <lintel/view.h>
#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lintel::testing {

struct RayWalk {
  std::vector<uint32_t> seen_cells;  // in order along the ray
  bool ambiguous = false;            // passed within a millimetre of a portal edge: ignore the ray
};

// The ray through NDC point `ndc` of `view`, starting in `start_cell`.
RayWalk walk_view_ray(const World& world, const View& view, uint32_t start_cell, const glm::dvec2& ndc);

}  // namespace lintel::testing
