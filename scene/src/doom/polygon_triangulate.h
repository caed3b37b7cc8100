// Triangulation of a polygon with holes by ear clipping: each hole is joined to the outer boundary
// by a bridge to a vertex it sees, then ears are cut one at a time (Eberly, "Triangulation by Ear
// Clipping", Geometric Tools, 2002). Built for exact input: corners are integers (Doom map
// vertices, |x| < 2^20), so every orientation test below is exact in double and the result can be
// checked exactly (triangulation_covers_outline).
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace lintel::doom {

// Twice the signed area of triangle a, b, c (> 0: counter-clockwise). Exact for integer corners.
double orient2(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c);

// Closed segments p-q and a-b share a point (touching counts). Exact for integer corners.
bool closed_segments_meet(const glm::dvec2& p, const glm::dvec2& q, const glm::dvec2& a, const glm::dvec2& b);

// Triangles over `corners` covering the polygon whose outer loop is `outer` (indices into
// `corners`, counter-clockwise) minus the holes (clockwise loops of indices). Preconditions (the
// caller checks them): the loops are simple, pairwise disjoint (no shared corner position), every
// hole lies inside `outer` and outside the other holes. Every corner is a corner of some triangle
// (collinear corners included), so each loop edge is an edge of exactly one triangle. Triangles
// are counter-clockwise index triples. Returns false (and no triangles) when no ear or bridge is
// found, which degenerate input can cause; the result is not checked here.
bool triangulate_polygon(const std::vector<glm::dvec2>& corners, const std::vector<uint32_t>& outer,
                         const std::vector<std::vector<uint32_t>>& holes,
                         std::vector<std::array<uint32_t, 3>>& triangles);

// The exact certificate that `triangles` tile the region bounded by `loops` (directed edges,
// the region on their left; loops simple and disjoint): every triangle is strictly
// counter-clockwise, no directed edge is used twice, and the edges whose reverse no triangle uses
// are exactly the loops' edges, each once. Then every point of the region is covered by exactly
// one triangle (the triangles' coverage sums to the winding number of their boundary, which is
// the loops) and nothing outside it is.
bool triangulation_covers_outline(const std::vector<glm::dvec2>& corners,
                                  const std::vector<std::vector<uint32_t>>& loops,
                                  const std::vector<std::array<uint32_t, 3>>& triangles);

}  // namespace lintel::doom
