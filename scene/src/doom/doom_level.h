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

inline constexpr int kDoorLip = 4;       // map units a Doom door stops below the lowest neighbouring ceiling
inline constexpr double kEyeUnits = 41;  // Doom's view height above the floor

struct Level {
  Map map;
  std::vector<FloorPiece> pieces;
  std::vector<std::vector<size_t>> pieces_of_sector;
  std::vector<int> floor, ceiling;  // effective heights (doors opened)
  std::vector<uint8_t> door;        // 1: a closed sector opened as a door
  std::vector<int> cell_node;       // SceneDesc node of the sector's (first) cell, or -1 (solid / no floor)
  // Sectors split into convex cells (DoomImportOptions::convex_cells): the cell node of every piece
  // (-1 before the cells exist), the piece of every subsector (-1: none, a sliver), the subsector of
  // every seg and the segs of every linedef.
  std::vector<int> piece_node;
  std::vector<int> piece_of_subsector;
  std::vector<uint16_t> seg_subsector;
  std::vector<std::vector<uint32_t>> segs_of_line;
  // The boundaries between cells of one sector (map x, y): a thing's box stays clear of them as
  // of lines, so that it stays in its cell.
  std::vector<std::pair<glm::dvec2, glm::dvec2>> cuts;
};

// Map (x, y) and height (units) -> Lintel world (m): X = x, Y = height, Z = -y, scaled.
inline glm::vec3 to_world(double x, double y, double height) {
  return glm::vec3(float(x * kDoomMetersPerUnit), float(height * kDoomMetersPerUnit), float(-y * kDoomMetersPerUnit));
}
inline glm::vec3 to_world(const glm::dvec2& p, double height) { return to_world(p.x, p.y, height); }

// Pieces, effective heights and door flags for `map`.
void prepare_level(Map map, Level& out, uint32_t& door_count);

// The sector a two-sided line's side leads to, or -1 when that side has no cell.
int side_cell_sector(const Level& level, uint16_t sidedef);

// The cell node under map point p: the cell of the piece of its subsector, else the first cell of
// the subsector's sector; -1 when that sector has no cell.
int cell_node_at(const Level& level, const glm::dvec2& p);

// The cell node of the piece of `sector` nearest to p (map units), and that distance when asked.
int nearest_piece_node(const Level& level, size_t sector, const glm::dvec2& p, double* distance);

// Cells with shells and volumes, then one portal per open two-sided line span. Appends to `scene`.
void add_cells_and_portals(Level& level, const DoomImportOptions& options, SceneDesc& scene, DoomImportStats& stats);

// Things as instances (one mesh and draw group per thing type) and point lights in bright sectors.
void add_things_and_lights(const Level& level, SceneDesc& scene, DoomImportStats& stats);

// The "doorway" timeline from the player 1 start through up to `crossings` portals.
void add_doorway_walk(const Level& level, uint32_t crossings, SceneDesc& scene, DoomImportStats& stats);

}  // namespace lintel::doom
