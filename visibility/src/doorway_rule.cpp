// The doorway rule: a portal the eye stands in passes the region through unchanged.
// Learns from: The Dark Mod's fix to Doom 3 (Doom 3 skipped clipping within 1 unit of any portal
// "because of epsilon problems that make the area vanish"; The Dark Mod applies the bypass only if
// the eye is inside the portal's expanded bounds) and Godot's rooms & portals, where the world
// vanished for a frame as the camera passed a portal.
#include <lintel/doorway_rule.h>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace lintel {

double portal_signed_distance(const Portal& portal, uint32_t cell, const glm::dvec3& p_world) {
  assert(cell == portal.from || cell == portal.to);
  return portal_signed_distance(portal.normal_world, portal.plane_d_world, cell == portal.from, p_world);
}

bool projects_inside_portal(const Portal& portal, const glm::dvec3& p_world, double expand_m) {
  const auto& poly = portal.polygon_world;
  assert(poly.size() >= 3 && expand_m >= 0.0);
  // Newell normal of the vertex order actually stored: the edge normals below point outward
  // whichever way the polygon winds around normal_world.
  glm::dvec3 winding(0.0);
  const size_t n = poly.size();
  for (size_t i = 0; i < n; ++i) {
    const glm::dvec3 a(poly[i]), b(poly[(i + 1) % n]);
    winding += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  const double winding_length = glm::length(winding);
  if (!(winding_length > 0.0)) return false;  // degenerate polygon: nothing to stand in
  winding /= winding_length;
  for (size_t i = 0; i < n; ++i) {
    const glm::dvec3 a(poly[i]), b(poly[(i + 1) % n]);
    const glm::dvec3 outward = glm::cross(b - a, winding);
    const double length = glm::length(outward);
    if (length == 0.0) continue;  // repeated vertex
    // Distance within the plane: the component along `outward` ignores the offset along the normal.
    if (glm::dot(p_world - a, outward) > expand_m * length) return false;
  }
  return true;
}

double portal_clip_depth(const View& view) {
  // tan(theta) = near_half_extent / near.
  const double theta = std::atan(near_half_extent(view) / double(view.near_m));
  return 0.5 * double(view.near_m) * std::min(std::sin(theta), std::cos(theta));
}

bool eye_in_doorway(const Portal& portal, uint32_t cell, const View& view) {
  const glm::dvec3 eye(view.eye_world);
  const double s = portal_signed_distance(portal, cell, eye);
  return std::abs(s) <= double(view.near_m) && projects_inside_portal(portal, eye, near_half_extent(view));
}

}  // namespace lintel
