// Internal: merging the pending polygons of a popped cell into fewer convex clip windows. Each
// portal of the cell is clipped once per window, and each piece costs a clip, a snap and a region
// insert downstream, so two pending polygons whose convex hull is hardly larger than the two
// together are replaced by that hull. The hull holds both, so every piece the two would have
// given lies inside a piece the hull gives: the flood stays conservative (docs/visibility.md,
// "Merged clip windows").
#pragma once

#include <lintel/clip_region.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <span>

namespace lintel::detail {

// A merge is taken when the hull's area is at most (1 + kMergeSlack) times the two polygons'
// areas summed (overlap counts twice, so a polygon inside the other always merges).
inline constexpr double kMergeSlack = 0.10;

// Convex hull of the vertices of `a` and `b` (convex, counter-clockwise, float NDC; for lattice
// polygons every product below is exact in double) into `out`, counter-clockwise from the
// lexicographically smallest vertex, without collinear vertices. Returns its vertex count, or 0
// when it would need more than out.size() vertices. `scratch` holds a.size() + b.size() + 1 points.
uint32_t convex_hull_of_two(std::span<const glm::vec2> a, std::span<const glm::vec2> b, std::span<glm::vec2> out,
                            std::span<glm::dvec2> scratch);

// Twice the area of a counter-clockwise polygon, in double.
double twice_area(std::span<const glm::vec2> poly);

// Pending polygons of one pop: `vertices` holds `count` polygons, polygon i at
// i * kMaxRegionPolygonVertices with counts[i] vertices and bounds rects[i]. Merges pairs (a
// merged window may merge again) while some pair's hull passes the slack test, compacting the
// arrays; returns the new count. Every input polygon lies inside some output polygon.
uint32_t merge_pending_windows(std::span<glm::vec2> vertices, std::span<uint32_t> counts, std::span<NdcRect> rects,
                               uint32_t count);

}  // namespace lintel::detail
