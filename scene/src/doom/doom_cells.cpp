// Sectors -> cells: the effective heights (closed doors opened), each sector's shell (floor and
// ceiling fans over its convex pieces, walls, lower and upper steps facing into it), its volume
// (one closed prism per piece) and one portal per two-sided line over the span both sides leave
// open. Cells keep identity frames: a Doom map spans at most ~1 km, where float32 is exact to
// tens of micrometres.
#include "doom/doom_convex_cells.h"
#include "doom/doom_level.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>

namespace lintel::doom {
namespace {

constexpr double kMinPortalSpan = 1.0;  // map units: a thinner opening is treated as closed
constexpr double kSameCut = 1e-3;       // map units: cuts of a line this close are one (split sectors)

glm::dvec3 world_dir(const glm::dvec2& n2, double dh) { return {n2.x, dh, -n2.y}; }

// Appends a triangle fan over `corners` (a planar convex polygon) to `mesh`, wound so that its
// front face (counter-clockwise, glTF) faces along `facing`.
void add_fan(MeshDesc& mesh, const std::vector<glm::vec3>& corners, const glm::dvec3& facing) {
  if (corners.size() < 3) return;
  glm::dvec3 normal(0.0);
  for (size_t i = 1; i + 1 < corners.size(); ++i)
    normal += glm::cross(glm::dvec3(corners[i] - corners[0]), glm::dvec3(corners[i + 1] - corners[0]));
  const bool flip = glm::dot(normal, facing) < 0.0;
  const auto base = uint32_t(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), corners.begin(), corners.end());
  for (uint32_t i = 1; i + 1 < corners.size(); ++i) {
    if (flip)
      mesh.indices.insert(mesh.indices.end(), {base, base + i + 1, base + i});
    else
      mesh.indices.insert(mesh.indices.end(), {base, base + i, base + i + 1});
  }
}

// A vertical quad on the map segment a -> b between heights lo and hi, facing along n2 (map x, y).
void add_wall(MeshDesc& mesh, const glm::dvec2& a, const glm::dvec2& b, double lo, double hi, const glm::dvec2& n2) {
  if (hi <= lo) return;
  add_fan(mesh, {to_world(a, lo), to_world(b, lo), to_world(b, hi), to_world(a, hi)}, world_dir(n2, 0.0));
}

glm::vec4 sector_colour(const Sector& s, uint16_t index) {
  const float light = 0.35f + 0.65f * float(std::clamp(s.light, 0, 255)) / 255.0f;
  const float tint = float(index % 7) * 0.02f;
  return {light * (0.78f + tint), light * 0.76f, light * (0.72f - tint), 1.0f};
}

std::string sector_name(size_t s) { return "sector_" + std::to_string(s); }

// The sector under map point p if it has a cell, else -1.
int sector_with_cell_at(const Level& level, const glm::dvec2& p) {
  const Map& m = level.map;
  const uint16_t s = m.seg_sector(m.segs[m.subsectors[subsector_at(m, p)].first_seg]);
  return level.cell_node[s] >= 0 ? int(s) : -1;
}

}  // namespace

