// Portals: resolve the two cells by name, extract the convex polygon in world space, orient it
// from `from` into `to`, express it in both cells' spaces, prove that a two-way portal touches
// both cells' volumes, and link it to the cells that can look through it.
//
// Orientation rule (docs/scene-format.md): probe points just in front of and behind the polygon's
// centroid (steps of 0.1 %, 1 % and 5 % of its size along the normal, each at least twice the
// rounding floor of the portal and of both cells' frames); the normal n points from
// `from` into `to` when `from`'s volume holds the points behind and `to`'s the points in front
// more often than the other way round. Volume meshes are used where given, so an outside cell
// whose box surrounds the house still orients its facade doors (its centre lies inside the house,
// which defeated a rule by volume centres alone). Only when the probes tie: with c_from and c_to
// the centres of the volume boxes, dot(n, c_to - c_from) > 0; then away from c_from, then towards
// c_to; when all are ambiguous the portal is refused. Linked portals (teleports, mirrors) border
// only `from`: the normal points out of `from`'s volume (the same probes and centre, `from` only),
// and the link is resolved once every portal is built (a named target may come later).
#include "read/load_limits.h"
#include "read/mesh_read.h"
#include "read/polygon_box_overlap.h"
#include "read/portal_polygon.h"
#include "read/world_assemble.h"

#include <lintel/cell_locate.h>
#include <lintel/portal_link.h>

#include <algorithm>
#include <cmath>

