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
  std::vector<glm::dvec4> portal_plane;  // per portal: normal_world, plane_d_world (a compact copy)
  std::vector<uint32_t> from;            // per portal: Portal::from
  double max_band_m = 0.0;
  std::vector<double> volumes_m3;  // per cell (cell_volumes_m3)
  // Per cell whose volume is convex (a box, or a triangle volume every vertex of which lies
  // inside every triangle's plane): its face planes in world space, outward (xyz unit normal,
  // w = -offset), so that containment is a handful of dot products. Empty range: not convex
  // (callers use cell_volume_distance_m).
  std::vector<uint32_t> plane_begin;  // cells + 1 offsets into `planes`
  std::vector<glm::dvec4> planes;

  void build(const World& world);  // allocates; once per World revision
  // True when p is inside the cell's convex volume by its planes (then cell_volume_distance_m is
  // 0 up to float rounding of the planes, far below any threshold the callers use); false when
  // outside or when the volume is not convex (unknown: ask cell_volume_distance_m).
  bool surely_inside(uint32_t cell, const glm::dvec3& p_world) const;
  // For a convex volume: min over its face planes of p's distance inside them -- for p inside, its
  // distance to the boundary (up to the planes' rounding, some 1e-12 m); negative outside (p lies
  // that far beyond some face plane). NaN when the volume is not convex (unknown: ask
  // cell_volume_clearance_m). The planes are the world-space volume, cell_volume_contains tests in
  // cell space: they differ by the frames' float rounding (1e-7 x the coordinates).
  double inside_clearance(uint32_t cell, const glm::dvec3& p_world) const;
};

// Follows the segment p0 -> p1 from `cell` through the portals it crosses, in order, at most
// `max_crossings`: the segment crosses portal P out of the current cell C when the signed distance
// seen from C goes from <= band(P) to > band(P) and that point lies in P's polygon (closed, 1 um
// slack) — ViewerTracker's rule exactly. Appends each crossing to `crossed` (portal indices) when
// it is non-null and returns the cell reached. Does not allocate when `crossed` has capacity.
uint32_t follow_portal_crossings(const World& world, const CrossingGraph& graph, uint32_t cell, const glm::dvec3& p0,
                                 const glm::dvec3& p1, uint32_t max_crossings,
                                 std::vector<uint32_t>* crossed = nullptr);

}  // namespace lintel
