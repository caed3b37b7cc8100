// Linked-portal test worlds and the ray-walk conservative check (link_test_worlds.h).
#include "link_test_worlds.h"

#include "link_ray_walk.h"

#include <lintel/portal_link.h>

#include <algorithm>
#include <cmath>

namespace lintel::testing {
namespace {

double distance_outside_convex(std::span<const glm::vec2> poly, const glm::dvec2& p) {
  double worst = -1e300;  // largest signed distance outside an edge line (ccw polygon)
  for (size_t i = 0; i < poly.size(); ++i) {
    const glm::dvec2 a(poly[i]), b(poly[(i + 1) % poly.size()]);
    const glm::dvec2 e = b - a;
    const double len = glm::length(e);
    if (len <= 0.0) continue;
    worst = std::max(worst, (e.x * (p.y - a.y) - e.y * (p.x - a.x)) / -len);
  }
  return worst;
}

bool region_contains(const VisibleSet& v, const VisibleCell& c, const glm::dvec2& p, double slack) {
  const ClipRegionView region = v.region(c);
  for (size_t k = 0; k < region.polygons.size(); ++k)
    if (distance_outside_convex(region.polygon(k), p) <= slack) return true;
  return false;
}

bool same_matrix(const glm::dmat4& a, const glm::dmat4& b) {
  double scale = 1.0;
  for (int r = 0; r < 3; ++r) scale = std::max({scale, std::abs(a[3][r]), std::abs(b[3][r])});
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (std::abs(a[c][r] - b[c][r]) > 1e-6 * scale) return false;
  return true;
}

}  // namespace

uint32_t add_linked_portal(TestWorld& t, uint32_t from, uint32_t to, const std::vector<glm::vec3>& polygon_layout,
                           const glm::vec3& from_side_layout, PortalLinkKind kind, const std::string& name) {
  Portal p;
  p.name = name;
  p.from = from;
  p.to = kind == PortalLinkKind::Mirror ? from : to;
  p.two_way = false;
  p.link = kind;
  glm::dvec3 centroid(0.0);
  for (const glm::vec3& v : polygon_layout) {
    p.polygon_world.push_back(t.to_world(v));
    centroid += glm::dvec3(p.polygon_world.back());
  }
  centroid /= double(polygon_layout.size());
  const glm::dvec3 a(p.polygon_world[0]), b(p.polygon_world[1]), c(p.polygon_world[2]);
  glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
  if (glm::dot(n, glm::dvec3(t.to_world(from_side_layout)) - centroid) > 0.0) {
    n = -n;
    std::reverse(p.polygon_world.begin(), p.polygon_world.end());  // normal by the right-hand rule
  }
  p.normal_world = glm::vec3(n);
  p.centroid_world = glm::vec3(centroid);
  p.plane_d_world = float(glm::dot(n, centroid));
  for (const glm::vec3& v : p.polygon_world) {
    p.polygon_from_cell.emplace_back(t.world.cells[p.from].world_to_cell * glm::vec4(v, 1.0f));
    p.polygon_to_cell.emplace_back(t.world.cells[p.to].world_to_cell * glm::vec4(v, 1.0f));
  }
  if (kind == PortalLinkKind::Mirror) p.link_world = mirror_transform(p);
  t.world.portals.push_back(p);
  return uint32_t(t.world.portals.size() - 1);
}

bool link_teleport(World& world, uint32_t source, uint32_t target) {
  Portal& s = world.portals[source];
  s.link_target = int(target);
  s.to = world.portals[target].from;
  return link_onto_target(s, world.portals[target], s.link_world).empty();
}

TestWorld make_facing_mirrors(const WorldOptions& options) {
  TestWorld t = make_chain(1, options);
  const float y0 = 0.3f, y1 = 2.7f, z = 1.6f;
  add_linked_portal(t, 0, 0, {{0, y0, -z}, {0, y0, z}, {0, y1, z}, {0, y1, -z}}, {1, 1, 0}, PortalLinkKind::Mirror,
                    "mirror_west");
  add_linked_portal(t, 0, 0, {{4, y0, -z}, {4, y0, z}, {4, y1, z}, {4, y1, -z}}, {3, 1, 0}, PortalLinkKind::Mirror,
                    "mirror_east");
  if (!finalize_world(t.world).ok()) t.world.cells.clear();
  return t;
}

TestWorld make_teleport_ring(uint32_t rooms, const WorldOptions& options) {
  TestWorld t = make_chain(rooms, options);
  const float east = 4.0f * float(rooms), y1 = 2.2f, z = 0.6f;
  const uint32_t last = rooms - 1;
  const uint32_t e = add_linked_portal(t, last, 0, {{east, 0, -z}, {east, 0, z}, {east, y1, z}, {east, y1, -z}},
                                       {east - 1, 1, 0}, PortalLinkKind::Teleport, "seam_east");
  const uint32_t w = add_linked_portal(t, 0, last, {{0, 0, -z}, {0, 0, z}, {0, y1, z}, {0, y1, -z}}, {1, 1, 0},
                                       PortalLinkKind::Teleport, "seam_west");
  add_linked_portal(t, 0, 0, {{0.5f, 0.3f, -2}, {3.5f, 0.3f, -2}, {3.5f, 2.7f, -2}, {0.5f, 2.7f, -2}}, {2, 1, 0},
                    PortalLinkKind::Mirror, "mirror_south");
  if (!link_teleport(t.world, e, w) || !link_teleport(t.world, w, e) || !finalize_world(t.world).ok())
    t.world.cells.clear();
  return t;
}

LinkCheck check_links_conservative(const World& world, const View& view, uint32_t start_cell, const VisibleSet& visible,
                                   uint32_t grid, double slack_ndc) {
  LinkCheck out;
  for (uint32_t j = 0; j < grid && out.failure.empty(); ++j)
    for (uint32_t i = 0; i < grid && out.failure.empty(); ++i) {
      const glm::dvec2 ndc(-1.0 + (2.0 * i + 1.0) / grid, -1.0 + (2.0 * j + 1.0) / grid);
      const LinkedRayWalk walk = walk_linked_view_ray(world, view, start_cell, ndc, kMaxLinkDepth);
      ++out.rays;
      if (walk.ambiguous) {
        ++out.ambiguous;
        continue;
      }
      for (const LinkedRaySeen& s : walk.seen) {
        bool found = false;
        auto look = [&](const std::vector<VisibleCell>& entries) {
          for (const VisibleCell& c : entries)
            if (c.cell == s.cell && same_matrix(visible.transforms[c.transform].seen_from_world, s.seen_from_world) &&
                region_contains(visible, c, ndc, slack_ndc))
              found = true;
        };
        look(visible.cells);
        look(visible.linked_cells);
        ++out.checked_entries;
        if (!found) {
          out.failure = "pixel (" + std::to_string(ndc.x) + ", " + std::to_string(ndc.y) + "): cell " +
                        world.cells[s.cell].name + " at link depth " + std::to_string(s.depth) +
                        " is seen by the ray but has no entry with that transform containing the pixel";
          break;
        }
      }
      if (walk.beyond_depth && out.failure.empty()) {
        ++out.beyond_depth;
        bool covered = false;
        for (const UnresolvedLink& u : visible.unresolved)
          covered = covered || (ndc.x >= u.rect_ndc.min.x - slack_ndc && ndc.x <= u.rect_ndc.max.x + slack_ndc &&
                                ndc.y >= u.rect_ndc.min.y - slack_ndc && ndc.y <= u.rect_ndc.max.y + slack_ndc);
        if (!covered)
          out.failure = "pixel (" + std::to_string(ndc.x) + ", " + std::to_string(ndc.y) +
                        "): the ray needs more than kMaxLinkDepth links but no unresolved rect covers it";
      }
    }
  return out;
}

}  // namespace lintel::testing
