// The cells an instance's world box reaches through portals (instance_reach.h). A flood over the
// portal graph, limited to what the box overlaps; Godot's rooms lesson (objects dropping while
// they straddle two rooms) says a portal engine must list such objects in every room they touch.
#include <lintel/instance_reach.h>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace lintel {
namespace {

// Whether the box reaches the portal's plane: its corners' signed distances do not all have one
// sign, with a tolerance so the test stays conservative: the polygon's own distance from its
// plane (the loader allows 1e-3 x the portal's size) plus float rounding of the coordinates.
bool box_meets_plane(const Aabb& box, const Portal& portal) {
  const glm::dvec3 n(portal.normal_world);
  const glm::dvec3 lo(box.min), hi(box.max);
  const double d = double(portal.plane_d_world);
  const double far = glm::dot(n, glm::dvec3(n.x >= 0 ? hi.x : lo.x, n.y >= 0 ? hi.y : lo.y, n.z >= 0 ? hi.z : lo.z)) - d;
  const double near = glm::dot(n, glm::dvec3(n.x >= 0 ? lo.x : hi.x, n.y >= 0 ? lo.y : hi.y, n.z >= 0 ? lo.z : hi.z)) - d;
  double scale = std::max(std::abs(d), 1.0);
  for (int k = 0; k < 3; ++k) scale = std::max({scale, std::abs(lo[k]), std::abs(hi[k])});
  double off_plane = 0.0;
  for (const glm::vec3& v : portal.polygon_world) off_plane = std::max(off_plane, std::abs(glm::dot(n, glm::dvec3(v)) - d));
  const double tolerance = off_plane + 1e-5 * scale;
  return near <= tolerance && far >= -tolerance;
}

}  // namespace

void InstanceReach::compute(const World& world) {
  const size_t n_cells = world.cells.size();
  std::vector<Aabb> volume_world(n_cells), portal_world(world.portals.size());
  for (size_t c = 0; c < n_cells; ++c)
    volume_world[c] = transform_aabb(world.cells[c].cell_to_world, world.cells[c].volume_box_cell);
  for (size_t p = 0; p < world.portals.size(); ++p)
    for (const glm::vec3& v : world.portals[p].polygon_world) portal_world[p].extend(v);

  first.assign(1, 0);
  first.reserve(world.instances.size() + 1);
  cells.clear();
  cells.reserve(world.instances.size());
  std::vector<uint8_t> seen(n_cells, 0);
  std::vector<uint32_t> stack;
  for (const Instance& inst : world.instances) {
    assert(inst.cell < n_cells);
    const size_t own = cells.size();
    cells.push_back(inst.cell);
    seen[inst.cell] = 1;
    if (!inst.bounds_world.empty()) {
      stack.assign(1, inst.cell);
      while (!stack.empty()) {
        const uint32_t c = stack.back();
        stack.pop_back();
        for (const PortalLink& link : world.cells[c].links) {
          if (seen[link.neighbour]) continue;
          if (!boxes_overlap(inst.bounds_world, portal_world[link.portal]) ||
              !box_meets_plane(inst.bounds_world, world.portals[link.portal]))
            continue;
          if (!boxes_overlap(inst.bounds_world, volume_world[link.neighbour])) continue;
          seen[link.neighbour] = 1;
          cells.push_back(link.neighbour);
          stack.push_back(link.neighbour);
        }
      }
    }
    for (size_t k = own; k < cells.size(); ++k) seen[cells[k]] = 0;
    std::sort(cells.begin() + std::ptrdiff_t(own) + 1, cells.end());
    first.push_back(uint32_t(cells.size()));
  }
}

}  // namespace lintel
