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
  // Every cell the ray passes (the start cell first), with the ray parameter (meters from the
  // eye) where it enters and leaves it: the points of the ray in [enter, leave] are inside that
  // cell's volume, before any wall or closed door (clamped to the far plane).
  struct Stretch {
    uint32_t cell = 0;
    double enter = 0.0, leave = 0.0;
  };
  std::vector<Stretch> stretches;
  glm::dvec3 origin{0.0}, direction{0.0};  // the ray: origin + t * direction, direction unit
  double t_near = 0.0;                     // where it meets the near plane
  bool ambiguous = false;                  // passed within a millimetre of a portal edge: ignore the ray
};

// The ray through NDC point `ndc` of `view`, starting in `start_cell`.
RayWalk walk_view_ray(const World& world, const View& view, uint32_t start_cell, const glm::dvec2& ndc);

}  // namespace lintel::testing
