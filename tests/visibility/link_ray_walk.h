// Test oracle for linked portals: walks a view ray through open portals like ray_walk.h and, at a
// teleport or mirror, carries the ray by the portal's link (point and direction) into its `to`
// cell. Lists every cell the ray passes beyond the near plane with the view transform it is seen
// through (the product of inverse links, ViewTransform::seen_from_world) and the link depth.
#pragma once

#include <lintel/view.h>
#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lintel::testing {

struct LinkedRaySeen {
  uint32_t cell = 0;
  glm::dmat4 seen_from_world{1.0};
  uint32_t depth = 0;  // linked portals passed before it
};

struct LinkedRayWalk {
  std::vector<LinkedRaySeen> seen;  // in order along the ray
  bool ambiguous = false;           // passed within a millimetre of a portal edge: ignore the ray
  bool beyond_depth = false;        // went on through more than `max_depth` links (not followed)
};

// The ray through NDC point `ndc` of `view`, starting in `start_cell`, following at most
// `max_depth` links (one more link sets beyond_depth and ends the walk).
LinkedRayWalk walk_linked_view_ray(const World& world, const View& view, uint32_t start_cell, const glm::dvec2& ndc,
                                   uint32_t max_depth);

}  // namespace lintel::testing
