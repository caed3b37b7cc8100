// Clipping a portal polygon on its way to screen space: against a plane parallel to the near
// plane and against the far plane, in homogeneous clip space (before the divide, so a portal
// around an eye standing in a doorway is clipped faithfully instead of exploding as w -> 0), then
// against one convex region polygon in NDC (Sutherland-Hodgman). All arithmetic is double;
// callers store results as float. Clip space follows view.h (w is the view depth).
//
// Why not the near plane itself: a ray that crosses a portal between the eye and the near plane
// still shows the cell behind it from the near plane on, so clipping the portal at the near plane
// would lose those pixels. The traversal clips at depth portal_clip_depth(view) < near instead;
// crossings closer than that are covered by the doorway rule (doorway_rule.h, docs/visibility.md).
#pragma once

#include <lintel/clip_region.h>
#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <span>

namespace lintel {

// Each clip plane adds at most one vertex to a convex polygon.
inline constexpr uint32_t kMaxSlabClippedVertices = kMaxPortalVertices + 2;
inline constexpr uint32_t kMaxRegionClippedVertices = kMaxSlabClippedVertices + kMaxRegionPolygonVertices;

struct SlabClipResult {
  uint32_t count = 0;         // vertices written to `out`; < 3 means nothing is left
  bool near_clipped = false;  // some vertex lay closer than min_depth (w < min_depth): cut away
};

// Clips convex polygon `in` (homogeneous clip space, 3..kMaxPortalVertices vertices) to the slab
// w >= min_depth (view depth, meters, > 0) and z <= w (the far plane). `out` and `scratch` need
// in.size() + 2 entries. Everything at or behind the eye (w <= 0) is removed; min_depth = near
// gives the ordinary near/far clip.
SlabClipResult clip_to_depth_slab(std::span<const glm::dvec4> in, double min_depth, std::span<glm::dvec4> out,
                                  std::span<glm::dvec4> scratch);

// x / w, y / w for each vertex. Precondition: every w > 0 (true after clip_to_depth_slab).
void perspective_divide(std::span<const glm::dvec4> in, std::span<glm::dvec2> out_ndc);

// Twice the signed area (> 0: counter-clockwise with y up).
double twice_signed_area(std::span<const glm::dvec2> poly);

// Sutherland-Hodgman: clips convex `subject` (NDC, counter-clockwise, up to
// kMaxSlabClippedVertices) by the closed half-planes of convex counter-clockwise `window`
// (a region polygon, up to kMaxRegionPolygonVertices). `out` and `scratch` need
// subject.size() + window.size() entries. Returns the number of vertices written (< 3: empty).
uint32_t clip_convex_by_convex(std::span<const glm::dvec2> subject, std::span<const glm::vec2> window,
                               std::span<glm::dvec2> out, std::span<glm::dvec2> scratch);

}  // namespace lintel
