// The merge plan of `lintel optimize` (cell_merge_plan.h). Learns from Godot 3's room conversion
// and Doom 3's area merging (dmap merges BSP leaves into areas, bounded by "areaportal" brushes):
// a split only pays when the opening between two spaces is much smaller than the wall between them.
#include "optimize/cell_merge_plan.h"

#include <lintel/cell_locate.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <utility>

namespace lintel::optimize {
namespace {

constexpr double kVerticalPortal = 0.3;  // |normal.y| below this: a wall opening (others are not judged)

// The cell's closed volume in world space, 3 points per triangle (its box when it has no volume mesh).
std::vector<glm::dvec3> volume_triangles_world(const Cell& cell) {
  std::vector<glm::dvec3> out;
  const glm::dmat4 to_world(cell.cell_to_world);
  auto add = [&](const glm::dvec3& p) { out.push_back(glm::dvec3(to_world * glm::dvec4(p, 1.0))); };
  if (!cell.volume_triangles_cell.empty()) {
    for (const glm::vec3& p : cell.volume_triangles_cell) add(glm::dvec3(p));
    return out;
  }
  const Aabb& b = cell.volume_box_cell;
  if (b.empty()) return out;
  glm::dvec3 c[8];
  for (int i = 0; i < 8; ++i)
    c[i] = {(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z};
  static constexpr int kQuads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : kQuads)
    for (int k : {q[0], q[1], q[2], q[0], q[2], q[3]}) add(c[k]);
  return out;
}

double polygon_area(const std::vector<glm::dvec3>& poly) {
  glm::dvec3 sum(0.0);
  for (size_t i = 1; i + 1 < poly.size(); ++i) sum += glm::cross(poly[i] - poly[0], poly[i + 1] - poly[0]);
  return 0.5 * glm::length(sum);
}

// The net area of the volume triangles lying in the plane (n, d) within tol: facing +n minus
// facing -n, so that the faces between two pieces of one cell (one each way) cancel and what is
// left is the cell's boundary in that plane (either winding of the whole volume).
double coplanar_area(const std::vector<glm::dvec3>& tris, const glm::dvec3& n, double d, double tol) {
  double signed_area = 0.0;
  for (size_t t = 0; t + 2 < tris.size(); t += 3) {
    bool in_plane = true;
    for (int k = 0; k < 3; ++k) in_plane = in_plane && std::fabs(glm::dot(n, tris[t + k]) - d) <= tol;
    if (!in_plane) continue;
    const glm::dvec3 twice = glm::cross(tris[t + 1] - tris[t], tris[t + 2] - tris[t]);
    signed_area += 0.5 * glm::length(twice) * (glm::dot(twice, n) >= 0.0 ? 1.0 : -1.0);
  }
  return std::fabs(signed_area);
}

struct OpenWall {
  double open = 0.0, wall = 0.0;  // wall < 0: not judged
};

// The portal's area, and the wall its two cells share in its plane: the union of both cells'
// boundaries there, taken as the sum of both minus the opening (where both are open).
OpenWall open_wall(const World& world, const std::vector<std::vector<glm::dvec3>>& volumes, uint32_t p) {
  const Portal& portal = world.portals[p];
  std::vector<glm::dvec3> poly(portal.polygon_world.begin(), portal.polygon_world.end());
  const glm::dvec3 n = glm::normalize(glm::dvec3(portal.normal_world));
  if (std::fabs(n.y) >= kVerticalPortal) return {0.0, -1.0};
  double d = 0.0;
  Aabb box;
  for (const glm::dvec3& q : poly) {
    d += glm::dot(n, q) / double(poly.size());
    box.extend(glm::vec3(q));
  }
  const double size = glm::length(glm::dvec3(box.max) - glm::dvec3(box.min));
  const double tol = 1e-3 * size + 1e-4;
  const double open = polygon_area(poly);
  const double a = coplanar_area(volumes[portal.from], n, d, tol);
  const double b = coplanar_area(volumes[portal.to], n, d, tol);
  // Each volume must close the opening from its side; otherwise the volumes do not meet at the
  // portal (thick walls between boxes) and the shared wall is unknown.
  if (a < 0.9 * open || b < 0.9 * open) return {open, -1.0};
  return {open, std::max(a + b - open, open)};
}

class Groups {
 public:
  Groups(const World& world, const std::vector<std::vector<glm::dvec3>>& volumes, const std::vector<bool>& closable,
         const OptimizeOptions& options)
      : world_(world), closable_(closable), options_(options) {
    const size_t n = world.cells.size();
    parent_.resize(n);
    std::iota(parent_.begin(), parent_.end(), 0u);
    parts_.assign(n, 1);
    lo_.assign(n, glm::dvec3(std::numeric_limits<double>::infinity()));
    hi_.assign(n, glm::dvec3(-std::numeric_limits<double>::infinity()));
    material_.assign(n, -2);
    alpha_.assign(n, {2.0f, 2.0f});
    emission_.assign(n, {glm::vec3(0.0f), -1});
    for (size_t c = 0; c < n; ++c) {
      for (const glm::dvec3& p : volumes[c]) lo_[c] = glm::min(lo_[c], p), hi_[c] = glm::max(hi_[c], p);
      const int shell = world.cells[c].shell_mesh;
      if (shell >= 0) {
        const Mesh& m = world.meshes[size_t(shell)];
        // A textured shell's sampler is part of its look: the merged shell keeps one.
        const TextureSampler& t = m.base_color_sampler;
        const int64_t sampler = m.base_color_texture < 0
                                    ? 0
                                    : int64_t(t.wrap_s) | int64_t(t.wrap_t) << 2 | int64_t(t.mag) << 4 |
                                          int64_t(t.min) << 5 | int64_t(t.mip) << 6;
        material_[c] = (2 * (int64_t(m.base_color_texture) + 1) + (m.double_sided ? 1 : 0)) << 8 | sampler;
        // A cut-out's coverage is its base colour's alpha times the texture's, against its cutoff:
        // parts merge only with the same (the merged shell keeps one base alpha and one cutoff).
        if (m.alpha_mode == Mesh::AlphaMode::Mask) alpha_[c] = {m.base_color.a, m.alpha_cutoff};
        if (m.alpha_mode == Mesh::AlphaMode::Blend) alpha_[c] = {-1.0f, -1.0f};
        // Emission is per material too: only parts that emit alike merge.
        const TextureSampler& e = m.emissive_sampler;
        emission_[c] = {m.emissive, m.emissive_texture < 0 ? -1
                                                           : int64_t(m.emissive_texture) << 8 | int64_t(e.wrap_s) |
                                                                 int64_t(e.wrap_t) << 2 | int64_t(e.mag) << 4 |
                                                                 int64_t(e.min) << 5 | int64_t(e.mip) << 6};
      }
    }
    for (uint32_t p = 0; p < world.portals.size(); ++p)
      if (closable_[p]) closable_list_.push_back(p);
  }

