// Conservative snapping of NDC polygons to a lattice, in a canonical vertex order, so that the
// traversal can recognise a polygon it has already seen (dedup) and so that a region can only
// take finitely many shapes (termination). Descent and Tomb Raider got the same two properties
// from integer screen rects that only grow; Lintel keeps convex polygons on the lattice instead.
//
// The lattice: `cells` cells per NDC axis over [-1, 1], a power of two up to 2^21 (spacing
// 2 / cells from 1 down to 9.5e-7 NDC, the 1e-6 the accuracy issue asked for). Why these bounds:
//   * every lattice coordinate -1 + k * 2 / cells is a multiple of 2^-20 in [-1, 1], which needs at
//     most 21 significant bits: exact in float, so regions are stored (and uploaded) exactly;
//   * in lattice units the hull's cross products are products of integers <= 2^21, below 2^43, and
//     in NDC products of multiples of 2^-20 up to 2 in size, multiples of 2^-40 below 8: both exact
//     in double, so containment and dedup between lattice polygons are exact;
//   * the tolerance below is 1e-12 NDC at 2^21 cells, still about 5000 double ulps of a coordinate
//     near 1, far above the rounding noise of the clipper (a few ulps), so a lattice polygon that
//     went round a cycle of portals still snaps back to itself.
// Float storage would allow 2^25 and double exactness 2^26, but the input does not carry that
// much: portal vertices are floats in world space (about 1e-7 relative), so past 2^21 the snap
// stops being what limits a region's tightness. The pop bound grows with `cells` (pop_bound()).
//
// Snapping replaces every vertex by the four corners of the lattice cell holding it and takes
// their convex hull: the hull contains every vertex, hence the whole polygon (it is the Minkowski
// sum with one lattice cell, never smaller than the input). A coordinate within
// kSnapToleranceCells of a lattice line counts as on it, so that double rounding noise on a
// polygon that is already on the lattice does not push it out by a whole cell every time it goes
// round a cycle of portals; the snapped polygon therefore contains the input up to
// kSnapToleranceCells * 2 / cells NDC (2e-9 NDC at the default 1024 cells, 1e-12 at 2^21, far
// below the float precision the input had).
#pragma once

#include <lintel/clip_region.h>
#include <lintel/portal_clip.h>

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <span>

namespace lintel {

inline constexpr uint32_t kDefaultSnapLatticeCells = 1024;
inline constexpr uint32_t kMaxSnapLatticeCells = uint32_t{1} << 21;  // 2 / cells = 9.5e-7 NDC
inline constexpr double kSnapToleranceCells = 1e-6;
// Largest input snap_polygon_conservative accepts (a portal clipped by the slab and a region polygon).
inline constexpr uint32_t kMaxSnapInputVertices = kMaxRegionClippedVertices;

// Power of two in [2, kMaxSnapLatticeCells].
bool valid_snap_lattice(uint32_t cells);

// A point of the snap lattice in lattice units (0..cells per axis).
struct LatticePoint {
  int64_t x = 0, y = 0;
};

// The lattice cell of a vertex, lattice units: [x0, x1] x [y0, y1] (zero width on a lattice line).
struct LatticeBox {
  int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// Reusable working memory of snap_polygon_conservative (about 13 KB; no allocation).
struct SnapScratch {
  std::array<glm::dvec2, kMaxSnapInputVertices + 4> screen_a;
  std::array<glm::dvec2, kMaxSnapInputVertices + 4> screen_b;
  std::array<glm::dvec2, 4 * (kMaxSnapInputVertices + 4)> corners;
  std::array<glm::dvec2, 4 * (kMaxSnapInputVertices + 4) + 1> hull;
  // Lattice mode: the vertices' cells (sorted by x0), the lowest and the highest corner of each
  // lattice column (at most two columns per box; lowest in the first half, highest in the second)
  // and the integer hull.
  std::array<LatticeBox, kMaxSnapInputVertices + 4> boxes;
  std::array<LatticePoint, 4 * (kMaxSnapInputVertices + 4)> lattice_points;
  std::array<LatticePoint, 4 * (kMaxSnapInputVertices + 4) + 1> lattice_hull;
};

// Snaps convex `poly_ndc` (any orientation, <= kMaxSnapInputVertices vertices; parts outside the
// screen are clipped away first) and writes the result to `out` (kMaxRegionPolygonVertices
// entries): counter-clockwise, starting at the lexicographically smallest (x, y) vertex, without
// repeated or collinear vertices, inside [-1, 1]^2. A hull with more than kMaxRegionPolygonVertices
// vertices is replaced by its bounding rect (still conservative). Returns the vertex count, or 0
// when the input has fewer than 3 vertices or does not meet the screen.
//
// lattice_cells == 0 is the TEST-ONLY unsnapped mode (VisibilityBuilderTesting::
// disable_snap_and_cap): the "lattice" is float precision itself and every coordinate is
// widened one float ulp outward so that storage stays conservative. Nothing makes that finite.
// `bounds`, when given, receives bounds_of() of the result (the snap has them anyway).
uint32_t snap_polygon_conservative(std::span<const glm::dvec2> poly_ndc, uint32_t lattice_cells,
                                   std::span<glm::vec2> out, SnapScratch& scratch, NdcRect* bounds = nullptr);

}  // namespace lintel
