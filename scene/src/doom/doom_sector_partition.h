// A sector's floor cut exactly into convex pieces, from its own lines rather than from the BSP:
// the lines with the sector on one side only form its outline (outer loops and holes), which is
// checked to be simple, triangulated by ear clipping with an exact certificate, and the triangles
// merged into convex pieces by dropping every diagonal whose removal keeps the piece convex
// (Hertel & Mehlhorn, "Fast triangulation of simple polygons", 1983: at most 4x the fewest convex
// pieces). Every corner is a map vertex (integers), so neighbouring pieces share their edges
// exactly, every line of the outline lies on exactly one piece, and a cut between pieces runs
// from one line end to another. The BSP's subsector polygons cannot give that: vanilla node
// builders round the split points, so neighbouring subsectors need not meet edge to edge.
#pragma once

#include "doom/doom_map.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace lintel::doom {

struct SectorPartition {
  std::vector<glm::dvec2> corners;  // the outline's corners (map units, integers), each position once
  struct Piece {
    std::vector<uint32_t> polygon;                   // convex, counter-clockwise (collinear corners kept)
    std::vector<std::array<uint32_t, 3>> triangles;  // counter-clockwise, tiling the polygon
  };
  std::vector<Piece> pieces;  // tile the sector's floor: no overlap, no gap
  // An edge between two pieces: `left` lies to the left of corners[a] -> corners[b], `right` to
  // its right.
  struct Diagonal {
    uint32_t a = 0, b = 0;
    size_t left = 0, right = 0;
  };
  std::vector<Diagonal> diagonals;
  // The piece each side of the sector's lines bounds: (2 * linedef + 0 for its front side or 1
  // for its back side, piece), ascending by side.
  std::vector<std::pair<uint32_t, size_t>> side_piece;
  double area = 0.0;  // map units^2 (exact: twice it is an integer)
};

// Partitions sector `sector` of `map`. Lines with the sector on both sides (decoration) are not
// part of the outline. Empty string on success; otherwise why the lines do not bound the sector
// as a polygon with holes ("a corner joins 4 of its lines", "two of its lines cross", ...): such
// a sector is kept as one cell. Cost: O(n^2) in the sector's line count (exact tests pairwise).
// `lines`: the linedefs with the sector on a side (others are skipped), or all of the map's.
std::string partition_sector(const Map& map, uint16_t sector, const std::vector<uint32_t>& lines, SectorPartition& out);
std::string partition_sector(const Map& map, uint16_t sector, SectorPartition& out);

// Area of the convex hull of `points` (Andrew's monotone chain; exact for integer points).
double convex_hull_area(std::vector<glm::dvec2> points);

}  // namespace lintel::doom