  uint32_t find(uint32_t c) {
    while (parent_[c] != c) c = parent_[c] = parent_[parent_[c]];
    return c;
  }
  uint32_t parts(uint32_t c) { return parts_[find(c)]; }

  // Unites the groups of a and b when the rules allow it; false (nothing changed) otherwise.
  bool unite(uint32_t a, uint32_t b) {
    a = find(a), b = find(b);
    if (a == b) return false;
    if (parts_[a] + parts_[b] > options_.max_parts) return false;
    const glm::dvec3 lo = glm::min(lo_[a], lo_[b]), hi = glm::max(hi_[a], hi_[b]);
    const glm::dvec3 extent = hi - lo;
    if (std::max({extent.x, extent.y, extent.z}) > options_.max_extent_m) return false;
    if (material_[a] != -2 && material_[b] != -2 &&
        (material_[a] != material_[b] || alpha_[a] != alpha_[b] || emission_[a] != emission_[b]))
      return false;
    for (uint32_t p : closable_list_) {
      const uint32_t f = find(world_.portals[p].from), t = find(world_.portals[p].to);
      if ((f == a && t == b) || (f == b && t == a)) return false;
    }
    if (a > b) std::swap(a, b);  // the lower index is the root: groups keep their first cell's order
    parent_[b] = a;
    parts_[a] += parts_[b];
    lo_[a] = lo, hi_[a] = hi;
    if (material_[a] == -2) material_[a] = material_[b], alpha_[a] = alpha_[b], emission_[a] = emission_[b];
    return true;
  }

