// Conservative snapping of NDC polygons to a lattice, in a canonical vertex order, so that the
// traversal can recognise a polygon it has already seen (dedup) and so that a region can only
// take finitely many shapes (termination). Descent and Tomb Raider got the same two properties
// from integer screen rects that only grow; Lintel keeps convex polygons on the lattice instead.
//
// The lattice: `cells` cells per NDC axis over [-1, 1] (a power of two, so every lattice
// coordinate -1 + k * 2 / cells is exact in float and cross products of lattice points are exact
// in double). Snapping replaces every vertex by the four corners of the lattice cell holding it
// and takes their convex hull: the hull contains every vertex, hence the whole polygon (it is the
// Minkowski sum with one lattice cell, never smaller than the input). A coordinate within
// kSnapToleranceCells of a lattice line counts as on it, so that double rounding noise on a
// polygon that is already on the lattice does not push it out by a whole cell every time it goes
// round a cycle of portals; the snapped polygon therefore contains the input up to
// kSnapToleranceCells * 2 / cells NDC (2e-9 NDC at the default 1024 cells, far below the float
// precision the input had).
#pragma once

#include <lintel/portal_clip.h>

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <span>

namespace lintel {

inline constexpr uint32_t kDefaultSnapLatticeCells = 1024;
inline constexpr uint32_t kMaxSnapLatticeCells = 65536;
inline constexpr double kSnapToleranceCells = 1e-6;
// Largest input snap_polygon_conservative accepts (a portal clipped by the slab and a region polygon).
inline constexpr uint32_t kMaxSnapInputVertices = kMaxRegionClippedVertices;

// Power of two in [2, kMaxSnapLatticeCells].
bool valid_snap_lattice(uint32_t cells);

// Reusable working memory of snap_polygon_conservative (about 13 KB; no allocation).
struct SnapScratch {
  std::array<glm::dvec2, kMaxSnapInputVertices + 4> screen_a;
  std::array<glm::dvec2, kMaxSnapInputVertices + 4> screen_b;
  std::array<glm::dvec2, 4 * (kMaxSnapInputVertices + 4)> corners;
  std::array<glm::dvec2, 4 * (kMaxSnapInputVertices + 4) + 1> hull;
};

// Snaps convex `poly_ndc` (any orientation, <= kMaxSnapInputVertices vertices; parts outside the
// screen are clipped away first) and writes the result to `out` (kMaxRegionPolygonVertices
// entries): counter-clockwise, starting at the lexicographically smallest (x, y) vertex, without
// repeated or collinear vertices, inside [-1, 1]^2. A hull with more than kMaxRegionPolygonVertices
// vertices is replaced by its bounding rect (still conservative). Returns the vertex count, or 0
// when the input has fewer than 3 vertices or does not meet the screen.
//
// lattice_cells == 0 is the TEST-ONLY unsnapped mode (VisibilityOptions::
// test_only_disable_snap_and_cap): the "lattice" is float precision itself and every coordinate is
// widened one float ulp outward so that storage stays conservative. Nothing makes that finite.
uint32_t snap_polygon_conservative(std::span<const glm::dvec2> poly_ndc, uint32_t lattice_cells,
                                   std::span<glm::vec2> out, SnapScratch& scratch);

}  // namespace lintel