void prepare_level(Map map, Level& out, uint32_t& door_count) {
  out = {};
  out.map = std::move(map);
  const Map& m = out.map;
  out.pieces = subsector_polygons(m);
  out.pieces_of_sector.assign(m.sectors.size(), {});
  for (size_t p = 0; p < out.pieces.size(); ++p) out.pieces_of_sector[out.pieces[p].sector].push_back(p);
  out.piece_node.assign(out.pieces.size(), -1);
  out.piece_of_subsector.assign(m.subsectors.size(), -1);
  for (size_t p = 0; p < out.pieces.size(); ++p) out.piece_of_subsector[out.pieces[p].subsector] = int(p);
  out.seg_subsector.assign(m.segs.size(), 0);
  for (size_t ss = 0; ss < m.subsectors.size(); ++ss)
    for (uint32_t k = 0; k < m.subsectors[ss].seg_count; ++k)
      out.seg_subsector[m.subsectors[ss].first_seg + k] = uint16_t(ss);
  out.segs_of_line.assign(m.linedefs.size(), {});
  for (size_t g = 0; g < m.segs.size(); ++g) out.segs_of_line[m.segs[g].linedef].push_back(uint32_t(g));
  out.floor.resize(m.sectors.size());
  out.ceiling.resize(m.sectors.size());
  out.door.assign(m.sectors.size(), 0);
  out.cell_node.assign(m.sectors.size(), -1);
  // A closed sector (ceiling at or below its floor) opens like a Doom door: up to the lowest
  // ceiling around it, minus a lip. One that cannot open (no higher neighbour) stays solid.
  std::vector<int> lowest_neighbour_ceiling(m.sectors.size(), INT_MAX);
  for (const Linedef& line : m.linedefs) {
    if (line.back == kNoSide) continue;
    const uint16_t f = m.sidedefs[line.front].sector, b = m.sidedefs[line.back].sector;
    if (f == b) continue;
    lowest_neighbour_ceiling[f] = std::min(lowest_neighbour_ceiling[f], m.sectors[b].ceiling);
    lowest_neighbour_ceiling[b] = std::min(lowest_neighbour_ceiling[b], m.sectors[f].ceiling);
  }
  door_count = 0;
  for (size_t s = 0; s < m.sectors.size(); ++s) {
    out.floor[s] = m.sectors[s].floor;
    out.ceiling[s] = m.sectors[s].ceiling;
    if (out.ceiling[s] > out.floor[s]) continue;
    if (lowest_neighbour_ceiling[s] != INT_MAX && lowest_neighbour_ceiling[s] - kDoorLip > out.floor[s]) {
      out.ceiling[s] = lowest_neighbour_ceiling[s] - kDoorLip;
      out.door[s] = 1;
      ++door_count;
    }
  }
}

int side_cell_sector(const Level& level, uint16_t sidedef) {
  if (sidedef == kNoSide) return -1;
  const uint16_t s = level.map.sidedefs[sidedef].sector;
  return level.cell_node[s] >= 0 ? int(s) : -1;
}

int cell_node_at(const Level& level, const glm::dvec2& p) {
  const Map& m = level.map;
  const uint16_t sub = subsector_at(m, p);
  const int piece = level.piece_of_subsector[sub];
  if (piece >= 0 && level.piece_node[size_t(piece)] >= 0) return level.piece_node[size_t(piece)];
  return level.cell_node[m.seg_sector(m.segs[m.subsectors[sub].first_seg])];
}

namespace {

// One stretch [t0, t1] of a line (parameter along v1 -> v2) and the cell node on one side of it.
struct SideSpan {
  double t0 = 0.0, t1 = 1.0;
  int node = -1;
};

// The cell node on one side of line l (front: right of v1 -> v2) at parameter t, found by the
// subsector a quarter unit off the line; the sector's first cell when that lands elsewhere.
int probe_side(const Level& level, size_t l, bool front, size_t sector, double t, DoomImportStats& stats) {
  const Map& m = level.map;
  const glm::dvec2 a = m.vertices[m.linedefs[l].v1], b = m.vertices[m.linedefs[l].v2];
  const glm::dvec2 right = glm::normalize(glm::dvec2(b.y - a.y, a.x - b.x));
  const glm::dvec2 p = a + t * (b - a) + (front ? 0.25 : -0.25) * right;
  const uint16_t sub = subsector_at(m, p);
  const int piece = level.piece_of_subsector[sub];
  ++stats.side_probes;
  if (piece >= 0 && level.pieces[size_t(piece)].sector == sector) return level.piece_node[size_t(piece)];
  // The BSP puts another sector there (a self-referencing line): the sector's piece nearest to p.
  return nearest_piece_node(level, sector, p, nullptr);
}

}  // namespace

