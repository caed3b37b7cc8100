// Closed containment and overlap tests on convex NDC polygons: the dedup test of the traversal and
// the rect-vs-region test of instance culling. Everything is evaluated in double; for polygons on
// the snap lattice (coordinates k * 2^-m) the cross products are exact, so dedup is exact there.
#include <lintel/clip_region.h>

#include <cassert>

namespace lintel {
namespace {

// > 0 when p is left of the directed edge a->b (inside for a CCW polygon).
double edge_side(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// Every point on the inner side of (or on) every edge of convex counter-clockwise `outer_ccw`.
template <typename Point>
bool contains_all(std::span<const glm::vec2> outer_ccw, std::span<const Point> points) {
  assert(outer_ccw.size() >= 3);
  const size_t n = outer_ccw.size();
  for (size_t i = 0; i < n; ++i) {
    const glm::dvec2 a(outer_ccw[i]);
    const glm::dvec2 b(outer_ccw[i + 1 == n ? 0 : i + 1]);
    for (const Point& v : points)
      if (edge_side(a, b, glm::dvec2(v)) < 0.0) return false;
  }
  return true;
}

}  // namespace

NdcRect bounds_of(std::span<const glm::vec2> poly_ndc) {
  NdcRect r;
  for (const glm::vec2& v : poly_ndc) r.extend(v);
  return r;
}

bool convex_contains_point(std::span<const glm::vec2> poly_ccw, const glm::dvec2& p_ndc, double tolerance) {
  assert(poly_ccw.size() >= 3 && tolerance >= 0.0);
  const size_t n = poly_ccw.size();
  for (size_t i = 0; i < n; ++i) {
    const glm::dvec2 a(poly_ccw[i]);
    const glm::dvec2 b(poly_ccw[i + 1 == n ? 0 : i + 1]);
    const double side = edge_side(a, b, p_ndc);
    if (side >= 0.0) continue;
    // Outside this edge's line: allow `tolerance` of distance.
    const double length = glm::length(b - a);
    if (length == 0.0 || -side > tolerance * length) return false;
  }
  return true;
}

bool convex_contains_convex(std::span<const glm::vec2> outer_ccw, std::span<const glm::vec2> inner) {
  return contains_all(outer_ccw, inner);
}

bool convex_contains_points(std::span<const glm::vec2> outer_ccw, std::span<const glm::dvec2> points) {
  return contains_all(outer_ccw, points);
}

bool rect_overlaps_convex(const NdcRect& rect, std::span<const glm::vec2> poly_ccw) {
  assert(poly_ccw.size() >= 3);
  if (rect.empty() || !rect.overlaps(bounds_of(poly_ccw))) return false;
  // Remaining separating axes: the polygon's edge normals. Separated when all four rect corners
  // lie strictly outside one edge.
  const glm::dvec2 corners[4] = {
      {rect.min.x, rect.min.y}, {rect.max.x, rect.min.y}, {rect.max.x, rect.max.y}, {rect.min.x, rect.max.y}};
  const size_t n = poly_ccw.size();
  for (size_t i = 0; i < n; ++i) {
    const glm::dvec2 a(poly_ccw[i]);
    const glm::dvec2 b(poly_ccw[i + 1 == n ? 0 : i + 1]);
    bool all_outside = true;
    for (const glm::dvec2& c : corners)
      if (edge_side(a, b, c) >= 0.0) {
        all_outside = false;
        break;
      }
    if (all_outside) return false;
  }
  return true;
}

bool ClipRegionView::contains(const glm::dvec2& p_ndc, double tolerance) const {
  for (size_t i = 0; i < polygons.size(); ++i)
    if (convex_contains_point(polygon(i), p_ndc, tolerance)) return true;
  return false;
}

bool ClipRegionView::overlaps(const NdcRect& rect) const {
  if (!rect.overlaps(rect_ndc)) return false;
  for (size_t i = 0; i < polygons.size(); ++i)
    if (rect_overlaps_convex(rect, polygon(i))) return true;
  return false;
}

}  // namespace lintel
