// A portal's polygon from its triangle mesh: the mesh must triangulate one planar convex polygon
// of 3..kMaxPortalVertices corners (any triangulation). Tolerances are relative to the polygon's
// size, so a door in millimetres and a hangar gate in metres are judged alike, and never below the
// float32 rounding of the coordinates the vertices came from (a small door far from its frame).
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace lintel::scene_read {

// Tolerances, each times the diagonal of the polygon's bounding box ("size").
inline constexpr double kPortalWeldTolerance = 1e-5;     // vertices closer than this are one vertex
inline constexpr double kPortalPlaneTolerance = 1e-3;    // max distance of a vertex from the plane
inline constexpr double kPortalOutlineTolerance = 1e-4;  // max distance of a vertex inside the outline
inline constexpr double kPortalAreaTolerance = 1e-3;     // |triangle area - outline area| / outline area
inline constexpr double kPortalDegenerateArea = 1e-6;    // area / size^2 below this is degenerate

// The rounding floor: a float32 vertex p_mesh taken to world by a float32 matrix [A | t] is off by
// up to about FLT_EPSILON * reach per coordinate, reach = |t|_inf + |A|_inf |p_mesh|_inf (every
// term of the product is at most that large). Distances measured between several such vertices
// (plane through the widest triangle, outline) add a few of those: the floor is kRoundingUlps
// times FLT_EPSILON times the largest reach.
inline constexpr double kRoundingUlps = 4.0;
// Below this size / rounding floor ratio the polygon cannot be represented at its coordinates'
// magnitude and is refused (its corners are not distinguishable from rounding).
inline constexpr double kMinSizeOverRounding = 20.0;

// The floor (m) for float32 points `p_mesh` taken to world by `mesh_to_world`.
double rounding_floor(const glm::dmat4& mesh_to_world, const std::vector<glm::vec3>& p_mesh);

struct ConvexPolygon {
  std::vector<glm::dvec3> vertices;  // projected onto the fitted plane, counter-clockwise about normal
  glm::dvec3 normal{0.0};            // unit, right-hand rule of the vertex order
  glm::dvec3 centroid{0.0};          // area centroid
  double plane_d = 0.0;              // dot(normal, p) == plane_d on the plane
  double area = 0.0;
  double size = 0.0;  // bounding-box diagonal of the input vertices
};

// Extracts the polygon from triangles (`indices`, 3 per triangle, into `points`). Returns an
// empty string on success, otherwise the fault ("is not planar: ...", "is not convex: ...").
// Steps: weld, fit a plane, 2D convex hull in that plane, then check that every vertex is on the
// outline and that the triangles cover the outline exactly once (area and open-edge checks).
// Vertices lying on an outline edge (within tolerance) are dropped from the result. The result
// winds like the file's triangles (by their summed signed area); callers orient it between cells.
// `rounding_m` is the rounding floor of the points (rounding_floor(); 0 for exact input): each
// tolerance is the larger of its relative value and the floor (areas: floor x size).
std::string extract_convex_polygon(const std::vector<glm::dvec3>& points, const std::vector<uint32_t>& indices,
                                   ConvexPolygon& out, double rounding_m = 0.0);

// Reverses the vertex order and flips the normal (and plane_d).
void flip_polygon(ConvexPolygon& polygon);

}  // namespace lintel::scene_read