namespace lintel::scene_read {
namespace {

using Kind = NodeTag::Kind;

// Tolerance for "the polygon touches the volume box": relative to the larger of the two.
constexpr double kTouchTolerance = 1e-3;

glm::dvec3 volume_centre_world(const Cell& cell) {
  return glm::dvec3(glm::dmat4(cell.cell_to_world) * glm::dvec4(glm::dvec3(cell.volume_box_cell.center()), 1.0));
}

// One probe of the orientation rule: `sign` counts when `cell`'s volume holds `point`.
struct Probe {
  uint32_t cell;
  glm::dvec3 point;
  int sign;
};

// A number with the sign of the probes' total (the sum of the signs of those that hold). Each
// probe moves the total by one at most, so they are tested in order only until those left cannot
// change its sign: the probes most likely to count go first.
int probe_score(const World& world, const CellVolumeIndex& volumes, const Probe* probes, int count) {
  int score = 0;
  for (int i = 0; i < count && std::abs(score) <= count - i; ++i)
    if (volumes.contains(world, probes[i].cell, probes[i].point)) score += probes[i].sign;
  return score;
}

constexpr double kProbeFractions[3] = {1e-3, 1e-2, 5e-2};

// The probes' steps along the normal: each fraction of the polygon's size, at least twice the rounding.
glm::dvec3 probe_step(const ConvexPolygon& polygon, double fraction, double rounding_m) {
  return polygon.normal * std::max(fraction * polygon.size, 2.0 * rounding_m);
}

// > 0 when the probes say the normal already points from `from` into `to`, < 0 when reversed.
int probe_sides(const World& world, const CellVolumeIndex& volumes, uint32_t from, uint32_t to,
                const ConvexPolygon& polygon, double rounding_m) {
  Probe probes[12];
  for (int f = 0; f < 3; ++f) {
    const glm::dvec3 step = probe_step(polygon, kProbeFractions[f], rounding_m);
    const glm::dvec3 behind = polygon.centroid - step, ahead = polygon.centroid + step;
    probes[2 * f] = {from, behind, 1};
    probes[2 * f + 1] = {to, ahead, 1};
    probes[6 + 2 * f] = {from, ahead, -1};
    probes[6 + 2 * f + 1] = {to, behind, -1};
  }
  return probe_score(world, volumes, probes, 12);
}

// The rounding floor of `polygon_world` taken into a cell's space (the volume is compared there).
double cell_rounding(const Cell& cell, const std::vector<glm::dvec3>& polygon_world) {
  const std::vector<glm::vec3> points(polygon_world.begin(), polygon_world.end());
  return rounding_floor(glm::dmat4(cell.world_to_cell), points);
}

// A linked portal borders `from` only: its normal points out of `from`'s volume.
Status orient_out_of(const AssemblyState& s, const NodeRecord& node, const World& world, const CellVolumeIndex& volumes,
                     uint32_t from_index, ConvexPolygon& polygon, double rounding_m) {
  rounding_m = std::max(rounding_m, cell_rounding(world.cells[from_index], polygon.vertices));
  Probe probes[6];
  for (int f = 0; f < 3; ++f) {
    const glm::dvec3 step = probe_step(polygon, kProbeFractions[f], rounding_m);
    probes[f] = {from_index, polygon.centroid - step, 1};
    probes[3 + f] = {from_index, polygon.centroid + step, -1};
  }
  if (const int score = probe_score(world, volumes, probes, 6); score != 0) {
    if (score < 0) flip_polygon(polygon);
    return {};
  }
  const glm::dvec3 c_from = volume_centre_world(world.cells[from_index]);
  const double away = polygon.plane_d - glm::dot(polygon.normal, c_from);  // > 0: from's centre is behind
  if (std::fabs(away) > 1e-6 * (glm::length(c_from - polygon.centroid) + polygon.size)) {
    if (away < 0.0) flip_polygon(polygon);
    return {};
  }
  return s.ctx.fail(node.element, "cannot orient the linked portal: the volume centre of '" +
                                      world.cells[from_index].name + "' lies in its plane");
}

Status orient(const AssemblyState& s, const NodeRecord& node, const World& world, const CellVolumeIndex& volumes,
              uint32_t from_index, uint32_t to_index, ConvexPolygon& polygon, double rounding_m) {
  rounding_m = std::max({rounding_m, cell_rounding(world.cells[from_index], polygon.vertices),
                         cell_rounding(world.cells[to_index], polygon.vertices)});
  if (const int score = probe_sides(world, volumes, from_index, to_index, polygon, rounding_m); score != 0) {
    if (score < 0) flip_polygon(polygon);
    return {};
  }
  const Cell& from = world.cells[from_index];
  const Cell& to = world.cells[to_index];
  const glm::dvec3 c_from = volume_centre_world(from), c_to = volume_centre_world(to);
  const double eps = 1e-6 * (glm::length(c_to - c_from) + polygon.size);
  const double tests[3] = {
      glm::dot(polygon.normal, c_to - c_from),
      polygon.plane_d - glm::dot(polygon.normal, c_from),  // > 0: from's centre is behind the plane
      glm::dot(polygon.normal, c_to) - polygon.plane_d,    // > 0: to's centre is in front
  };
  for (double t : tests) {
    if (std::fabs(t) <= eps) continue;
    if (t < 0.0) flip_polygon(polygon);
    return {};
  }
  return s.ctx.fail(node.element, "cannot orient the portal: the volume centres of '" + from.name + "' and '" +
                                      to.name + "' lie in its plane");
}

std::vector<glm::vec3> to_space(const glm::mat4& m, const std::vector<glm::dvec3>& points) {
  std::vector<glm::vec3> out;
  out.reserve(points.size());
  for (const glm::dvec3& p : points) out.emplace_back(glm::dmat4(m) * glm::dvec4(p, 1.0));
  return out;
}

Status check_touches(const AssemblyState& s, const NodeRecord& node, const Cell& cell,
                     const std::vector<glm::vec3>& polygon_cell, double portal_size) {
  std::vector<glm::dvec3> poly(polygon_cell.begin(), polygon_cell.end());
  const glm::dvec3 lo(cell.volume_box_cell.min), hi(cell.volume_box_cell.max);
  const double rounding = rounding_floor(glm::dmat4(cell.world_to_cell), polygon_cell);
  const double tolerance = std::max(kTouchTolerance * std::max(glm::length(hi - lo), portal_size), rounding);
  if (polygon_touches_box(poly, lo, hi, tolerance)) return {};
  return s.ctx.fail(node.element, "two-way portal does not touch the volume of cell '" + cell.name +
                                      "' (polygon and volume box are apart in that cell's space)");
}

Status build_portal(AssemblyState& s, World& world, const CellVolumeIndex& volumes, size_t n, Portal& portal) {
  const NodeRecord& node = s.nodes[n];
  const auto from = s.cell_by_name.find(node.tag.from);
  if (from == s.cell_by_name.end())
    return s.ctx.fail(node.element, "portal 'from' names unknown cell '" + node.tag.from + "'");
  const bool linked = node.tag.mirror || node.tag.link_matrix_given || !node.tag.link_target.empty();
  // A mirror leads back into `from`; a named link into its target's `from` (resolve_links() checks `to`).
  const std::string& to_name = node.tag.to.empty() ? node.tag.from : node.tag.to;
  const auto to = s.cell_by_name.find(to_name);
  if (to == s.cell_by_name.end()) return s.ctx.fail(node.element, "portal 'to' names unknown cell '" + to_name + "'");
  if (node.tag.mirror && from->second != to->second)
    return s.ctx.fail(node.element, "a mirror leads back into its own cell: 'to' must be '" + node.tag.from +
                                        "' or absent, not '" + node.tag.to + "'");
  if (!linked && from->second == to->second)
    return s.ctx.fail(node.element, "portal leads from cell '" + node.tag.from + "' to itself (from == to)");
  if (node.mesh < 0) return s.ctx.fail(node.element, "portal node has no mesh");

  Mesh mesh;
  if (Status st = read_mesh(s.ctx, s.model, node.mesh, s.budget, nullptr, mesh); !st) return st;
  if (mesh.indices.size() / 3 > kMaxPortalTriangles)
    return s.ctx.fail(node.element, "portal mesh has " + std::to_string(mesh.indices.size() / 3) +
                                        " triangles, over the limit of " + std::to_string(kMaxPortalTriangles));
  std::vector<glm::dvec3> points_world(mesh.positions.size());
  for (size_t i = 0; i < mesh.positions.size(); ++i)
    points_world[i] = transform_point(s.graph.world[n], mesh.positions[i]);
  const double rounding_m = rounding_floor(s.graph.world[n], mesh.positions);
  ConvexPolygon polygon;
  if (std::string why = extract_convex_polygon(points_world, mesh.indices, polygon, rounding_m); !why.empty())
    return s.ctx.fail(node.element, "portal polygon " + why);

  const Cell& from_cell = world.cells[from->second];
  const Cell& to_cell = world.cells[to->second];
  if (linked) {
    if (Status st = orient_out_of(s, node, world, volumes, from->second, polygon, rounding_m); !st) return st;
  } else if (Status st = orient(s, node, world, volumes, from->second, to->second, polygon, rounding_m); !st) {
    return st;
  }

  portal.name = node.name;
  portal.node = int(n);
  portal.from = from->second;
  portal.to = to->second;
  portal.two_way = node.tag.two_way;
  portal.open_from_to = portal.open_to_from = node.tag.open;
  portal.polygon_world.assign(polygon.vertices.begin(), polygon.vertices.end());
  portal.polygon_from_cell = to_space(from_cell.world_to_cell, polygon.vertices);
  portal.polygon_to_cell = to_space(to_cell.world_to_cell, polygon.vertices);
  portal.normal_world = glm::vec3(polygon.normal);
  portal.plane_d_world = float(polygon.plane_d);
  portal.centroid_world = glm::vec3(polygon.centroid);
  if (node.tag.mirror) {
    portal.link = PortalLinkKind::Mirror;
    portal.link_world = mirror_transform(portal);
  } else if (linked) {
    portal.link = PortalLinkKind::Teleport;
    portal.link_world = node.tag.link_matrix;  // a named link: resolve_links()
  }
  // One-way portals may look into a cell far away (a window onto a distant view), so only
  // two-way portals must sit where both volumes meet.
  if (portal.two_way) {
    if (Status st = check_touches(s, node, from_cell, portal.polygon_from_cell, polygon.size); !st) return st;
    if (Status st = check_touches(s, node, to_cell, portal.polygon_to_cell, polygon.size); !st) return st;
  }
  return {};
}

// Named links need every portal built; then every link is checked (portal_link.h).
Status resolve_links(const AssemblyState& s, World& world) {
  for (uint32_t p = 0; p < world.portals.size(); ++p) {
    Portal& portal = world.portals[p];
    if (!portal.linked()) continue;
    const NodeRecord& node = s.nodes[size_t(portal.node)];
    if (!node.tag.link_target.empty()) {
      const int target = world.find_portal(node.tag.link_target);
      if (target < 0)
        return s.ctx.fail(node.element, "portal link names unknown portal '" + node.tag.link_target + "'");
      if (uint32_t(target) == p) return s.ctx.fail(node.element, "portal links to itself");
      const Portal& t = world.portals[size_t(target)];
      if (t.two_way || t.link == PortalLinkKind::Mirror)
        return s.ctx.fail(node.element, "link target '" + t.name + "' must be a one-way portal that is not a mirror");
      if (std::string why = link_onto_target(portal, t, portal.link_world); !why.empty())
        return s.ctx.fail(node.element, "portal polygon " + why + " '" + t.name + "'");
      if (!node.tag.to.empty() && node.tag.to != world.cells[t.from].name)
        return s.ctx.fail(node.element, "portal 'to' is '" + node.tag.to + "' but its link target '" + t.name +
                                            "' opens into '" + world.cells[t.from].name + "'");
      portal.link_target = target;
      portal.to = t.from;
      portal.polygon_to_cell =
          to_space(world.cells[t.from].world_to_cell,
                   std::vector<glm::dvec3>(portal.polygon_world.begin(), portal.polygon_world.end()));
    }
    if (std::string why = check_portal_link(world, p); !why.empty()) return s.ctx.fail(node.element, "portal " + why);
  }
  return {};
}

}  // namespace

Status assemble_portals(AssemblyState& s, World& world) {
  // The probes are cell_volume_contains; the index answers the same, reading only the triangles
  // near each probe's ray (the cells' volumes are complete here).
  CellVolumeIndex volumes;
  volumes.build(world);
  for (size_t n = 0; n < s.nodes.size(); ++n) {
    if (!s.graph.in_scene[n] || s.nodes[n].tag.kind != Kind::Portal) continue;
    Portal portal;
    if (Status st = build_portal(s, world, volumes, n, portal); !st) return st;
    world.portals.push_back(std::move(portal));  // Cell::links: finalize_world()
  }
  return resolve_links(s, world);
}

}  // namespace lintel::scene_read
