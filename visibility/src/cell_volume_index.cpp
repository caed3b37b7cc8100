// CellVolumeIndex (cell_locate.h): cell_volume_contains' ray test with each volume triangle's
// bounds across the ray taken once, filed in a 1D grid along one sheared axis (u or v) and ordered
// by how far along the ray they reach, so that a test meets only the triangles whose bounds can
// hold its point. Learns from: Ericson 2005 "Real-Time Collision Detection" 7.1 (uniform grids)
// and 7.1.6 (objects filed in every cell they overlap).
#include <lintel/cell_locate.h>

#include "point_in_volume.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace lintel {
namespace {

// Cells with fewer triangles are scanned whole: a grid would not pay for itself.
constexpr size_t kMinTrianglesToFile = 16;
// At most one bucket per kTrianglesPerBucket triangles, and few enough that the triangles are
// filed about kMaxFilingsPerTriangle times each at most (a triangle goes in every bucket its
// bounds overlap; a level's floors span many).
constexpr size_t kTrianglesPerBucket = 2;
constexpr double kMaxFilingsPerTriangle = 4.0;

bool finite(const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

}  // namespace

size_t CellVolumeIndex::CellEntry::bucket_of(double x) const {
  // Monotonic in x (a rounded subtraction, a product with a positive number, floor and clamp all
  // are), so a triangle with lo <= x <= hi is filed in x's bucket.
  return size_t(std::clamp(std::floor((x - min) * buckets_per_unit), 0.0, double(buckets - 1)));
}

void CellVolumeIndex::build(const World& world) {
  cells_.assign(world.cells.size(), CellEntry{});
  shadows_.clear();
  bucket_begin_.clear();
  filed_.clear();
  size_t triangles = 0;
  for (const Cell& cell : world.cells) triangles += cell.volume_triangles_cell.size() / 3;
  shadows_.reserve(triangles);
  for (size_t c = 0; c < world.cells.size(); ++c) {
    CellEntry& entry = cells_[c];
    const auto& t = world.cells[c].volume_triangles_cell;
    entry.first_shadow = shadows_.size();
    entry.triangles = t.size() / 3;
    entry.sorted = std::all_of(t.begin(), t.begin() + std::ptrdiff_t(3 * entry.triangles), finite);
    for (size_t i = 0; i + 2 < t.size(); i += 3) {
      const glm::dvec3 a(t[i]), b(t[i + 1]), cc(t[i + 2]);
      const glm::dvec2 a_uv = sheared(a), b_uv = sheared(b), c_uv = sheared(cc);
      // Widened outward past any difference in rounding between these bounds and the step's own
      // (a fused multiply-add that the compiler contracts in one place and not the other: a few
      // ulps of the coordinates), so that the filter never drops a triangle the step would see.
      // x_hi is the step's own first test, exact (a choice among three converted floats).
      const glm::dvec3 m = glm::max(glm::max(glm::abs(a), glm::abs(b)), glm::abs(cc));
      const double widen = 1e-12 * std::max({m.x, m.y, m.z});
      shadows_.push_back({std::min({a_uv.x, b_uv.x, c_uv.x}) - widen, std::max({a_uv.x, b_uv.x, c_uv.x}) + widen,
                          std::min({a_uv.y, b_uv.y, c_uv.y}) - widen, std::max({a_uv.y, b_uv.y, c_uv.y}) + widen,
                          std::max({a.x, b.x, cc.x}), uint32_t(i / 3)});
    }
    if (!entry.sorted) continue;  // a non-finite vertex: met in order, every one
    // Farthest along the ray first: a test stops at the first triangle wholly behind its point.
    Shadow* shadows = shadows_.data() + entry.first_shadow;
    std::stable_sort(shadows, shadows + entry.triangles,
                     [](const Shadow& x, const Shadow& y) { return x.x_hi > y.x_hi; });
    if (entry.triangles < kMinTrianglesToFile) continue;
    // The grid runs along u or v, whichever meets fewer triangles at a random point (the walls of
    // a y-up level span all of u; its floors and ceilings span v).
    double best_share = HUGE_VAL, best_span = 0.0;
    for (int axis = 0; axis < 2; ++axis) {
      double lo = HUGE_VAL, hi = -HUGE_VAL, span = 0.0;
      for (size_t k = 0; k < entry.triangles; ++k) {
        lo = std::min(lo, shadows[k].lo(axis));
        hi = std::max(hi, shadows[k].hi(axis));
        span += shadows[k].hi(axis) - shadows[k].lo(axis);
      }
      if (!(hi > lo) || !(span / (hi - lo) < best_share)) continue;
      best_share = span / (hi - lo);
      best_span = span;
      entry.axis = axis;
      entry.min = lo;
      entry.max = hi;
    }
    if (best_share == HUGE_VAL) continue;
    const double range = entry.max - entry.min;
    const double by_filings = (kMaxFilingsPerTriangle - 1.0) * double(entry.triangles) * range / best_span;
    const size_t buckets = size_t(std::min(double(entry.triangles / kTrianglesPerBucket), by_filings));
    entry.buckets_per_unit = double(buckets) / range;
    if (buckets <= 1 || !std::isfinite(entry.buckets_per_unit)) continue;
    entry.buckets = buckets;
    // Counting sort into the buckets (CSR); within each, the triangles keep their order along x.
    const int axis = entry.axis;
    entry.first_bucket = bucket_begin_.size();
    bucket_begin_.resize(bucket_begin_.size() + buckets + 1, 0);
    size_t* begin = bucket_begin_.data() + entry.first_bucket;
    for (size_t k = 0; k < entry.triangles; ++k)
      for (size_t b = entry.bucket_of(shadows[k].lo(axis)), last = entry.bucket_of(shadows[k].hi(axis)); b <= last; ++b)
        ++begin[b + 1];
    begin[0] = filed_.size();
    for (size_t b = 0; b < buckets; ++b) begin[b + 1] += begin[b];
    filed_.resize(begin[buckets]);
    std::vector<size_t> next(begin, begin + buckets);
    for (size_t k = 0; k < entry.triangles; ++k)
      for (size_t b = entry.bucket_of(shadows[k].lo(axis)), last = entry.bucket_of(shadows[k].hi(axis)); b <= last; ++b)
        filed_[next[b]++] = uint32_t(k);
  }
}

bool CellVolumeIndex::contains(const World& world, uint32_t cell_index, const glm::dvec3& p_world) const {
  assert(cell_index < world.cells.size() && cells_.size() == world.cells.size());
  const Cell& cell = world.cells[cell_index];
  const CellEntry& entry = cells_[cell_index];
  assert(entry.triangles == cell.volume_triangles_cell.size() / 3);
  glm::dvec3 p;
  if (const std::optional<bool> decided = box_decides(cell, p_world, p)) return *decided;
  // volume_winding_by_ray, meeting only the triangles whose widened (u, v) bounds hold (pu, pv)
  // and that reach past p in x: every other one is a Miss there too, and the signed count does
  // not depend on the order.
  const ContainmentRay r = containment_ray(cell, p);
  const double behind = r.p.x - r.margin_x;  // the step's own first test: x_hi < behind is a Miss
  const auto& t = cell.volume_triangles_cell;
  const Shadow* shadows = shadows_.data() + entry.first_shadow;
  int crossings = 0;
  bool unambiguous = true;
  // Whether to go on after shadows[k]; a NaN anywhere fails the comparisons, so the step decides.
  auto meet = [&](size_t k) {
    const Shadow& s = shadows[k];
    if (entry.sorted && s.x_hi < behind) return false;  // so are all after it
    if (r.pu < s.u_lo || r.pu > s.u_hi || r.pv < s.v_lo || r.pv > s.v_hi) return true;
    const size_t i = 3 * size_t(s.triangle);
    unambiguous = count_step(ray_meets_triangle(r, t[i], t[i + 1], t[i + 2]), crossings);
    return unambiguous;
  };
  const double x = entry.axis == 0 ? r.pu : r.pv;
  if (entry.buckets > 0 && x >= entry.min && x <= entry.max) {
    const size_t* begin = bucket_begin_.data() + entry.first_bucket;
    const size_t b = entry.bucket_of(x);
    for (size_t i = begin[b]; i < begin[b + 1] && meet(filed_[i]); ++i) {}
  } else {  // no grid, or (pu, pv) outside every triangle's bounds (or NaN): all of them
    for (size_t k = 0; k < entry.triangles && meet(k); ++k) {}
  }
  if (unambiguous) return crossings != 0;
  return std::abs(volume_winding_exact(cell, p)) > 0.5;
}

}  // namespace lintel
