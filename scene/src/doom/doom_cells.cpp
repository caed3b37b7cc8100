// Sectors -> cells (doom_level.cpp prepares the heights): each sector's shell (floor and
// ceiling fans over its convex pieces, walls, lower and upper steps facing into it), its volume
// (one closed prism per piece) and one portal per two-sided line over the span both sides leave
// open. With convex cells, a sector's pieces are cut from its exact lines (doom_sector_partition.h,
// doom_convex_cells.h): a non-convex sector is several cells joined by always-open portals along
// the cuts, any other one cell over them; each of its lines lies on one piece, so walls and line
// portals need no cutting. Only sectors whose outline fails keep the BSP's pieces. Cells keep identity
// frames: a Doom map spans at most ~1 km, where float32 is exact to tens of micrometres.
#include "doom/doom_convex_cells.h"
#include "doom/doom_level.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>

namespace lintel::doom {
namespace {

// A sector's exact outline must enclose the area of its BSP pieces to within this fraction plus
// kOutlineAreaSlack map units^2 (the BSP's rounding), or the lines do not describe the floor
// Doom draws (an unclosed sector, lines of another sector's trick) and the sector stays whole.
constexpr double kOutlineAreaTolerance = 0.01;
constexpr double kOutlineAreaSlack = 64.0;

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

// The sector Doom draws beside line l's side if it has a cell, else -1.
int sector_with_cell_beside(const Level& level, size_t l, int side) {
  const uint16_t s = sector_beside_line(level, l, side);
  return level.cell_node[s] >= 0 ? int(s) : -1;
}

// Appends a cell node (and its volume node) with the given shell and volume meshes.
int add_cell_node(const std::string& name, MeshDesc shell, MeshDesc volume, SceneDesc& scene) {
  NodeDesc cell;
  cell.name = name;
  cell.kind = NodeDesc::Kind::Cell;
  cell.cell_name = cell.name;
  cell.mesh = int(scene.meshes.size());
  scene.meshes.push_back(std::move(shell));
  const int node = int(scene.nodes.size());
  scene.nodes.push_back(cell);
  NodeDesc vol;
  vol.name = name + "_volume";
  vol.parent = node;
  vol.kind = NodeDesc::Kind::Volume;
  vol.mesh = int(scene.meshes.size());
  scene.meshes.push_back(std::move(volume));
  scene.nodes.push_back(vol);
  return node;
}

MeshDesc new_mesh(const std::string& name, const glm::vec4& colour) {
  MeshDesc mesh;
  mesh.name = name;
  mesh.base_color = colour;
  return mesh;
}

constexpr glm::vec4 kVolumeColour{0.3f, 0.6f, 1.0f, 0.0f};

// One sector as one cell over its BSP pieces: floor and ceiling fans, one prism per piece.
int add_whole_sector_cell(const Level& level, size_t s, SceneDesc& scene) {
  const double lo = level.floor[s], hi = level.ceiling[s];
  MeshDesc shell = new_mesh(sector_name(s) + "_shell", sector_colour(level.map.sectors[s], uint16_t(s)));
  MeshDesc volume = new_mesh(sector_name(s) + "_volume", kVolumeColour);
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
  return add_cell_node(sector_name(s), std::move(shell), std::move(volume), scene);
}

// One cell of a split sector over some of its exact pieces: floor and ceiling from the pieces'
// triangles (collinear corners make fans degenerate), one prism per piece.
int add_split_cell(const Level& level, size_t s, const SectorPartition& part, const std::vector<size_t>& pieces,
                   const std::string& name, SceneDesc& scene) {
  const double lo = level.floor[s], hi = level.ceiling[s];
  MeshDesc shell = new_mesh(name + "_shell", sector_colour(level.map.sectors[s], uint16_t(s)));
  MeshDesc volume = new_mesh(name + "_volume", kVolumeColour);
  for (size_t p : pieces) {
    const SectorPartition::Piece& piece = part.pieces[p];
    for (const auto& t : piece.triangles) {
      std::vector<glm::vec3> floor_corners, ceiling_corners;
      for (uint32_t c : t)
        floor_corners.push_back(to_world(part.corners[c], lo)),
            ceiling_corners.push_back(to_world(part.corners[c], hi));
      add_fan(shell, floor_corners, {0, 1, 0});
      add_fan(shell, ceiling_corners, {0, -1, 0});
      add_fan(volume, floor_corners, {0, -1, 0});
      add_fan(volume, ceiling_corners, {0, 1, 0});
    }
    const std::vector<uint32_t>& poly = piece.polygon;
    for (size_t i = 0; i < poly.size(); ++i) {
      const glm::dvec2 a = part.corners[poly[i]], b = part.corners[poly[(i + 1) % poly.size()]];
      add_fan(volume, {to_world(a, lo), to_world(b, lo), to_world(b, hi), to_world(a, hi)},
              world_dir({b.y - a.y, a.x - b.x}, 0.0));
    }
  }
  return add_cell_node(name, std::move(shell), std::move(volume), scene);
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
  MeshDesc mesh = new_mesh(portal.name, {1.0f, 0.8f, 0.2f, 0.0f});
  mesh.positions = {to_world(a, lo), to_world(b, lo), to_world(b, hi), to_world(a, hi)};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  portal.mesh = int(scene.meshes.size());
  scene.meshes.push_back(std::move(mesh));
  scene.nodes.push_back(portal);
}

MeshDesc& shell_of(SceneDesc& scene, int node) { return scene.meshes[size_t(scene.nodes[size_t(node)].mesh)]; }

// Sectors beside a self-referencing line (see below) stay whole: which of their cells meets the
// line is the BSP's answer, not their outline's.
std::vector<uint8_t> sectors_beside_self_referencing_lines(const Level& level) {
  const Map& m = level.map;
  std::vector<uint8_t> beside(m.sectors.size(), 0);
  for (size_t l = 0; l < m.linedefs.size(); ++l) {
    const Linedef& line = m.linedefs[l];
    if (line.back == kNoSide || m.sidedefs[line.front].sector != m.sidedefs[line.back].sector) continue;
    if (m.vertices[line.v1] == m.vertices[line.v2]) continue;
    beside[m.sidedefs[line.front].sector] = 1;
    for (int side = 0; side < 2; ++side) beside[sector_beside_line(level, l, side)] = 1;
  }
  return beside;
}

// Sector s as cells over its exact pieces (doom_sector_partition.h): several convex cells when
// the options find it worth splitting, else one. Returns false (and adds nothing) when its outline
// does not describe its floor: it is then one cell over the BSP's pieces.
bool add_split_sector(Level& level, size_t s, const DoomImportOptions& options, const std::vector<uint32_t>& lines,
                      const std::vector<ThingClearance>& things, SceneDesc& scene, DoomImportStats& stats) {
  const Map& m = level.map;
  SectorPartition part;
  if (!partition_sector(m, uint16_t(s), lines, part).empty()) {
    ++stats.outline_failures;
    return false;
  }
  double bsp_area = 0.0;
  for (size_t p : level.pieces_of_sector[s]) bsp_area += polygon_area(level.pieces[p].polygon);
  if (std::fabs(part.area - bsp_area) > kOutlineAreaTolerance * bsp_area + kOutlineAreaSlack) {
    ++stats.outline_failures;
    return false;
  }
  // A sector not worth splitting is still one cell over these exact pieces, not over the BSP's:
  // the BSP's pieces end where the node builder rounded its split points (a few millimetres off
  // the lines), so beside an exact neighbour its floor left a crack a ray could pass through into
  // the space under the level (a false "visible" cell of freedoom1 E4M7's ground truth).
  size_t group_count = 1;
  std::vector<size_t> group(part.pieces.size(), 0);
  if (convex_hull_area(part.corners) > part.area * (1.0 + options.convex_min_sector_excess)) {
    // No cut passes within a thing's clearance: the pieces on both sides of such a diagonal stay together.
    std::vector<std::pair<size_t, size_t>> must_join;
    for (const SectorPartition::Diagonal& d : part.diagonals)
      for (const ThingClearance& thing : things)
        if (distance_to_segment(thing.position, part.corners[d.a], part.corners[d.b]) <= thing.clearance) {
          must_join.emplace_back(d.left, d.right);
          break;
        }
    group = convex_piece_groups(part, options.convex_hull_excess, must_join, group_count);
    if (group_count < 2) group.assign(part.pieces.size(), 0), group_count = 1;
  }
  std::vector<std::vector<size_t>> pieces_of_group(group_count);
  for (size_t p = 0; p < part.pieces.size(); ++p) pieces_of_group[group[p]].push_back(p);
  std::vector<int> node_of_group(group_count);
  for (size_t g = 0; g < group_count; ++g) {
    const std::string name = group_count == 1 ? sector_name(s) : sector_name(s) + "_" + std::to_string(g);
    node_of_group[g] = add_split_cell(level, s, part, pieces_of_group[g], name, scene);
    ++stats.cells;
  }
  level.cell_node[s] = node_of_group[0];
  if (group_count == 1) return true;  // one cell: nothing to tell its pieces or sides apart by
  for (size_t p = 0; p < part.pieces.size(); ++p) {
    Level::SplitPiece piece;
    for (uint32_t c : part.pieces[p].polygon) piece.polygon.push_back(part.corners[c]);
    piece.node = node_of_group[group[p]];
    level.split_pieces[s].push_back(std::move(piece));
  }
  for (const auto& [side, piece] : part.side_piece) level.side_node[side] = node_of_group[group[piece]];
  // Cuts: always open, floor to ceiling; each runs from the cell on its right (as line portals run
  // from the line's front, on the right).
  const std::vector<GroupBoundary> cuts = group_boundaries(part, group);
  for (size_t k = 0; k < cuts.size(); ++k) {
    const GroupBoundary& cut = cuts[k];
    level.cuts.emplace_back(cut.a, cut.b);
    add_portal(sector_name(s) + "_cut_" + std::to_string(k), node_of_group[cut.right], node_of_group[cut.left], cut.a,
               cut.b, level.floor[s], level.ceiling[s], true, scene);
    ++stats.portals;
    ++stats.inner_portals;
  }
  ++stats.split_sectors;
  return true;
}

// The cell node on one side of line l (side 0 front, 1 back) of sector `sector`.
int side_cell_node(const Level& level, size_t l, int side, size_t sector) {
  const int node = level.side_node[2 * l + size_t(side)];
  return node >= 0 ? node : level.cell_node[sector];
}

}  // namespace

void add_cells_and_portals(Level& level, const DoomImportOptions& options, SceneDesc& scene, DoomImportStats& stats) {
  const Map& m = level.map;
  const std::vector<uint8_t> keep_whole =
      options.convex_cells ? sectors_beside_self_referencing_lines(level) : std::vector<uint8_t>(m.sectors.size(), 1);
  std::vector<std::vector<ThingClearance>> things(m.sectors.size());
  std::vector<std::vector<uint32_t>> lines_of_sector(m.sectors.size());
  if (options.convex_cells) {
    things = thing_clearances(m);
    for (uint32_t l = 0; l < m.linedefs.size(); ++l) {
      const Linedef& line = m.linedefs[l];
      lines_of_sector[m.sidedefs[line.front].sector].push_back(l);
      if (line.back != kNoSide && m.sidedefs[line.back].sector != m.sidedefs[line.front].sector)
        lines_of_sector[m.sidedefs[line.back].sector].push_back(l);
    }
  }
  for (size_t s = 0; s < m.sectors.size(); ++s) {
    ++stats.sectors;
    if (level.pieces_of_sector[s].empty() || level.ceiling[s] <= level.floor[s]) {
      ++stats.solid_sectors;
      continue;
    }
    if (!keep_whole[s] && add_split_sector(level, s, options, lines_of_sector[s], things[s], scene, stats)) continue;
    level.cell_node[s] = add_whole_sector_cell(level, s, scene);
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
      const int on_right = sector_with_cell_beside(level, l, 0), on_left = sector_with_cell_beside(level, l, 1);
      if (on_right < 0 || on_left < 0 || on_right == on_left) continue;
      f = on_right, k = on_left;
    }
    if (f < 0 || k < 0) {  // a wall of whichever side has a cell
      if (f >= 0)
        add_wall(shell_of(scene, side_cell_node(level, l, 0, size_t(f))), a, b, level.floor[size_t(f)],
                 level.ceiling[size_t(f)], right);
      if (k >= 0)
        add_wall(shell_of(scene, side_cell_node(level, l, 1, size_t(k))), a, b, level.floor[size_t(k)],
                 level.ceiling[size_t(k)], -right);
      continue;
    }
    const size_t fs = size_t(f), ks = size_t(k);
    const int front_node = side_cell_node(level, l, 0, fs), back_node = side_cell_node(level, l, 1, ks);
    // Steps: the lower part belongs to the side with the lower floor, the upper part to the side
    // with the higher ceiling; each faces into its owner.
    if (level.floor[fs] != level.floor[ks]) {
      const bool front_low = level.floor[fs] < level.floor[ks];
      add_wall(shell_of(scene, front_low ? front_node : back_node), a, b, std::min(level.floor[fs], level.floor[ks]),
               std::max(level.floor[fs], level.floor[ks]), front_low ? right : -right);
    }
    if (level.ceiling[fs] != level.ceiling[ks]) {
      const bool front_high = level.ceiling[fs] > level.ceiling[ks];
      add_wall(shell_of(scene, front_high ? front_node : back_node), a, b,
               std::min(level.ceiling[fs], level.ceiling[ks]), std::max(level.ceiling[fs], level.ceiling[ks]),
               front_high ? right : -right);
    }
    const double lo = std::max(level.floor[fs], level.floor[ks]), hi = std::min(level.ceiling[fs], level.ceiling[ks]);
    if (hi - lo < kMinPortalSpan) {
      // No opening: close the gap between the steps from both sides.
      add_wall(shell_of(scene, front_node), a, b, lo, hi, right);
      add_wall(shell_of(scene, back_node), a, b, lo, hi, -right);
      continue;
    }
    add_portal("line_" + std::to_string(l), front_node, back_node, a, b, lo, hi,
               options.doors_open || !(level.door[fs] || level.door[ks]), scene);
    ++stats.portals;
  }
}

}  // namespace lintel::doom
