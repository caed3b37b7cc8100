// Packed portals and links: see packed_portals.h.
#include "packed_portals.h"

#include <algorithm>

namespace lintel::detail {

void PackedPortals::prepare(const World& world) {
  portals_.assign(world.portals.size(), PackedPortal{});
  inline_vertices_.assign(world.portals.size(), InlineVertices{});
  vertices_.clear();
  for (size_t i = 0; i < world.portals.size(); ++i) {
    const Portal& portal = world.portals[i];
    PackedPortal& p = portals_[i];
    p.normal = portal.normal_world;
    p.plane_d = portal.plane_d_world;
    p.from = portal.from;
    p.to = portal.to;
    p.first_vertex = static_cast<uint32_t>(vertices_.size());
    p.vertex_count = static_cast<uint8_t>(portal.polygon_world.size());  // <= kMaxPortalVertices
    p.two_way = portal.two_way;
    p.linked = portal.linked();
    for (const glm::vec3& v : portal.polygon_world) p.box.extend(v);
    if (portal.polygon_world.size() <= kInlinePortalVertices)
      std::copy(portal.polygon_world.begin(), portal.polygon_world.end(), inline_vertices_[i].v);
    else
      vertices_.insert(vertices_.end(), portal.polygon_world.begin(), portal.polygon_world.end());
  }
  cell_link_first_.assign(world.cells.size() + 1, 0);
  cell_links_.clear();
  for (size_t c = 0; c < world.cells.size(); ++c) {
    cell_links_.insert(cell_links_.end(), world.cells[c].links.begin(), world.cells[c].links.end());
    cell_link_first_[c + 1] = static_cast<uint32_t>(cell_links_.size());
  }
}

}  // namespace lintel::detail
