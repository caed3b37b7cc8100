// A non-convex sector as a few cells: its exact convex pieces (doom_sector_partition.h) merged
// greedily into unions that stay convex within a tolerance, and the cuts between those unions,
// which become always-open portals. Pieces that touch nothing of their sector (disjoint loops)
// end in unions of their own. Hertel & Mehlhorn's greedy merge again, across the diagonals the
// exact merge kept, with a looser convexity test (hull area).
#pragma once

#include "doom/doom_sector_partition.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <utility>
#include <vector>

namespace lintel::doom {

// A straight cut between union `left` and union `right` (indices into the groups): `left` lies to
// the left of a -> b, `right` to its right (map x, y). a and b are line ends of the sector.
struct GroupBoundary {
  size_t left = 0, right = 0;
  glm::dvec2 a{0.0}, b{0.0};
};

// Groups the pieces of `part` into unions of pieces joined by diagonals whose convex hull exceeds
// their area by at most `hull_excess` (relative, e.g. 0.02). The pairs in `must_join` (piece
// indices) are joined first whatever their hull (a thing stands across their diagonal); then the
// pairs that share the longest boundary, repeatedly until no pair merges. Returns the group of
// every piece; groups are numbered in the order of their smallest piece.
std::vector<size_t> convex_piece_groups(const SectorPartition& part, double hull_excess,
                                        const std::vector<std::pair<size_t, size_t>>& must_join, size_t& group_count);

// The cuts between different groups: the diagonals between pieces of two groups, collinear
// neighbours with the same two groups joined into one.
std::vector<GroupBoundary> group_boundaries(const SectorPartition& part, const std::vector<size_t>& group_of_piece);

}  // namespace lintel::doom
