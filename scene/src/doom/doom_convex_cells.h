// A non-convex sector as a few convex cells: its convex floor pieces (the BSP's subsectors) merged
// greedily into maximal unions that stay convex within a tolerance, and the boundaries between
// those unions, which become always-open portals. Pieces that touch nothing of their sector
// (disjoint loops) end in unions of their own. The approach of Hertel & Mehlhorn's greedy merge
// of a triangulation into convex parts, applied to the BSP's convex pieces instead of triangles.
#pragma once

#include "doom/doom_subsector_polygons.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <vector>

namespace lintel::doom {

// A straight stretch of boundary between union `left` and union `right` (indices into the
// groups): `left` lies to the left of a -> b, `right` to its right (map x, y, counter-clockwise).
struct GroupBoundary {
  size_t left = 0, right = 0;
  glm::dvec2 a{0.0}, b{0.0};
};

// Groups `piece_ids` (indices into `pieces`, all of one sector) into unions of adjacent pieces
// whose convex hull exceeds their area by at most `hull_excess` (relative, e.g. 0.02) plus a
// rounding allowance. Merges the pairs that share the longest boundary first and repeats until no
// pair merges. Every piece is in exactly one group; groups list piece ids ascending, and are
// ordered by their smallest piece id.
std::vector<std::vector<size_t>> convex_piece_groups(const std::vector<FloorPiece>& pieces,
                                                     const std::vector<size_t>& piece_ids, double hull_excess);

// The boundaries between different groups of one sector: each maximal straight run of edges the
// groups' pieces share (edges of two pieces that lie on one line, facing each other).
std::vector<GroupBoundary> group_boundaries(const std::vector<FloorPiece>& pieces,
                                            const std::vector<std::vector<size_t>>& groups);

// Area of the convex hull of the corners of `piece_ids` (map units^2).
double convex_hull_area(const std::vector<FloorPiece>& pieces, const std::vector<size_t>& piece_ids);

}  // namespace lintel::doom
