// Clip regions: where on the screen a cell can be seen. A region is a small set of convex polygons
// in NDC (the union is the region) plus its bounding rect; the start cell's region is the whole
// screen [-1, 1]^2. Polygons are stored as float NDC vertices, counter-clockwise (y up), in the
// canonical order of ndc_snap.h. Descent and Tomb Raider kept one integer rect per cell; Lintel
// keeps a few convex polygons on the same kind of lattice and falls back to the rect (docs/visibility.md).
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <limits>
#include <span>

namespace lintel {

// A stored region polygon has at most this many vertices; a snapped polygon with more becomes
// its bounding rect (conservative). 32 x 8 bytes = 256 bytes per polygon slot.
inline constexpr uint32_t kMaxRegionPolygonVertices = 32;
// The most convex polygons VisibilityOptions::max_region_polygons may ask a region to hold.
inline constexpr uint32_t kMaxRegionPolygonsLimit = 16;

// Axis-aligned rect in NDC, closed. Empty when min > max (the default).
struct NdcRect {
  glm::vec2 min{std::numeric_limits<float>::infinity()};
  glm::vec2 max{-std::numeric_limits<float>::infinity()};

  bool empty() const { return min.x > max.x || min.y > max.y; }
  void extend(const glm::vec2& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void extend(const NdcRect& r) {
    if (r.empty()) return;
    extend(r.min);
    extend(r.max);
  }
  // Touching counts as overlapping: the tests are conservative.
  bool overlaps(const NdcRect& r) const {
    return !empty() && !r.empty() && min.x <= r.max.x && r.min.x <= max.x && min.y <= r.max.y && r.min.y <= max.y;
  }
  bool contains(const NdcRect& r) const {
    return !r.empty() && min.x <= r.min.x && min.y <= r.min.y && r.max.x <= max.x && r.max.y <= max.y;
  }
  friend bool operator==(const NdcRect&, const NdcRect&) = default;
};

// The full screen in NDC.
inline NdcRect full_screen_rect() { return NdcRect{glm::vec2(-1.0f), glm::vec2(1.0f)}; }

// One convex polygon of a region: a range of vertices in the owning vertex array.
struct RegionPolygon {
  uint32_t first_vertex = 0;
  uint32_t vertex_count = 0;
  friend bool operator==(const RegionPolygon&, const RegionPolygon&) = default;
};

// Bounds of a vertex list (empty list: empty rect).
NdcRect bounds_of(std::span<const glm::vec2> poly_ndc);

// Closed point-in-convex test. poly_ccw: >= 3 vertices, counter-clockwise. `tolerance` (NDC)
// widens every edge outward.
bool convex_contains_point(std::span<const glm::vec2> poly_ccw, const glm::dvec2& p_ndc, double tolerance = 0.0);

// Whether convex `inner` lies inside convex `outer` (closed). Exact for lattice polygons (their
// coordinates are multiples of a power of two, so the double cross products are exact).
bool convex_contains_convex(std::span<const glm::vec2> outer_ccw, std::span<const glm::vec2> inner);
// The same for points in double (closed: a point on an edge is inside).
bool convex_contains_points(std::span<const glm::vec2> outer_ccw, std::span<const glm::dvec2> points);

// Separating-axis test of a rect against a convex polygon; touching counts as overlap.
bool rect_overlaps_convex(const NdcRect& rect, std::span<const glm::vec2> poly_ccw);

// Read-only view of one cell's region inside a VisibleSet.
struct ClipRegionView {
  std::span<const RegionPolygon> polygons;
  std::span<const glm::vec2> vertices_ndc;  // what `polygons` index into
  NdcRect rect_ndc;                         // bounds of all polygons

  std::span<const glm::vec2> polygon(size_t i) const {
    return vertices_ndc.subspan(polygons[i].first_vertex, polygons[i].vertex_count);
  }
  bool contains(const glm::dvec2& p_ndc, double tolerance = 0.0) const;
  // Conservative: true if the rect touches any polygon of the region.
  bool overlaps(const NdcRect& rect) const;
};

}  // namespace lintel
