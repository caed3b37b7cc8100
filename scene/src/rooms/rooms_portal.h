// A '*-portal' mesh of the rooms convention as a Lintel portal: its vertices must be planar (the
// loader's scale-aware tolerance), the polygon is their convex hull in the plane, wound about the
// mesh's face normal (right-hand rule); it is linked to the two rooms whose volumes it touches,
// found by probing points beside the polygon.
#pragma once

#include "rooms/rooms_volume.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace lintel::rooms {

// Probe distances beside the polygon, times its size (the diagonal of its vertices' box): a room
// counts as touched on one side when its volume lies within the largest of them.
inline constexpr double kProbeSteps[] = {1e-3, 1e-2, 5e-2, 0.15};

struct HullPolygon {
  std::vector<glm::dvec3> corners_world;  // counter-clockwise about `normal` (right-hand rule)
  glm::dvec3 normal{0.0};                 // unit: the mesh's face normal (summed triangle areas)
  glm::dvec3 centroid{0.0};               // mean of the corners
  double size = 0.0;
  double rounding_m = 0.0;         // the float32 rounding floor of the input vertices
  bool winding_consistent = true;  // false when the triangles' facing cancels out
};

// `points_world` are the portal mesh's vertices in world space, `indices` its triangles;
// `rounding_m` their rounding floor (scene_read::rounding_floor). Returns "" or the fault
// ("is not planar: ...", "is degenerate ...", "has more than 64 corners ...").
std::string hull_polygon(const std::vector<glm::dvec3>& points_world, const std::vector<uint32_t>& indices,
                         double rounding_m, HullPolygon& out);

struct PortalLinkResult {
  int from = -1, to = -1;    // room indices: from = behind the normal, to = in front
  std::vector<int> touched;  // every room touched (for messages)
};

// Probes points a little behind and in front of the polygon (its centroid and corners pulled 20 %
// towards it), at the distances kProbeSteps x size (at least 2 x the rounding floor), nearest
// first; per side the rooms hit at the first distance that hits any. Returns "" with from/to set
// when exactly two rooms are touched and one lies behind, the other in front; otherwise the fault.
std::string link_portal(const HullPolygon& polygon, const std::vector<RoomVolume>& rooms,
                        const std::vector<std::string>& room_names, PortalLinkResult& out);

// A mirror: the same probes, in front of its face only (what lies behind it is the wall it hangs
// on, and maybe another room); exactly one room must be touched there: from = to = that room.
std::string link_mirror(const HullPolygon& polygon, const std::vector<RoomVolume>& rooms,
                        const std::vector<std::string>& room_names, PortalLinkResult& out);

}  // namespace lintel::rooms
