// Internal: what a build reads of the World's portals and of its cells' links, packed. A Portal
// spans five cache lines and keeps its vertices in an allocation of their own, and each Cell its
// links in another; a build that starts with cold caches (a game renders between two builds) pays
// for every line, so the builder reads a one-line copy per portal, its vertices from a line at the
// same index (up to 5 vertices) or one shared array, and all cells' links from another. It also
// keeps the build's projection cache entry there (portal_traversal.cpp). Filled by prepare() for a World (its revision); the
// open flags are not copied: doors toggle live (World::set_portal_open), so the build reads them
// from the World.
#pragma once

#include <lintel/aabb.h>
#include <lintel/world.h>

#include "prefetch.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace lintel::detail {

struct alignas(64) PackedPortal {
  glm::vec3 normal{0.0f};  // Portal::normal_world
  float plane_d = 0.0f;    // Portal::plane_d_world
  uint32_t from = 0, to = 0;
  uint32_t first_vertex = 0;  // into PackedPortals' shared vertex array (more than 5 vertices)
  uint8_t vertex_count = 0;   // <= kMaxPortalVertices
  bool two_way = false, linked = false;
  Aabb box;  // of the vertices, world space: the flood queue's key
  // The build's projection cache entry, in the line process_link reads anyway: the build
  // (stamp) that projected this portal, and where it put the projection (portal_traversal.cpp).
  uint32_t projection_stamp = 0;
  uint32_t projection_slot = 0;
};
static_assert(sizeof(PackedPortal) == 64);

// A portal's vertices in a line of their own at an address known from its index alone, so that a
// build can ask for them together with the portal's packed line, before reading either (most
// portals are quads). Portals with more vertices keep them in the shared array.
inline constexpr uint32_t kInlinePortalVertices = 5;
struct alignas(64) InlineVertices {
  glm::vec3 v[kInlinePortalVertices];
};
static_assert(sizeof(InlineVertices) == 64);

class PackedPortals {
 public:
  void prepare(const World& world);  // allocates

  const PackedPortal& operator[](uint32_t portal) const { return portals_[portal]; }
  PackedPortal& operator[](uint32_t portal) { return portals_[portal]; }
  void clear_projection_stamps() {
    for (PackedPortal& p : portals_) p.projection_stamp = 0;
  }
  // Portal::polygon_world, the same floats.
  std::span<const glm::vec3> polygon(uint32_t portal) const {
    const PackedPortal& p = portals_[portal];
    if (p.vertex_count <= kInlinePortalVertices) return {inline_vertices_[portal].v, p.vertex_count};
    return {vertices_.data() + p.first_vertex, p.vertex_count};
  }
  // The lines of `portal` a build reads (prefetch.h): its packed line and, where they are inline,
  // its vertices.
  void prefetch(uint32_t portal) const {
    prefetch_read(&portals_[portal]);
    prefetch_read(&inline_vertices_[portal]);
  }
  // Cell::links, in their order.
  std::span<const PortalLink> links(uint32_t cell) const {
    return {cell_links_.data() + cell_link_first_[cell], cell_link_first_[cell + 1] - cell_link_first_[cell]};
  }

 private:
  std::vector<PackedPortal> portals_;
  std::vector<InlineVertices> inline_vertices_;  // per portal; used when vertex_count <= 5
  std::vector<glm::vec3> vertices_;              // the larger portals' vertices
  std::vector<uint32_t> cell_link_first_;        // cell c's links are [first[c], first[c + 1])
  std::vector<PortalLink> cell_links_;
};

}  // namespace lintel::detail
