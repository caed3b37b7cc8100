// The Level the scene builder shares between its steps (doom_level.h): the BSP's floor pieces,
// the effective heights (closed doors opened, sealed platforms lowered), which sector Doom draws
// beside each side of each line, and the lookups from a sector or sidedef to its cells.
#include "doom/doom_level.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <unordered_map>

namespace lintel::doom {
namespace {

// Level::bsp_sector_beside. A seg's subsector is the sector Doom's renderer draws there (the sector
// of the subsector's first seg). The seg over the line's middle, not a probe point beside it: a
// point one unit off the line lands in the next sector where another line runs one unit away
// (freedoom2 MAP28, line 2826), and a point closer than the node builder's rounding of partition
// lines (a few tenths of a unit) may land in the wrong subsector.
std::vector<uint16_t> bsp_sectors_beside_lines(const Map& m) {
  std::vector<uint16_t> beside(2 * m.linedefs.size(), kNoBspSector);
  for (const Subsector& ss : m.subsectors) {
    const uint16_t sector = m.seg_sector(m.segs[ss.first_seg]);
    for (uint32_t i = ss.first_seg; i < uint32_t(ss.first_seg) + ss.seg_count; ++i) {
      const Seg& seg = m.segs[i];
      const Linedef& line = m.linedefs[seg.linedef];
      const glm::dvec2 a = m.vertices[line.v1], d = glm::dvec2(m.vertices[line.v2]) - a;
      if (d == glm::dvec2(0.0)) continue;
      // The seg's span along its line, in the line's parameter (0 at v1, 1 at v2).
      const double t1 = glm::dot(glm::dvec2(m.vertices[seg.v1]) - a, d) / glm::dot(d, d);
      const double t2 = glm::dot(glm::dvec2(m.vertices[seg.v2]) - a, d) / glm::dot(d, d);
      uint16_t& slot = beside[2 * size_t(seg.linedef) + (seg.reversed ? 1 : 0)];
      if (slot == kNoBspSector && std::min(t1, t2) <= 0.5 && 0.5 <= std::max(t1, t2)) slot = sector;
    }
  }
  return beside;
}

// How far a Doom floor special lowers the sectors it tags (vanilla line types; Boom's generalized
// ones are not read): to the lowest floor around and under the sector, to the highest around, or
// 8 units above that.
enum class FloorLowering { None, ToLowest, ToHighest, ToHighestPlus8 };

FloorLowering floor_lowering(uint16_t special) {
  switch (special) {
    case 23:
    case 38:
    case 60:
    case 82:  // floor lower to lowest: S1, W1, SR, WR
    case 37:
    case 84:  // the same, changing texture and type: W1, WR
    case 10:
    case 21:
    case 62:
    case 88:  // lifts (down to the lowest, wait, up): W1, S1, SR, WR
    case 120:
    case 121:
    case 122:
    case 123:  // turbo lifts: WR, W1, S1, SR
      return FloorLowering::ToLowest;
    case 19:
    case 45:
    case 83:
    case 102:  // floor lower to highest: W1, SR, WR, S1
      return FloorLowering::ToHighest;
    case 36:
    case 70:
    case 71:
    case 98:  // turbo lower to 8 above highest: W1, SR, S1, WR
      return FloorLowering::ToHighestPlus8;
    default:
      return FloorLowering::None;
  }
}

// A sector sealed from all its neighbours (no line into another sector leaves an opening the
// portals would keep) whose floor a line lowers is imported lowered, as a closed door is imported
// open: it is a platform the player stands on or rides down (E2M8 starts on one that a switch
// lowers), and sealed it would be a cell no portal reaches. Sectors with an opening keep their
// height: the walk and the portals already reach them.
uint32_t lower_sealed_platforms(const Map& m, const std::vector<std::vector<uint16_t>>& neighbours, Level& out) {
  // Per tag, the lowering of the first line (in line order) that lowers the floors it tags.
  std::unordered_map<uint16_t, FloorLowering> lowering_of_tag;
  for (const Linedef& line : m.linedefs)
    if (const FloorLowering how = floor_lowering(line.special); how != FloorLowering::None && line.tag != 0)
      lowering_of_tag.emplace(line.tag, how);
  uint32_t lowered = 0;
  std::vector<int> target(m.sectors.size());
  for (size_t s = 0; s < m.sectors.size(); ++s) {
    target[s] = out.floor[s];
    const auto tagged = lowering_of_tag.find(m.sectors[s].tag);
    if (m.sectors[s].tag == 0 || tagged == lowering_of_tag.end() || neighbours[s].empty()) continue;
    const FloorLowering how = tagged->second;
    bool sealed = true;
    int lowest = m.sectors[s].floor, highest = INT_MIN;
    for (uint16_t n : neighbours[s]) {
      sealed = sealed &&
               std::min(out.ceiling[s], out.ceiling[n]) - std::max(out.floor[s], out.floor[n]) < int(kMinPortalSpan);
      lowest = std::min(lowest, m.sectors[n].floor);
      highest = std::max(highest, m.sectors[n].floor);
    }
    if (!sealed) continue;
    const int to = how == FloorLowering::ToLowest ? lowest : how == FloorLowering::ToHighest ? highest : highest + 8;
    if (to < out.floor[s]) target[s] = to;
  }
  for (size_t s = 0; s < m.sectors.size(); ++s)
    if (target[s] != out.floor[s]) out.floor[s] = target[s], ++lowered;
  return lowered;
}

}  // namespace

void prepare_level(Map map, Level& out, uint32_t& door_count, uint32_t& lowered_count) {
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
  out.side_node.assign(2 * m.linedefs.size(), -1);
  out.split_pieces.assign(m.sectors.size(), {});
  out.bsp_sector_beside = bsp_sectors_beside_lines(m);
  // The sectors across each sector's two-sided lines (both directions; repeats are harmless).
  std::vector<std::vector<uint16_t>> neighbours(m.sectors.size());
  for (const Linedef& line : m.linedefs) {
    if (line.back == kNoSide) continue;
    const uint16_t f = m.sidedefs[line.front].sector, b = m.sidedefs[line.back].sector;
    if (f == b) continue;
    neighbours[f].push_back(b);
    neighbours[b].push_back(f);
  }
  // A closed sector (ceiling at or below its floor) opens like a Doom door: up to the lowest
  // ceiling around it, minus a lip. One that cannot open (no higher neighbour) stays solid.
  door_count = 0;
  for (size_t s = 0; s < m.sectors.size(); ++s) {
    out.floor[s] = m.sectors[s].floor;
    out.ceiling[s] = m.sectors[s].ceiling;
    if (out.ceiling[s] > out.floor[s]) continue;
    int lowest_neighbour_ceiling = INT_MAX;
    for (uint16_t n : neighbours[s])
      lowest_neighbour_ceiling = std::min(lowest_neighbour_ceiling, m.sectors[n].ceiling);
    if (lowest_neighbour_ceiling != INT_MAX && lowest_neighbour_ceiling - kDoorLip > out.floor[s]) {
      out.ceiling[s] = lowest_neighbour_ceiling - kDoorLip;
      out.door[s] = 1;
      ++door_count;
    }
  }
  lowered_count = lower_sealed_platforms(m, neighbours, out);
}

uint16_t sector_beside_line(const Level& level, size_t l, int side) {
  if (const uint16_t s = level.bsp_sector_beside[2 * l + size_t(side)]; s != kNoBspSector) return s;
  const Map& m = level.map;
  const glm::dvec2 a = m.vertices[m.linedefs[l].v1], b = m.vertices[m.linedefs[l].v2];
  const glm::dvec2 right = glm::normalize(glm::dvec2(b.y - a.y, a.x - b.x));
  const glm::dvec2 p = 0.5 * (a + b) + (side == 0 ? right : -right);
  return m.seg_sector(m.segs[m.subsectors[subsector_at(m, p)].first_seg]);
}

int side_cell_sector(const Level& level, uint16_t sidedef) {
  if (sidedef == kNoSide) return -1;
  const uint16_t s = level.map.sidedefs[sidedef].sector;
  return level.cell_node[s] >= 0 ? int(s) : -1;
}

int cell_node_at(const Level& level, size_t sector, const glm::dvec2& p) {
  const std::vector<Level::SplitPiece>& pieces = level.split_pieces[sector];
  if (pieces.empty()) return level.cell_node[sector];
  double best = INFINITY;
  int node = pieces.front().node;
  for (const Level::SplitPiece& piece : pieces) {
    // Distance from p to the convex piece (0 inside).
    double outside = 0.0, edge = INFINITY;
    const std::vector<glm::dvec2>& poly = piece.polygon;
    for (size_t i = 0; i < poly.size(); ++i) {
      const glm::dvec2 a = poly[i], u = poly[(i + 1) % poly.size()] - a;
      const double len2 = glm::dot(u, u);
      if (len2 == 0.0) continue;
      outside = std::max(outside, (u.y * (p.x - a.x) - u.x * (p.y - a.y)) / std::sqrt(len2));  // > 0: right of the edge
      const double along = std::clamp(glm::dot(p - a, u) / len2, 0.0, 1.0);
      edge = std::min(edge, glm::length(p - (a + along * u)));
    }
    const double d = outside > 0.0 ? edge : 0.0;
    if (d < best) best = d, node = piece.node;
  }
  return node;
}

}  // namespace lintel::doom
