// The imported scene's doorway walk (see rooms_walk.h), timed by walk_timeline (walking speed).
#include "rooms/rooms_walk.h"

#include "generate/walk_timeline.h"

#include <algorithm>
#include <vector>

namespace lintel::rooms {
namespace {

struct Crossing {
  glm::dvec3 before, after;
};

Crossing crossing(const Portal& p, uint32_t from_cell) {
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const glm::vec3& v : p.polygon_world) {
    lo = glm::min(lo, glm::dvec3(v));
    hi = glm::max(hi, glm::dvec3(v));
  }
  const double d = std::min(0.5, 0.5 * glm::length(hi - lo));
  const glm::dvec3 n = glm::dvec3(p.normal_world) * (p.from == from_cell ? 1.0 : -1.0);
  const glm::dvec3 c(p.centroid_world);
  return {c - d * n, c + d * n};
}

}  // namespace

bool doorway_walk(const World& world, Timeline& out) {
  if (world.cells.empty()) return false;
  std::vector<uint8_t> seen(world.cells.size(), 0);
  std::vector<glm::dvec3> waypoints;
  size_t crossings = 0;
  // Iterative depth first: a frame is (cell, next link to try, the link that entered it).
  struct Frame {
    uint32_t cell;
    size_t next;
    int entered_by;  // portal index, -1 for the start
  };
  std::vector<Frame> stack{{0, 0, -1}};
  seen[0] = 1;
  while (!stack.empty() && crossings < kMaxWalkCrossings) {
    Frame& top = stack.back();
    const Cell& cell = world.cells[top.cell];
    if (top.next < cell.links.size()) {
      const PortalLink link = cell.links[top.next++];
      const Portal& portal = world.portals[link.portal];
      if (!portal.two_way || !portal.open_from_to || seen[link.neighbour]) continue;
      seen[link.neighbour] = 1;
      const Crossing c = crossing(portal, top.cell);
      waypoints.insert(waypoints.end(), {c.before, c.after});
      ++crossings;
      stack.push_back({link.neighbour, 0, int(link.portal)});
      continue;
    }
    if (top.entered_by >= 0) {  // back out the way we came
      const Crossing c = crossing(world.portals[size_t(top.entered_by)], top.cell);
      waypoints.insert(waypoints.end(), {c.before, c.after});
      ++crossings;
    }
    stack.pop_back();
  }
  std::vector<glm::dvec3> kept;
  for (const glm::dvec3& p : waypoints)
    if (kept.empty() || glm::length(p - kept.back()) > 0.01) kept.push_back(p);
  if (kept.size() < 2) return false;
  out = gen::walk_timeline("doorways", 60.0, kept);
  return true;
}

}  // namespace lintel::rooms