 private:
  const World& world_;
  const std::vector<bool>& closable_;
  const OptimizeOptions& options_;
  std::vector<uint32_t> parent_, parts_, closable_list_;
  std::vector<glm::dvec3> lo_, hi_;
  // (2 * (texture + 1) + double_sided) << 8 | the texture's sampler bits; -2: no shell (merges with any)
  std::vector<int64_t> material_;
  // Per group: (base alpha, cutoff) of a Mask shell, (-1, -1) for Blend, (2, 2) for Opaque.
  std::vector<std::pair<float, float>> alpha_;
  // Per group: Mesh::emissive, and its emissive texture << 8 | that texture's sampler bits (-1: none).
  std::vector<std::pair<glm::vec3, int64_t>> emission_;
};

double surface_area(const std::vector<glm::dvec3>& tris) {
  double area = 0.0;
  for (size_t t = 0; t + 2 < tris.size(); t += 3)
    area += 0.5 * glm::length(glm::cross(tris[t + 1] - tris[t], tris[t + 2] - tris[t]));
  return area;
}

}  // namespace

std::vector<bool> closable_portals(const World& world) {
  std::vector<bool> closable(world.portals.size(), false);
  for (uint32_t p = 0; p < world.portals.size(); ++p) {
    const Portal& portal = world.portals[p];
    closable[p] = !portal.two_way || !portal.open_from_to || !portal.open_to_from;
  }
  for (const Timeline& timeline : world.timelines)
    for (const TimelineEvent& event : timeline.events)
      if (const int p = world.find_portal(event.portal); p >= 0) closable[size_t(p)] = true;
  return closable;
}

double portal_open_fraction(const World& world, uint32_t portal) {
  std::vector<std::vector<glm::dvec3>> volumes(world.cells.size());
  const Portal& p = world.portals[portal];
  volumes[p.from] = volume_triangles_world(world.cells[p.from]);
  volumes[p.to] = volume_triangles_world(world.cells[p.to]);
  const OpenWall ow = open_wall(world, volumes, portal);
  return ow.wall > 0.0 ? ow.open / ow.wall : -1.0;
}

CellMergePlan plan_cell_merges(const World& world, const OptimizeOptions& options) {
  const size_t n = world.cells.size();
  std::vector<std::vector<glm::dvec3>> volumes(n);
  for (size_t c = 0; c < n; ++c) volumes[c] = volume_triangles_world(world.cells[c]);
  const std::vector<bool> closable = closable_portals(world);
  CellMergePlan plan;
  plan.closable_portals = uint32_t(std::count(closable.begin(), closable.end(), true));
  Groups groups(world, volumes, closable, options);

  // 1. Pairs whose portals open most of their shared wall, the most open first.
  std::map<std::pair<uint32_t, uint32_t>, OpenWall> pairs;
  for (uint32_t p = 0; p < world.portals.size(); ++p) {
    const Portal& portal = world.portals[p];
    if (closable[p] || portal.from == portal.to) continue;
    const OpenWall ow = open_wall(world, volumes, p);
    if (ow.wall <= 0.0) continue;
    OpenWall& sum = pairs[std::minmax(portal.from, portal.to)];
    sum.open += ow.open;
    sum.wall += ow.wall;
  }
  std::vector<std::pair<double, std::pair<uint32_t, uint32_t>>> ranked;
  for (const auto& [cells, ow] : pairs)
    if (ow.open >= options.min_open_fraction * ow.wall) ranked.push_back({ow.open / ow.wall, cells});
  std::stable_sort(ranked.begin(), ranked.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  for (const auto& [fraction, cells] : ranked) plan.open_wall_merges += groups.unite(cells.first, cells.second);

  // 2. Cells still alone that are slivers, smallest first, into the neighbour they share the most
  // portal area with (through portals that may be merged across).
  std::vector<double> volume_m3 = cell_volumes_m3(world);
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return volume_m3[a] < volume_m3[b]; });
  for (uint32_t c : order) {
    if (groups.parts(c) != 1) continue;
    const double area = surface_area(volumes[c]);
    const bool sliver = volume_m3[c] < options.sliver_volume_m3 ||
                        (area > 0.0 && 3.0 * volume_m3[c] / area < options.sliver_thickness_m);
    if (!sliver) continue;
    std::map<uint32_t, double> shared;  // neighbour cell -> portal area
    for (const PortalLink& link : world.cells[c].links)
      if (!closable[link.portal] && link.neighbour != c)
        shared[link.neighbour] += polygon_area(std::vector<glm::dvec3>(world.portals[link.portal].polygon_world.begin(),
                                                                       world.portals[link.portal].polygon_world.end()));
    std::vector<std::pair<double, uint32_t>> best;
    for (const auto& [neighbour, a] : shared) best.push_back({-a, neighbour});
    std::sort(best.begin(), best.end());
    for (const auto& [a, neighbour] : best)
      if (groups.unite(c, neighbour)) {
        ++plan.sliver_merges;
        break;
      }
  }

  plan.group_of_cell.assign(n, 0);
  std::vector<int> group_of_root(n, -1);
  for (uint32_t c = 0; c < n; ++c) {
    const uint32_t root = groups.find(c);
    if (group_of_root[root] < 0) {
      group_of_root[root] = int(plan.groups.size());
      plan.groups.emplace_back();
    }
    plan.group_of_cell[c] = uint32_t(group_of_root[root]);
    plan.groups[size_t(group_of_root[root])].push_back(c);
  }
  return plan;
}

}  // namespace lintel::optimize
