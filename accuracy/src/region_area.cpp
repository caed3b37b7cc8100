// Slice integration of the area of a union of convex polygons (region_area.h).
#include <lintel/reference/region_area.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace lintel {
namespace {

// The x-interval a convex polygon covers on the line y = y0, or false when it misses the line.
bool interval_at(const std::vector<glm::dvec2>& poly, double y0, double& x_lo, double& x_hi) {
  x_lo = std::numeric_limits<double>::infinity();
  x_hi = -x_lo;
  const size_t n = poly.size();
  for (size_t i = 0; i < n; ++i) {
    const glm::dvec2 a = poly[i], b = poly[(i + 1) % n];
    if ((a.y - y0) * (b.y - y0) > 0.0) continue;  // edge entirely above or below
    if (a.y == b.y) {
      x_lo = std::min({x_lo, a.x, b.x});
      x_hi = std::max({x_hi, a.x, b.x});
      continue;
    }
    const double x = a.x + (b.x - a.x) * (y0 - a.y) / (b.y - a.y);
    x_lo = std::min(x_lo, x);
    x_hi = std::max(x_hi, x);
  }
  return x_lo <= x_hi;
}

}  // namespace

double union_area_ndc(std::span<const std::vector<glm::dvec2>> polygons, uint32_t rows) {
  double y_min = std::numeric_limits<double>::infinity(), y_max = -y_min;
  for (const auto& p : polygons) {
    if (p.size() < 3) continue;
    for (const glm::dvec2& v : p) {
      y_min = std::min(y_min, v.y);
      y_max = std::max(y_max, v.y);
    }
  }
  if (!(y_min < y_max) || rows == 0) return 0.0;
  const double dy = (y_max - y_min) / rows;
  std::vector<std::pair<double, double>> spans;
  double area = 0.0;
  for (uint32_t r = 0; r < rows; ++r) {
    const double y0 = y_min + (r + 0.5) * dy;
    spans.clear();
    for (const auto& p : polygons) {
      double lo = 0.0, hi = 0.0;
      if (p.size() >= 3 && interval_at(p, y0, lo, hi)) spans.emplace_back(lo, hi);
    }
    std::sort(spans.begin(), spans.end());
    double covered = 0.0, cur_lo = 0.0, cur_hi = -std::numeric_limits<double>::infinity();
    for (const auto& [lo, hi] : spans) {
      if (lo > cur_hi) {
        if (std::isfinite(cur_hi)) covered += cur_hi - cur_lo;
        cur_lo = lo;
        cur_hi = hi;
      } else {
        cur_hi = std::max(cur_hi, hi);
      }
    }
    if (std::isfinite(cur_hi)) covered += cur_hi - cur_lo;
    area += covered * dy;
  }
  return area;
}

void measure_regions(const VisibleSet& visible, std::vector<std::vector<glm::dvec2>>& scratch, MethodResult& out) {
  for (const VisibleCell& c : visible.cells) {
    out.cell_bounds[c.cell] = glm::dvec4(c.rect_ndc.min.x, c.rect_ndc.min.y, c.rect_ndc.max.x, c.rect_ndc.max.y);
    const ClipRegionView region = visible.region(c);
    scratch.resize(region.polygons.size());
    for (size_t i = 0; i < region.polygons.size(); ++i) {
      const auto p = region.polygon(i);
      scratch[i].assign(p.begin(), p.end());
    }
    out.cell_region_area[c.cell] = union_area_ndc(scratch);
  }
}

}  // namespace lintel
