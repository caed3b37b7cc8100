// Sectors -> cells: the effective heights (closed doors opened), each sector's shell (floor and
// ceiling fans over its convex pieces, walls, lower and upper steps facing into it), its volume
// (one closed prism per piece) and one portal per two-sided line over the span both sides leave
// open. Cells keep identity frames: a Doom map spans at most ~1 km, where float32 is exact to
// tens of micrometres.
#include "doom/doom_level.h"

#include <algorithm>
#include <climits>
#include <string>

namespace lintel::doom {
namespace {

constexpr double kMinPortalSpan = 1.0;  // map units: a thinner opening is treated as closed

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

void add_cells_and_portals(Level& level, const DoomImportOptions& options, SceneDesc& scene, DoomImportStats& stats) {
  const Map& m = level.map;
  std::vector<int> shell_mesh(m.sectors.size(), -1);
  for (size_t s = 0; s < m.sectors.size(); ++s) {
    ++stats.sectors;
    if (level.pieces_of_sector[s].empty() || level.ceiling[s] <= level.floor[s]) {
      ++stats.solid_sectors;
      continue;
    }
    const double lo = level.floor[s], hi = level.ceiling[s];
    MeshDesc shell, volume;
    shell.name = sector_name(s) + "_shell";
    shell.base_color = sector_colour(m.sectors[s], uint16_t(s));
    volume.name = sector_name(s) + "_volume";
    volume.base_color = {0.3f, 0.6f, 1.0f, 0.0f};
    for (size_t p : level.pieces_of_sector[s]) {
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
    cell.name = sector_name(s);
    cell.kind = NodeDesc::Kind::Cell;
    cell.cell_name = cell.name;
    shell_mesh[s] = int(scene.meshes.size());
    cell.mesh = shell_mesh[s];
    scene.meshes.push_back(std::move(shell));
    level.cell_node[s] = int(scene.nodes.size());
    scene.nodes.push_back(cell);
    NodeDesc vol;
    vol.name = sector_name(s) + "_volume";
    vol.parent = level.cell_node[s];
    vol.kind = NodeDesc::Kind::Volume;
    vol.mesh = int(scene.meshes.size());
    scene.meshes.push_back(std::move(volume));
    scene.nodes.push_back(vol);
    ++stats.cells;
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
    if (f < 0 || k < 0) {  // a wall of whichever side has a cell
      if (f >= 0)
        add_wall(scene.meshes[size_t(shell_mesh[size_t(f)])], a, b, level.floor[size_t(f)], level.ceiling[size_t(f)],
                 right);
      if (k >= 0)
        add_wall(scene.meshes[size_t(shell_mesh[size_t(k)])], a, b, level.floor[size_t(k)], level.ceiling[size_t(k)],
                 -right);
      continue;
    }
    const size_t fs = size_t(f), ks = size_t(k);
    // Steps: the lower part belongs to the side with the lower floor, the upper part to the side
    // with the higher ceiling; each faces into its owner.
    if (level.floor[fs] != level.floor[ks]) {
      const bool front_low = level.floor[fs] < level.floor[ks];
      add_wall(scene.meshes[size_t(shell_mesh[front_low ? fs : ks])], a, b, std::min(level.floor[fs], level.floor[ks]),
               std::max(level.floor[fs], level.floor[ks]), front_low ? right : -right);
    }
    if (level.ceiling[fs] != level.ceiling[ks]) {
      const bool front_high = level.ceiling[fs] > level.ceiling[ks];
      add_wall(scene.meshes[size_t(shell_mesh[front_high ? fs : ks])], a, b,
               std::min(level.ceiling[fs], level.ceiling[ks]), std::max(level.ceiling[fs], level.ceiling[ks]),
               front_high ? right : -right);
    }
    const double lo = std::max(level.floor[fs], level.floor[ks]), hi = std::min(level.ceiling[fs], level.ceiling[ks]);
    if (hi - lo < kMinPortalSpan) {
      // No opening: close the gap between the steps from both sides.
      add_wall(scene.meshes[size_t(shell_mesh[fs])], a, b, lo, hi, right);
      add_wall(scene.meshes[size_t(shell_mesh[ks])], a, b, lo, hi, -right);
      continue;
    }
    NodeDesc portal;
    portal.name = "line_" + std::to_string(l);
    portal.parent = level.cell_node[fs];
    portal.kind = NodeDesc::Kind::Portal;
    portal.portal_from = sector_name(fs);
    portal.portal_to = sector_name(ks);
    portal.portal_open = options.doors_open || !(level.door[fs] || level.door[ks]);
    MeshDesc mesh;
    mesh.name = portal.name;
    mesh.base_color = {1.0f, 0.8f, 0.2f, 0.0f};
    mesh.positions = {to_world(a, lo), to_world(b, lo), to_world(b, hi), to_world(a, hi)};
    mesh.indices = {0, 1, 2, 0, 2, 3};
    portal.mesh = int(scene.meshes.size());
    scene.meshes.push_back(std::move(mesh));
    scene.nodes.push_back(portal);
    ++stats.portals;
  }
}

}  // namespace lintel::doom