int nearest_piece_node(const Level& level, size_t sector, const glm::dvec2& p, double* distance) {
  double best = INFINITY;
  int node = level.cell_node[sector];
  for (size_t q : level.pieces_of_sector[sector]) {
    const std::vector<glm::dvec2>& poly = level.pieces[q].polygon;
    double d = INFINITY;
    for (size_t i = 0; i < poly.size(); ++i) {
      const glm::dvec2 u = poly[(i + 1) % poly.size()] - poly[i];
      const double along = std::clamp(glm::dot(p - poly[i], u) / glm::dot(u, u), 0.0, 1.0);
      d = std::min(d, glm::length(p - (poly[i] + along * u)));
    }
    if (d < best) best = d, node = level.piece_node[q];
  }
  if (distance) *distance = best;
  return node;
}

namespace {

// The cells along one side of line l, in order along it. A sector of one cell is one span; a
// split sector's cells come from the line's segs on that side (each seg lies on its subsector's
// boundary, so its piece is the cell there), gaps and segs of other sectors by a probe.
std::vector<SideSpan> side_spans(const Level& level, size_t l, bool front, size_t sector, bool split,
                                 DoomImportStats& stats) {
  if (!split) return {{0.0, 1.0, level.cell_node[sector]}};
  const Map& m = level.map;
  const glm::dvec2 a = m.vertices[m.linedefs[l].v1], b = m.vertices[m.linedefs[l].v2];
  const glm::dvec2 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  std::vector<SideSpan> spans;
  for (uint32_t g : level.segs_of_line[l]) {
    const Seg& seg = m.segs[g];
    if (seg.reversed == front) continue;
    const double t0 = glm::dot(m.vertices[seg.v1] - a, ab) / len2, t1 = glm::dot(m.vertices[seg.v2] - a, ab) / len2;
    SideSpan span{std::clamp(std::min(t0, t1), 0.0, 1.0), std::clamp(std::max(t0, t1), 0.0, 1.0), -1};
    if (!(span.t1 > span.t0)) continue;
    const int piece = level.piece_of_subsector[level.seg_subsector[g]];
    if (piece >= 0 && level.pieces[size_t(piece)].sector == sector)
      span.node = level.piece_node[size_t(piece)];
    else
      span.node = probe_side(level, l, front, sector, 0.5 * (span.t0 + span.t1), stats);
    spans.push_back(span);
  }
  std::sort(spans.begin(), spans.end(), [](const SideSpan& x, const SideSpan& y) { return x.t0 < y.t0; });
  // Cover [0, 1]: overlaps cut at the later start, gaps filled by a probe; what is shorter than
  // kSameCut joins the stretch before it (or after it, at the start), so nothing is degenerate.
  const double same = kSameCut / std::sqrt(len2);
  std::vector<SideSpan> out;
  double at = 0.0;
  for (SideSpan span : spans) {
    if (span.t1 - at <= same) continue;
    if (span.t0 - at > same) {
      out.push_back({at, span.t0, probe_side(level, l, front, sector, 0.5 * (at + span.t0), stats)});
    } else {
      span.t0 = at;
    }
    out.push_back(span);
    at = span.t1;
  }
  if (1.0 - at > same) {
    out.push_back({at, 1.0, probe_side(level, l, front, sector, 0.5 * (at + 1.0), stats)});
  } else if (!out.empty()) {
    out.back().t1 = 1.0;
  } else {
    out.push_back({0.0, 1.0, probe_side(level, l, front, sector, 0.5, stats)});
  }
  return out;
}

// The stretches of line l with one cell on each side: both sides' spans cut at each other's ends,
// neighbours with the same pair of cells joined.
struct LineStretch {
  double t0 = 0.0, t1 = 1.0;
  int front = -1, back = -1;  // cell nodes
};

std::vector<LineStretch> line_stretches(const std::vector<SideSpan>& front, const std::vector<SideSpan>& back,
                                        double line_length) {
  std::vector<LineStretch> out;
  size_t i = 0, j = 0;
  double at = 0.0;
  const double same = kSameCut / line_length;
  while (i < front.size() && j < back.size()) {
    const double end = std::min(front[i].t1, back[j].t1);
    // Both sides' cuts come from the same partition lines: ends closer than kSameCut are one cut
    // (the stretch before takes the sliver).
    if (end - at > same || (end >= 1.0 && out.empty())) {
      if (!out.empty() && out.back().front == front[i].node && out.back().back == back[j].node)
        out.back().t1 = end;
      else
        out.push_back({at, end, front[i].node, back[j].node});
      at = end;
    } else if (end >= 1.0) {
      out.back().t1 = 1.0;
    }
    if (front[i].t1 <= end) ++i;
    if (j < back.size() && back[j].t1 <= end) ++j;
  }
  return out;
}

void add_cell(Level& level, size_t s, const std::vector<size_t>& pieces, const std::string& name, SceneDesc& scene) {
  const Map& m = level.map;
  const double lo = level.floor[s], hi = level.ceiling[s];
  MeshDesc shell, volume;
  shell.name = name + "_shell";
  shell.base_color = sector_colour(m.sectors[s], uint16_t(s));
  volume.name = name + "_volume";
  volume.base_color = {0.3f, 0.6f, 1.0f, 0.0f};
  for (size_t p : pieces) {
    const std::vector<glm::dvec2>& poly = level.pieces[p].polygon;
    std::vector<glm::vec3> floor_corners, ceiling_corners;
    for (const glm::dvec2& c : poly)
      floor_corners.push_back(to_world(c, lo)), ceiling_corners.push_back(to_world(c, hi));
    add_fan(shell, floor_corners, {0, 1, 0});
    add_fan(shell, ceiling_corners, {0, -1, 0});
    // The prism, faces outward; its corners are the same floats on every face (closed mesh).
    add_fan(volume, floor_corners, {0, -1, 0});
    add_fan(volume, ceiling_corners, {0, 1, 0});
    for (size_t i = 0; i < poly.size(); ++i) {
      const glm::dvec2 a = poly[i], b = poly[(i + 1) % poly.size()];
      add_fan(volume,
              {floor_corners[i], floor_corners[(i + 1) % poly.size()], ceiling_corners[(i + 1) % poly.size()],
               ceiling_corners[i]},
              world_dir({b.y - a.y, a.x - b.x}, 0.0));  // right of a -> b: outside a counter-clockwise piece
    }
  }
  NodeDesc cell;
  cell.name = name;
  cell.kind = NodeDesc::Kind::Cell;
  cell.cell_name = cell.name;
  cell.mesh = int(scene.meshes.size());
  scene.meshes.push_back(std::move(shell));
  const int node = int(scene.nodes.size());
  if (level.cell_node[s] < 0) level.cell_node[s] = node;
  for (size_t p : pieces) level.piece_node[p] = node;
  scene.nodes.push_back(cell);
  NodeDesc vol;
  vol.name = name + "_volume";
  vol.parent = node;
  vol.kind = NodeDesc::Kind::Volume;
  vol.mesh = int(scene.meshes.size());
  scene.meshes.push_back(std::move(volume));
  scene.nodes.push_back(vol);
}

void add_portal(const std::string& name, int from_node, int to_node, const glm::dvec2& a, const glm::dvec2& b,
                double lo, double hi, bool open, SceneDesc& scene) {
  NodeDesc portal;
  portal.name = name;
  portal.parent = from_node;
  portal.kind = NodeDesc::Kind::Portal;
  portal.portal_from = scene.nodes[size_t(from_node)].name;
  portal.portal_to = scene.nodes[size_t(to_node)].name;
  portal.portal_open = open;
  MeshDesc mesh;
  mesh.name = portal.name;
  mesh.base_color = {1.0f, 0.8f, 0.2f, 0.0f};
  mesh.positions = {to_world(a, lo), to_world(b, lo), to_world(b, hi), to_world(a, hi)};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  portal.mesh = int(scene.meshes.size());
  scene.meshes.push_back(std::move(mesh));
  scene.nodes.push_back(portal);
}

MeshDesc& shell_of(SceneDesc& scene, int node) { return scene.meshes[size_t(scene.nodes[size_t(node)].mesh)]; }

}  // namespace

