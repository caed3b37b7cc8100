// A portal's polygon from its triangle mesh: the mesh must triangulate one planar convex polygon
// of 3..kMaxPortalVertices corners (any triangulation). All tolerances are relative to the
// polygon's size, so a door in millimetres and a hangar gate in metres are judged alike.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace lintel::scene_read {

// Tolerances, each times the diagonal of the polygon's bounding box ("size").
inline constexpr double kPortalWeldTolerance = 1e-5;      // vertices closer than this are one vertex
inline constexpr double kPortalPlaneTolerance = 1e-3;     // max distance of a vertex from the plane
inline constexpr double kPortalOutlineTolerance = 1e-4;   // max distance of a vertex inside the outline
inline constexpr double kPortalAreaTolerance = 1e-3;      // |triangle area - outline area| / outline area
inline constexpr double kPortalDegenerateArea = 1e-6;     // area / size^2 below this is degenerate

struct ConvexPolygon {
  std::vector<glm::dvec3> vertices;  // projected onto the fitted plane, counter-clockwise about normal
  glm::dvec3 normal{0.0};            // unit, right-hand rule of the vertex order
  glm::dvec3 centroid{0.0};          // area centroid
  double plane_d = 0.0;              // dot(normal, p) == plane_d on the plane
  double area = 0.0;
  double size = 0.0;                 // bounding-box diagonal of the input vertices
};

// Extracts the polygon from triangles (`indices`, 3 per triangle, into `points`). Returns an
// empty string on success, otherwise the fault ("is not planar: ...", "is not convex: ...").
// Steps: weld, fit a plane, 2D convex hull in that plane, then check that every vertex is on the
// outline and that the triangles cover the outline exactly once (area and open-edge checks).
// Vertices lying on an outline edge (within tolerance) are dropped from the result. The result
// winds like the file's triangles (by their summed signed area); callers orient it between cells.
std::string extract_convex_polygon(const std::vector<glm::dvec3>& points, const std::vector<uint32_t>& indices,
                                   ConvexPolygon& out);

// Reverses the vertex order and flips the normal (and plane_d).
void flip_polygon(ConvexPolygon& polygon);

}  // namespace lintel::scene_read
