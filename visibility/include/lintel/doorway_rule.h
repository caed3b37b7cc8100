// Where the eye stands relative to a portal, as seen from one of the portal's cells, and the
// doorway rule (docs/visibility.md): when the eye is within the near distance of a portal's plane
// and its projection onto that plane lies inside the portal polygon expanded by the near plane's
// half-extent, the neighbour receives the current cell's region unchanged. Near the plane the
// projected portal degenerates (edge-on at distance 0, behind the eye just past it); the rule
// makes visibility continuous as the eye crosses. The viewer tracker uses the same signed
// distance, so "which side of the portal" means one thing everywhere.
#pragma once

#include <lintel/view.h>
#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>

namespace lintel {

// Signed distance in meters of `p_world` from the portal's plane, positive on the far side as seen
// from `cell` (the side of the other cell). Precondition: cell is portal.from or portal.to.
// The traversal projects a portal when this is < 0 and the doorway rule does not apply (the rule
// needs a magnitude <= near). The tracker splits space with the portal's own orientation: distance
// seen from `from` > 0 is `to`'s side, <= 0 is `from`'s side (viewer_tracker.h).
double portal_signed_distance(const Portal& portal, uint32_t cell, const glm::dvec3& p_world);
// The same from the portal's plane alone (normal_world, plane_d_world), for callers that keep a
// packed copy of it; `from_side`: cell == portal.from. One expression for both, bit for bit.
inline double portal_signed_distance(const glm::vec3& normal_world, float plane_d_world, bool from_side,
                                     const glm::dvec3& p_world) {
  const double s = glm::dot(glm::dvec3(normal_world), p_world) - double(plane_d_world);
  return from_side ? s : -s;
}

// Whether `p_world`, projected along the portal normal onto its plane, lies inside the polygon with
// every edge moved outward by `expand_m` meters (closed). Works for either vertex winding.
bool projects_inside_portal(const Portal& portal, const glm::dvec3& p_world, double expand_m);

// The view depth (meters) at which the traversal clips projected portals:
// 0.5 * near * min(sin(theta), cos(theta)), theta the angle between the view direction and a
// corner ray of the frustum. A ray inside the frustum that crosses a portal closer than this is
// within near of the portal's plane and within half the near half-extent of the polygon, so the
// doorway rule passes the whole region through that portal: nothing is lost by not projecting
// the part of the portal closer than this depth (docs/visibility.md, "Near clipping").
double portal_clip_depth(const View& view);

// The doorway rule for `view` and the portal seen from `cell`:
// |portal_signed_distance| <= view.near_m and projects_inside_portal(eye, near_half_extent(view)).
bool eye_in_doorway(const Portal& portal, uint32_t cell, const View& view);

}  // namespace lintel
