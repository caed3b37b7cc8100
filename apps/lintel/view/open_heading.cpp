// most_open_heading (open_heading.h): one visibility build per heading, at the viewer start only.
#include "open_heading.h"

#include <lintel/cell_locate.h>
#include <lintel/visibility_builder.h>

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace lintel::view {

View most_open_heading(const World& world, const View& start) {
  if (world.cells.empty()) return start;
  const glm::dvec3 eye(start.eye_world), look = glm::dvec3(start.target_world) - eye;
  const double horizontal = std::hypot(look.x, look.z);
  if (!(horizontal > 1e-6 * glm::length(look))) return start;  // straight up or down: no heading to turn
  const uint32_t cell = locate_cell(world, eye).cell;
  VisibilityBuilder builder;
  VisibleSet visible;
  auto cells_seen = [&](const View& v) -> size_t {
    return builder.build(world, v, cell, {}, visible).ok() ? visible.cells.size() : 0;
  };
  View best = start;
  size_t most = cells_seen(start);
  const double heading0 = std::atan2(look.z, look.x);
  for (uint32_t k = 0; k < kOpenHeadings; ++k) {
    const double a = heading0 + 2.0 * glm::pi<double>() * double(k + 1) / double(kOpenHeadings);
    View v = start;
    v.target_world = glm::vec3(eye + glm::dvec3(horizontal * std::cos(a), look.y, horizontal * std::sin(a)));
    if (const size_t seen = cells_seen(v); seen > most) {
      most = seen;
      best = v;
    }
  }
  return best;
}

}  // namespace lintel::view
