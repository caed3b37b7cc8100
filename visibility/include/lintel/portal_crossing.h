// Following a point from cell to cell by portal crossings, for things other than the viewer (moving
// instances): the same side rule and hysteresis band as ViewerTracker (viewer_tracker.h), over a
// per-world adjacency shared by every point that is followed.
#pragma once

#include <lintel/viewer_tracker.h>
#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lintel {

// Portals incident to each cell (from or to, one-way and closed ones included: the opening is
// physical), each portal's hysteresis_band_m, and the cells' volumes for locate_cell.
struct CrossingGraph {
  std::vector<uint32_t> incident_begin;  // cells + 1 offsets into `incident`
  std::vector<uint32_t> incident;
  std::vector<double> band_m;            // per portal
  double max_band_m = 0.0;
  std::vector<double> volumes_m3;        // per cell (cell_volumes_m3)

  void build(const World& world);  // allocates; once per World revision
};

// Follows the segment p0 -> p1 from `cell` through the portals it crosses, in order, at most
// `max_crossings`: the segment crosses portal P out of the current cell C when the signed distance
// seen from C goes from <= band(P) to > band(P) and that point lies in P's polygon (closed, 1 um
// slack) — ViewerTracker's rule exactly. Appends each crossing to `crossed` (portal indices) when
// it is non-null and returns the cell reached. Does not allocate when `crossed` has capacity.
uint32_t follow_portal_crossings(const World& world, const CrossingGraph& graph, uint32_t cell, const glm::dvec3& p0,
                                 const glm::dvec3& p1, uint32_t max_crossings, std::vector<uint32_t>* crossed = nullptr);

}  // namespace lintel
