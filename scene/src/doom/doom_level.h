// What the Doom scene builder shares between its steps: the decoded map, its convex floor
// pieces, the heights each sector gets (doors opened), and the cell node of every sector.
#pragma once

#include "doom/doom_map.h"
#include "doom/doom_subsector_polygons.h"

#include <lintel/doom_import.h>
#include <lintel/scene_desc.h>

#include <glm/glm.hpp>

#include <utility>
#include <vector>

namespace lintel::doom {

inline constexpr int kDoorLip = 4;             // map units a Doom door stops below the lowest neighbouring ceiling
inline constexpr double kEyeUnits = 41;        // Doom's view height above the floor
inline constexpr double kMinPortalSpan = 1.0;  // map units: a thinner opening is treated as closed

struct Level {
  Map map;
  std::vector<FloorPiece> pieces;
  std::vector<std::vector<size_t>> pieces_of_sector;
  std::vector<int> floor, ceiling;  // effective heights (doors opened)
  std::vector<uint8_t> door;        // 1: a closed sector opened as a door
  std::vector<int> cell_node;       // SceneDesc node of the sector's (first) cell, or -1 (solid / no floor)
  // Sectors split into convex cells (DoomImportOptions::convex_cells): the cell node of each side
  // of each line (index 2 * linedef + 0 front / 1 back; -1: not a side of a split sector), the
  // split sectors' exact convex pieces with their cells, and the cuts between their cells (map
  // x, y), which a thing's box keeps clear of as of lines, so that it stays in its cell.
  std::vector<int> side_node;
  struct SplitPiece {
    std::vector<glm::dvec2> polygon;  // convex, counter-clockwise
    int node = -1;
  };
  std::vector<std::vector<SplitPiece>> split_pieces;  // per sector; empty: one cell
  std::vector<std::pair<glm::dvec2, glm::dvec2>> cuts;
  // The sector Doom draws beside each side of each line (index 2 * linedef + 0 front / 1 back):
  // that of the BSP subsector holding the side's seg over the line's middle; kNoBspSector when
  // the BSP has no such seg (a line the node builder left out).
  std::vector<uint16_t> bsp_sector_beside;
};

inline constexpr uint16_t kNoBspSector = 0xffff;

// The sector Doom draws beside side `side` (0: front, the right of v1 -> v2; 1: back) of line l:
// Level::bsp_sector_beside, else the sector under a point one unit off the line's middle.
uint16_t sector_beside_line(const Level& level, size_t l, int side);

// Map (x, y) and height (units) -> Lintel world (m): X = x, Y = height, Z = -y, scaled.
inline glm::vec3 to_world(double x, double y, double height) {
  return glm::vec3(float(x * kDoomMetersPerUnit), float(height * kDoomMetersPerUnit), float(-y * kDoomMetersPerUnit));
}
inline glm::vec3 to_world(const glm::dvec2& p, double height) { return to_world(p.x, p.y, height); }

// Pieces, effective heights (closed doors opened, sealed platforms lowered) and door flags for `map`.
void prepare_level(Map map, Level& out, uint32_t& door_count, uint32_t& lowered_count);

// The sector a two-sided line's side leads to, or -1 when that side has no cell.
int side_cell_sector(const Level& level, uint16_t sidedef);

// The cell node of `sector` at map point p: its only cell, or for a split sector the cell of the
// piece that holds p (the nearest piece when p lies in none); -1 when the sector has no cell.
int cell_node_at(const Level& level, size_t sector, const glm::dvec2& p);

// Cells with shells and volumes, then one portal per open two-sided line span. Appends to `scene`.
void add_cells_and_portals(Level& level, const DoomImportOptions& options, SceneDesc& scene, DoomImportStats& stats);

// A thing drawn as an instance: where it stands, and how far a cut between two cells of its
// sector must keep from it so that the box stays at least half as wide as the lines around it
// allow, and at least 1 unit (a box never crosses a cut: it is shrunk, add_things_and_lights).
struct ThingClearance {
  glm::dvec2 position{0.0};
  double clearance = 0.0;  // map units
};
// Per sector (the BSP's sector under each thing, as add_things_and_lights places them).
std::vector<std::vector<ThingClearance>> thing_clearances(const Map& map);

double distance_to_segment(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b);

// Things as instances (one mesh and draw group per thing type) and point lights in bright sectors.
void add_things_and_lights(const Level& level, SceneDesc& scene, DoomImportStats& stats);

// The "doorway" timeline from the player 1 start through up to `crossings` portals.
void add_doorway_walk(const Level& level, uint32_t crossings, SceneDesc& scene, DoomImportStats& stats);

}  // namespace lintel::doom
