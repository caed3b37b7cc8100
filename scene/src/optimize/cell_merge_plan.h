// Which cells of a World merge (see lintel/optimize.h): union-find over the portal graph, first the
// pairs whose portals cover most of their shared wall, then slivers into their widest neighbour,
// each union refused when it would swallow a closable portal or outgrow the size limits.
#pragma once

#include <lintel/optimize.h>
#include <lintel/world.h>

#include <cstdint>
#include <vector>

namespace lintel::optimize {

struct CellMergePlan {
  std::vector<uint32_t> group_of_cell;        // per cell: index into `groups`
  std::vector<std::vector<uint32_t>> groups;  // cells of each merged cell, ascending; ordered by first cell
  uint32_t open_wall_merges = 0, sliver_merges = 0, closable_portals = 0;
};

// A portal the merge never crosses: one-way, closed in either direction, or named by an event of
// one of the world's timelines (a door that a timeline opens or closes).
std::vector<bool> closable_portals(const World& world);

// The fraction of the wall shared by `portal`'s two cells that the portal opens: its area over the
// union of both cells' volume faces lying in its plane. Negative when it cannot
// be judged (a horizontal portal, or volumes that do not reach the portal plane). Both boundaries
// are net areas: faces between pieces of one cell cancel.
double portal_open_fraction(const World& world, uint32_t portal);

CellMergePlan plan_cell_merges(const World& world, const OptimizeOptions& options);

}  // namespace lintel::optimize