void add_cells_and_portals(Level& level, const DoomImportOptions& options, SceneDesc& scene, DoomImportStats& stats) {
  const Map& m = level.map;
  std::vector<uint8_t> split(m.sectors.size(), 0);
  std::vector<std::vector<std::vector<size_t>>> groups_of_sector(m.sectors.size());
  // Sectors beside a self-referencing line stay whole: the BSP's leaves there need not reach the
  // line (E1M6: a ring of 8-unit strips 1 unit off its inner sector's lines), and only the whole
  // sector's cell is sure to meet the portal.
  std::vector<uint8_t> keep_whole(m.sectors.size(), 0);
  for (const Linedef& line : m.linedefs) {
    if (line.back == kNoSide || m.sidedefs[line.front].sector != m.sidedefs[line.back].sector) continue;
    const glm::dvec2 a = m.vertices[line.v1], b = m.vertices[line.v2];
    if (a == b) continue;
    const glm::dvec2 mid = 0.5 * (a + b), step = glm::normalize(glm::dvec2(b.y - a.y, a.x - b.x));
    for (const glm::dvec2& q : {mid + step, mid - step})
      keep_whole[m.seg_sector(m.segs[m.subsectors[subsector_at(m, q)].first_seg])] = 1;
  }
  for (size_t s = 0; s < m.sectors.size(); ++s) {
    ++stats.sectors;
    if (level.pieces_of_sector[s].empty() || level.ceiling[s] <= level.floor[s]) {
      ++stats.solid_sectors;
      continue;
    }
    std::vector<std::vector<size_t>>& groups = groups_of_sector[s];
    double area = 0.0;
    for (size_t p : level.pieces_of_sector[s]) area += polygon_area(level.pieces[p].polygon);
    if (options.convex_cells && !keep_whole[s] &&
        convex_hull_area(level.pieces, level.pieces_of_sector[s]) > area * (1.0 + options.convex_min_sector_excess))
      groups = convex_piece_groups(level.pieces, level.pieces_of_sector[s], options.convex_hull_excess);
    else
      groups = {level.pieces_of_sector[s]};
    split[s] = groups.size() > 1;
    stats.split_sectors += split[s];
    for (size_t g = 0; g < groups.size(); ++g) {
      add_cell(level, s, groups[g], split[s] ? sector_name(s) + "_" + std::to_string(g) : sector_name(s), scene);
      ++stats.cells;
    }
  }
  // Portals between the cells of a split sector: always open, floor to ceiling. Each boundary has
  // the left group's cell on its left; the portal runs from the cell on its right (as line portals
  // run from the line's front, on the right).
  for (size_t s = 0; s < m.sectors.size(); ++s) {
    if (!split[s]) continue;
    const std::vector<std::vector<size_t>>& groups = groups_of_sector[s];
    const std::vector<GroupBoundary> boundaries = group_boundaries(level.pieces, groups);
    for (size_t k = 0; k < boundaries.size(); ++k) {
      const GroupBoundary& edge = boundaries[k];
      glm::dvec2 a = edge.a, b = edge.b;
      // A stretch shorter than a unit is widened to one: a wider portal only shows more.
      const double length = glm::length(b - a);
      if (length < kMinPortalSpan) {
        const glm::dvec2 mid = 0.5 * (a + b), half = (0.5 * kMinPortalSpan / length) * (b - a);
        a = mid - half, b = mid + half;
      }
      level.cuts.emplace_back(edge.a, edge.b);
      add_portal(sector_name(s) + "_cut_" + std::to_string(k), level.piece_node[groups[edge.right].front()],
                 level.piece_node[groups[edge.left].front()], a, b, level.floor[s], level.ceiling[s], true, scene);
      ++stats.portals;
      ++stats.inner_portals;
    }
  }

  for (size_t l = 0; l < m.linedefs.size(); ++l) {
    const Linedef& line = m.linedefs[l];
    const glm::dvec2 a = m.vertices[line.v1], b = m.vertices[line.v2];
    if (a == b) continue;
    const glm::dvec2 right(b.y - a.y, a.x - b.x);  // points into the front sector
    int f = side_cell_sector(level, line.front), k = side_cell_sector(level, line.back);
    if (f >= 0 && k >= 0 && f == k) {
      // Both sides name one sector: decoration, unless the BSP puts another sector on one side
      // (a "self-referencing sector", Doom's deep-water trick: its lines all name it on both
      // sides, and it lies open inside its neighbour). Then it is a line between those two.
      const glm::dvec2 mid = 0.5 * (a + b), step = glm::normalize(right);
      const int on_right = sector_with_cell_at(level, mid + step), on_left = sector_with_cell_at(level, mid - step);
      if (on_right < 0 || on_left < 0 || on_right == on_left) continue;
      f = on_right, k = on_left;
    }
    auto point = [&](double t) { return a + t * (b - a); };
    if (f < 0 || k < 0) {  // a wall of whichever side has a cell
      if (f >= 0)
        for (const SideSpan& span : side_spans(level, l, true, size_t(f), split[size_t(f)], stats))
          add_wall(shell_of(scene, span.node), point(span.t0), point(span.t1), level.floor[size_t(f)],
                   level.ceiling[size_t(f)], right);
      if (k >= 0)
        for (const SideSpan& span : side_spans(level, l, false, size_t(k), split[size_t(k)], stats))
          add_wall(shell_of(scene, span.node), point(span.t0), point(span.t1), level.floor[size_t(k)],
                   level.ceiling[size_t(k)], -right);
      continue;
    }
    const size_t fs = size_t(f), ks = size_t(k);
    const std::vector<LineStretch> stretches =
        line_stretches(side_spans(level, l, true, fs, split[fs], stats),
                       side_spans(level, l, false, ks, split[ks], stats), glm::length(b - a));
    for (size_t part = 0; part < stretches.size(); ++part) {
      const LineStretch& st = stretches[part];
      const glm::dvec2 sa = point(st.t0), sb = point(st.t1);
      // Steps: the lower part belongs to the side with the lower floor, the upper part to the side
      // with the higher ceiling; each faces into its owner.
      if (level.floor[fs] != level.floor[ks]) {
        const bool front_low = level.floor[fs] < level.floor[ks];
        add_wall(shell_of(scene, front_low ? st.front : st.back), sa, sb, std::min(level.floor[fs], level.floor[ks]),
                 std::max(level.floor[fs], level.floor[ks]), front_low ? right : -right);
      }
      if (level.ceiling[fs] != level.ceiling[ks]) {
        const bool front_high = level.ceiling[fs] > level.ceiling[ks];
        add_wall(shell_of(scene, front_high ? st.front : st.back), sa, sb,
                 std::min(level.ceiling[fs], level.ceiling[ks]), std::max(level.ceiling[fs], level.ceiling[ks]),
                 front_high ? right : -right);
      }
      const double lo = std::max(level.floor[fs], level.floor[ks]), hi = std::min(level.ceiling[fs], level.ceiling[ks]);
      if (hi - lo < kMinPortalSpan) {
        // No opening: close the gap between the steps from both sides.
        add_wall(shell_of(scene, st.front), sa, sb, lo, hi, right);
        add_wall(shell_of(scene, st.back), sa, sb, lo, hi, -right);
        continue;
      }
      const std::string name =
          "line_" + std::to_string(l) + (stretches.size() > 1 ? "_" + std::to_string(part) : std::string());
      add_portal(name, st.front, st.back, sa, sb, lo, hi, options.doors_open || !(level.door[fs] || level.door[ks]),
                 scene);
      ++stats.portals;
    }
  }
}

}  // namespace lintel::doom
