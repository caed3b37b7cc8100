// Portal polygon extraction: weld -> plane from the widest triangle -> Andrew's monotone-chain
// hull (A. M. Andrew, "Another efficient algorithm for convex hulls in two dimensions", 1979) in
// the plane -> Newell's normal of the hull -> planarity, outline and area checks.
#include "read/portal_polygon.h"

#include "read/load_context.h"

#include <lintel/world.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <map>

namespace lintel::scene_read {
namespace {

double cross2(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Indices of the hull of `pts`, counter-clockwise, collinear points excluded.
std::vector<size_t> convex_hull(const std::vector<glm::dvec2>& pts) {
  std::vector<size_t> order(pts.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return pts[a].x < pts[b].x || (pts[a].x == pts[b].x && pts[a].y < pts[b].y); });
  std::vector<size_t> hull(2 * order.size());
  size_t k = 0;
  for (size_t i : order) {  // lower chain
    while (k >= 2 && cross2(pts[hull[k - 2]], pts[hull[k - 1]], pts[i]) <= 0.0) --k;
    hull[k++] = i;
  }
  for (size_t j = order.size() - 1, lower = k + 1; j-- > 0;) {  // upper chain
    const size_t i = order[j];
    while (k >= lower && cross2(pts[hull[k - 2]], pts[hull[k - 1]], pts[i]) <= 0.0) --k;
    hull[k++] = i;
  }
  hull.resize(k > 1 ? k - 1 : k);  // the last point repeats the first
  return hull;
}

double distance_to_segment(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
  const glm::dvec2 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

double polygon_area_2d(const std::vector<glm::dvec2>& pts, const std::vector<size_t>& ring) {
  double twice = 0.0;
  for (size_t i = 0; i < ring.size(); ++i) {
    const glm::dvec2& a = pts[ring[i]];
    const glm::dvec2& b = pts[ring[(i + 1) % ring.size()]];
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * twice;
}

// Removes outline corners that lie within `tolerance` of the segment joining their neighbours;
// removing a corner of a convex polygon keeps it convex. Such corners only add degenerate edges.
void drop_flat_corners(const std::vector<glm::dvec2>& pts, std::vector<size_t>& ring, double tolerance) {
  bool changed = true;
  while (changed && ring.size() > 3) {
    changed = false;
    for (size_t i = 0; i < ring.size() && ring.size() > 3; ++i) {
      const glm::dvec2& prev = pts[ring[(i + ring.size() - 1) % ring.size()]];
      const glm::dvec2& next = pts[ring[(i + 1) % ring.size()]];
      if (distance_to_segment(pts[ring[i]], prev, next) <= tolerance) {
        ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
      }
    }
  }
}

// The triangles must cover the outline exactly once. Unsigned areas must add up to the outline's
// area, and the edges used by an odd number of triangles (the boundary of the triangle set, mod 2)
// must all run along the outline: then every point inside is covered an odd number of times, so
// at least once, and the area sum leaves no room for more. Either alone is fooled: two triangles
// that overlap exactly as much as they leave uncovered pass the area test. Triangles of near-zero
// area are ignored (any triangulation may contain slivers).
std::string check_single_cover(const std::vector<glm::dvec2>& flat, const std::vector<size_t>& ring,
                               const std::vector<uint32_t>& welded, double hull_area, double outline_tolerance,
                               double degenerate_area, double area_tolerance) {
  double covered = 0.0;
  std::map<std::pair<uint32_t, uint32_t>, int> edge_uses;
  for (size_t t = 0; t + 2 < welded.size(); t += 3) {
    const uint32_t v[3] = {welded[t], welded[t + 1], welded[t + 2]};
    const double area = 0.5 * std::fabs(cross2(flat[v[0]], flat[v[1]], flat[v[2]]));
    if (area <= degenerate_area) continue;
    covered += area;
    for (int e = 0; e < 3; ++e) ++edge_uses[std::minmax(v[e], v[(e + 1) % 3])];
  }
  if (std::fabs(covered - hull_area) > area_tolerance)
    return "is not one convex polygon: its triangles cover " + number_text(covered) + " m^2 but the outline has " +
           number_text(hull_area) + " m^2 (overlaps, holes or separate pieces)";
  size_t boundary_edges = 0;
  for (const auto& [edge, uses] : edge_uses) {
    if (uses % 2 == 0) continue;
    ++boundary_edges;
    const glm::dvec2 mid = 0.5 * (flat[edge.first] + flat[edge.second]);
    double nearest = INFINITY;
    for (size_t e = 0; e < ring.size(); ++e)
      nearest = std::min(nearest, distance_to_segment(mid, flat[ring[e]], flat[ring[(e + 1) % ring.size()]]));
    if (nearest > outline_tolerance)
      return "is not one convex polygon: its triangles overlap or leave a hole (an open edge crosses the interior)";
  }
  if (boundary_edges == 0) return "is not one convex polygon: its triangles cover the outline twice";
  return {};
}

}  // namespace

double rounding_floor(const glm::dmat4& mesh_to_world, const std::vector<glm::vec3>& p_mesh) {
  double row_sum = 0.0, translation = 0.0;
  for (int r = 0; r < 3; ++r) {
    row_sum = std::max(
        row_sum, std::fabs(mesh_to_world[0][r]) + std::fabs(mesh_to_world[1][r]) + std::fabs(mesh_to_world[2][r]));
    translation = std::max(translation, std::fabs(mesh_to_world[3][r]));
  }
  double largest = 0.0;
  for (const glm::vec3& p : p_mesh)
    largest = std::max({largest, double(std::fabs(p.x)), double(std::fabs(p.y)), double(std::fabs(p.z))});
  return kRoundingUlps * double(FLT_EPSILON) * (translation + row_sum * largest);
}

std::string extract_convex_polygon(const std::vector<glm::dvec3>& points, const std::vector<uint32_t>& indices,
                                   ConvexPolygon& out, double rounding_m) {
  out = {};
  if (indices.size() < 3) return "has no triangles";
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (uint32_t i : indices) {
    lo = glm::min(lo, points[i]);
    hi = glm::max(hi, points[i]);
  }
  const double size = glm::length(hi - lo);
  if (!(size > 0.0) || !std::isfinite(size)) return "is degenerate (all vertices coincide)";
  out.size = size;
  if (size < kMinSizeOverRounding * rounding_m)
    return "is too small for its coordinates: size " + number_text(size) + " m against a float32 rounding of " +
           number_text(rounding_m) + " m at their magnitude (move the node's frame closer to the portal)";
  // Each tolerance: its relative value, or the rounding floor where that is larger.
  const double plane_tolerance = std::max(kPortalPlaneTolerance * size, rounding_m);
  const double outline_tolerance = std::max(kPortalOutlineTolerance * size, rounding_m);
  const double degenerate_area = std::max(kPortalDegenerateArea * size * size, rounding_m * size);

  // Weld: the file may repeat a corner once per triangle, with rounding. welded[k] is the
  // distinct vertex that indices[k] became.
  std::vector<glm::dvec3> unique;
  std::vector<uint32_t> welded(indices.size());
  const double weld = std::max(kPortalWeldTolerance * size, rounding_m);
  for (size_t k = 0; k < indices.size(); ++k) {
    const glm::dvec3& p = points[indices[k]];
    const auto known =
        std::find_if(unique.begin(), unique.end(), [&](const glm::dvec3& q) { return glm::length(p - q) <= weld; });
    if (known != unique.end()) {
      welded[k] = uint32_t(known - unique.begin());
      continue;
    }
    if (unique.size() == kMaxPortalVertices)
      return "has more than " + std::to_string(kMaxPortalVertices) + " distinct vertices (the format's limit)";
    welded[k] = uint32_t(unique.size());
    unique.push_back(p);
  }
  if (unique.size() < 3) return "is degenerate (fewer than 3 distinct vertices)";

  // Provisional plane from the widest triangle of distinct vertices: p0, the vertex farthest from
  // it, and the vertex farthest from the line through both.
  const glm::dvec3 p0 = unique[0];
  glm::dvec3 p1 = p0;
  for (const glm::dvec3& p : unique)
    if (glm::length(p - p0) > glm::length(p1 - p0)) p1 = p;
  glm::dvec3 widest(0.0);
  for (const glm::dvec3& p : unique) {
    const glm::dvec3 c = glm::cross(p1 - p0, p - p0);
    if (glm::length(c) > glm::length(widest)) widest = c;
  }
  if (glm::length(widest) <= 2.0 * degenerate_area) return "is degenerate (its vertices are collinear)";
  const glm::dvec3 n0 = glm::normalize(widest);
  // Planarity first, against the plane through the widest triangle: the later checks measure
  // areas and outlines in that plane and would misreport a bent polygon.
  double worst = 0.0;
  for (const glm::dvec3& p : unique) worst = std::max(worst, std::fabs(glm::dot(n0, p - p0)));
  if (worst > plane_tolerance)
    return "is not planar: a vertex is " + number_text(worst) + " m from the plane (tolerance " +
           number_text(plane_tolerance) + " m)";
  const glm::dvec3 u = glm::normalize(p1 - p0);
  const glm::dvec3 v = glm::cross(n0, u);
  std::vector<glm::dvec2> flat(unique.size());
  for (size_t i = 0; i < unique.size(); ++i) flat[i] = {glm::dot(unique[i] - p0, u), glm::dot(unique[i] - p0, v)};

  std::vector<size_t> ring = convex_hull(flat);
  const double hull_area = ring.size() >= 3 ? polygon_area_2d(flat, ring) : 0.0;
  if (!(hull_area > degenerate_area))
    return "is degenerate (area " + number_text(hull_area) + " m^2 is near zero for its size " + number_text(size) +
           " m)";

  // Every vertex must be a corner of the outline or lie on it: one inside makes the polygon
  // non-convex (or the mesh is not a single polygon).
  for (size_t i = 0; i < flat.size(); ++i) {
    if (std::find(ring.begin(), ring.end(), i) != ring.end()) continue;
    double nearest = INFINITY;
    for (size_t e = 0; e < ring.size(); ++e)
      nearest = std::min(nearest, distance_to_segment(flat[i], flat[ring[e]], flat[ring[(e + 1) % ring.size()]]));
    if (nearest > outline_tolerance)
      return "is not convex: a vertex lies " + number_text(nearest) + " m inside the outline of the others";
  }

  // Rounding moves the area by at most the perimeter (< 4 x size for a convex polygon) times the floor.
  const double area_tolerance = std::max(kPortalAreaTolerance * hull_area, 4.0 * size * rounding_m);
  if (std::string why =
          check_single_cover(flat, ring, welded, hull_area, outline_tolerance, degenerate_area, area_tolerance);
      !why.empty())
    return why;

  drop_flat_corners(flat, ring, outline_tolerance);

  // Keep the file's winding where it has one: the outline is counter-clockwise about n0, so
  // reverse it when the triangles mostly wind the other way about n0.
  double signed_area = 0.0;
  for (size_t t = 0; t + 2 < welded.size(); t += 3)
    signed_area += 0.5 * cross2(flat[welded[t]], flat[welded[t + 1]], flat[welded[t + 2]]);
  if (signed_area < 0.0) std::reverse(ring.begin(), ring.end());

  // Newell's normal and the area centroid of the outline give the stored plane.
  glm::dvec3 newell(0.0), weighted(0.0);
  double area_sum = 0.0;
  for (size_t i = 0; i < ring.size(); ++i) {
    const glm::dvec3& a = unique[ring[i]];
    const glm::dvec3& b = unique[ring[(i + 1) % ring.size()]];
    newell += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  out.normal = glm::normalize(newell);
  const glm::dvec3& anchor = unique[ring[0]];
  for (size_t i = 1; i + 1 < ring.size(); ++i) {
    const double a = 0.5 * glm::dot(glm::cross(unique[ring[i]] - anchor, unique[ring[i + 1]] - anchor), out.normal);
    weighted += a * (anchor + unique[ring[i]] + unique[ring[i + 1]]) / 3.0;
    area_sum += a;
  }
  out.centroid = weighted / area_sum;
  out.area = area_sum;
  out.plane_d = glm::dot(out.normal, out.centroid);

  out.vertices.reserve(ring.size());
  for (size_t i : ring)
    out.vertices.push_back(unique[i] - (glm::dot(out.normal, unique[i]) - out.plane_d) * out.normal);
  return {};
}

void flip_polygon(ConvexPolygon& polygon) {
  std::reverse(polygon.vertices.begin(), polygon.vertices.end());
  polygon.normal = -polygon.normal;
  polygon.plane_d = -polygon.plane_d;
}

}  // namespace lintel::scene_read
