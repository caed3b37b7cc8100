// Conservative lattice snapping with a canonical convex hull (Andrew's monotone chain, 1979).
// Learns from: Descent / Tomb Raider portal renderers (integer screen rects: finitely many, so a
// flood that only lets them grow must stop) and from the Lintel lessons, where exact-match dedup of
// float polygons never matched after a round through non-identity cell transforms.
#include <lintel/ndc_snap.h>

#include "monotone_chain.h"
#include "ndc_snap_testing.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace lintel {
namespace {

const glm::vec2 kScreen[4] = {{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}};

// Convex hull of `points` (sorted in place), counter-clockwise from the lexicographically smallest
// point, collinear and repeated points dropped. `hull` needs points.size() + 1 entries.
// Exact when the points are small integers (lattice mode).
uint32_t monotone_chain(std::span<glm::dvec2> points, std::span<glm::dvec2> hull) {
  std::sort(points.begin(), points.end(),
            [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  return detail::monotone_chain_sorted(points, hull);
}

// Outward float rounding plus one extra ulp (the test-only unsnapped mode).
double float_floor_widened(double x) {
  float f = static_cast<float>(x);
  if (double(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  return std::max(-1.0, double(std::nextafter(f, -std::numeric_limits<float>::infinity())));
}
double float_ceil_widened(double x) {
  float f = static_cast<float>(x);
  if (double(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return std::min(1.0, double(std::nextafter(f, std::numeric_limits<float>::infinity())));
}

int64_t lattice_cross(const LatticePoint& o, const LatticePoint& a, const LatticePoint& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);  // |terms| < 2^44: exact
}

// Andrew's monotone chain (the integer twin of monotone_chain: the same hull, since both are exact
// here) over lattice columns, x ascending: column i is the points (x_i, low_i.y) and, when higher,
// (x_i, high_i.y); `points` counts them. The chain over all of them, sorted by (x, y), pushes a
// column's high point on the lower hull right after its low point (a left turn) and pops it at the
// next point (a right turn), leaving the stack as it was; the upper pass does the same with low
// points. So the lower pass takes only the low points (and the last column's high point, where
// the lower hull ends) and the upper pass only the high ones (and the first column's low point):
// the same steps otherwise, hence the same hull, with half the points.
uint32_t lattice_column_hull(const LatticePoint* low, const LatticePoint* high, uint32_t columns, uint32_t points,
                             LatticePoint* hull) {
  if (points < 3) return 0;
  size_t k = 0;
  auto push = [&](const LatticePoint& p, size_t floor) {
    while (k >= floor && lattice_cross(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  };
  for (uint32_t i = 0; i < columns; ++i) push(low[i], 2);
  if (high[columns - 1].y != low[columns - 1].y) push(high[columns - 1], 2);
  const size_t lower = k + 1;
  for (uint32_t i = columns - 1; i-- > 0;) push(high[i], lower);
  if (high[0].y != low[0].y) push(low[0], lower);
  // The last point repeats the first.
  return k >= 4 ? static_cast<uint32_t>(k - 1) : 0;
}

// The lattice path of snap_polygon_conservative, in integers. Same output as the double path
// would give, bit for bit (NdcSnap.IntegerLatticePathMatchesTheDoubleReference): both return the
// exact hull of the same corners, and a hull's canonical vertex list is unique.
uint32_t snap_on_lattice(std::span<const glm::dvec2> poly, uint32_t lattice_cells, std::span<glm::vec2> out,
                         SnapScratch& scratch, NdcRect* bounds) {
  const double half_cells = 0.5 * double(lattice_cells);
  int64_t lo_y = std::numeric_limits<int64_t>::max(), hi_x = std::numeric_limits<int64_t>::min(), hi_y = hi_x;
  const double cells_d = double(lattice_cells);
  LatticeBox* box = scratch.boxes.data();
  uint32_t n = 0;
  for (const glm::dvec2& v_raw : poly) {
    // floor(u + tol) and ceil(u - tol) clamped to [0, cells], as the double path computes them:
    // u + tol >= 0 here, where truncation is floor; ceil is truncation plus one when it fell short.
    auto lattice_lo = [&](double c) {
      const double u = (std::min(std::max(c, -1.0), 1.0) + 1.0) * half_cells + kSnapToleranceCells;
      return int64_t(std::min(double(int64_t(u)), cells_d));
    };
    auto lattice_hi = [&](double c) {
      const double u = (std::min(std::max(c, -1.0), 1.0) + 1.0) * half_cells - kSnapToleranceCells;
      int64_t t = int64_t(u);
      if (double(t) < u) ++t;
      return std::min(std::max(t, int64_t{0}), int64_t(lattice_cells));
    };
    const LatticeBox b{lattice_lo(v_raw.x), lattice_lo(v_raw.y), lattice_hi(v_raw.x), lattice_hi(v_raw.y)};
    assert(b.x0 <= b.x1 && b.y0 <= b.y1 && b.x1 - b.x0 <= 1);
    lo_y = std::min(lo_y, b.y0);
    hi_x = std::max(hi_x, b.x1);
    hi_y = std::max(hi_y, b.y1);
    // Kept sorted by x0 (insertion: a convex polygon's vertices are two runs monotone in x).
    uint32_t j = n++;
    for (; j > 0 && box[j - 1].x0 > b.x0; --j) box[j] = box[j - 1];
    box[j] = b;
  }
  // The hull of the boxes' corners needs, per lattice column x that some corner lies on, only the
  // lowest and the highest corner there: any other lies between them on a vertical segment, inside
  // the hull or collinear with its edge (dropped either way). A box spans one column (x0 == x1,
  // the vertex on a lattice line) or two (x1 == x0 + 1), so the columns are the merge of the
  // boxes' x0 (sorted) and the x1 of the two-column boxes (sorted too: x0 + 1), in one pass. The
  // columns come out sorted by x, which is what the monotone chain needs; no sort of corners.
  LatticePoint* low = scratch.lattice_points.data();
  LatticePoint* high = low + scratch.lattice_points.size() / 2;
  uint32_t m = 0, points = 0;
  // One pass over the boxes in x0 order: column x takes the boxes starting there, plus what the
  // two-column boxes of column x - 1 carried over to it (a carried column with no box of its own
  // comes first).
  constexpr int64_t kNone = std::numeric_limits<int64_t>::max();
  int64_t carry_x = kNone, carry_lo = 0, carry_hi = 0;
  auto emit = [&](int64_t x, int64_t y_lo, int64_t y_hi) {
    low[m] = {x, y_lo};
    high[m++] = {x, y_hi};
    points += y_hi != y_lo ? 2 : 1;
  };
  for (uint32_t i = 0; i < n;) {
    const int64_t x = box[i].x0;
    int64_t y_lo = std::numeric_limits<int64_t>::max(), y_hi = std::numeric_limits<int64_t>::min();
    if (carry_x != kNone) {
      if (carry_x < x) {
        emit(carry_x, carry_lo, carry_hi);
      } else {  // carry_x == x: the box starts where the carried column is
        y_lo = carry_lo;
        y_hi = carry_hi;
      }
      carry_x = kNone;
    }
    int64_t next_lo = std::numeric_limits<int64_t>::max(), next_hi = std::numeric_limits<int64_t>::min();
    for (; i < n && box[i].x0 == x; ++i) {
      y_lo = std::min(y_lo, box[i].y0);
      y_hi = std::max(y_hi, box[i].y1);
      if (box[i].x1 != x) {
        next_lo = std::min(next_lo, box[i].y0);
        next_hi = std::max(next_hi, box[i].y1);
      }
    }
    emit(x, y_lo, y_hi);
    if (next_lo != std::numeric_limits<int64_t>::max()) carry_x = x + 1, carry_lo = next_lo, carry_hi = next_hi;
  }
  if (carry_x != kNone) emit(carry_x, carry_lo, carry_hi);
  const uint32_t count = lattice_column_hull(low, high, m, points, scratch.lattice_hull.data());

  // half_cells is a power of two: multiplying by its inverse is exact, the same as dividing.
  const double inv_half_cells = 1.0 / half_cells;
  auto to_ndc = [inv_half_cells](int64_t x, int64_t y) {
    return glm::vec2(float(double(x) * inv_half_cells - 1.0), float(double(y) * inv_half_cells - 1.0));
  };
  if (count < 3 || count > kMaxRegionPolygonVertices) {
    // Too many vertices, or all corners on one line (a sliver thinner than the snap tolerance):
    // the bounding rect, at least one cell wide, is the conservative answer.
    int64_t lo_x = box[0].x0;  // the boxes are sorted by x0
    auto widen = [lattice_cells](int64_t& lo, int64_t& hi) {
      if (lo < hi) return;
      if (hi < int64_t(lattice_cells))
        hi += 1;
      else
        lo -= 1;
    };
    widen(lo_x, hi_x);
    widen(lo_y, hi_y);
    out[0] = to_ndc(lo_x, lo_y);
    out[1] = to_ndc(hi_x, lo_y);
    out[2] = to_ndc(hi_x, hi_y);
    out[3] = to_ndc(lo_x, hi_y);
    if (bounds) *bounds = NdcRect{out[0], out[2]};
    return 4;
  }
  for (uint32_t i = 0; i < count; ++i) out[i] = to_ndc(scratch.lattice_hull[i].x, scratch.lattice_hull[i].y);
  // The hull's bounds are the corners' (an extreme corner is a hull vertex, or lies on a hull
  // edge between two vertices of the same extreme coordinate).
  if (bounds) *bounds = NdcRect{to_ndc(box[0].x0, lo_y), to_ndc(hi_x, hi_y)};
  return count;
}

}  // namespace

bool valid_snap_lattice(uint32_t cells) {
  return cells >= 2 && cells <= kMaxSnapLatticeCells && (cells & (cells - 1)) == 0;
}

namespace {

// Clips to the screen first when needed: clamping vertices of a polygon that sticks out would not
// contain its on-screen part. Polygons from the traversal are inside up to rounding noise.
// Empty span when nothing is left on the screen.
std::span<const glm::dvec2> on_screen_part(std::span<const glm::dvec2> poly, SnapScratch& scratch) {
  constexpr double kOutside = 1.0 + 1e-9;
  bool sticks_out = false;
  for (const glm::dvec2& v : poly)
    if (!(std::abs(v.x) <= kOutside && std::abs(v.y) <= kOutside)) sticks_out = true;
  if (!sticks_out) return poly;
  // The subject's orientation does not matter to Sutherland-Hodgman, only the window's.
  const uint32_t n = clip_convex_by_convex(poly, kScreen, scratch.screen_a, scratch.screen_b);
  return n < 3 ? std::span<const glm::dvec2>() : std::span<const glm::dvec2>(scratch.screen_a.data(), n);
}

// The snap as first written: all four corners of every vertex's cell as doubles, one sort of
// pairs, the hull in double (exact on the lattice, where the integer path is used instead).
uint32_t snap_by_double_hull(std::span<const glm::dvec2> poly, uint32_t lattice_cells, std::span<glm::vec2> out,
                             SnapScratch& scratch) {
  // Corners of the lattice cell of each vertex (in lattice units in lattice mode: exact integers).
  const bool lattice = lattice_cells != 0;
  const double half_cells = 0.5 * double(lattice_cells);
  uint32_t corner_count = 0;
  glm::dvec2 lo_box(std::numeric_limits<double>::infinity()), hi_box(-std::numeric_limits<double>::infinity());
  for (const glm::dvec2& v_raw : poly) {
    const glm::dvec2 v = glm::clamp(v_raw, glm::dvec2(-1.0), glm::dvec2(1.0));
    glm::dvec2 lo, hi;
    if (lattice) {
      const glm::dvec2 u = (v + 1.0) * half_cells;
      lo = glm::clamp(glm::floor(u + kSnapToleranceCells), glm::dvec2(0.0), glm::dvec2(lattice_cells));
      hi = glm::clamp(glm::ceil(u - kSnapToleranceCells), glm::dvec2(0.0), glm::dvec2(lattice_cells));
    } else {
      lo = glm::dvec2(float_floor_widened(v.x), float_floor_widened(v.y));
      hi = glm::dvec2(float_ceil_widened(v.x), float_ceil_widened(v.y));
    }
    assert(lo.x <= hi.x && lo.y <= hi.y);
    lo_box = glm::min(lo_box, lo);
    hi_box = glm::max(hi_box, hi);
    scratch.corners[corner_count++] = {lo.x, lo.y};
    scratch.corners[corner_count++] = {hi.x, lo.y};
    scratch.corners[corner_count++] = {hi.x, hi.y};
    scratch.corners[corner_count++] = {lo.x, hi.y};
  }
  uint32_t count = monotone_chain(std::span<glm::dvec2>(scratch.corners.data(), corner_count), scratch.hull);

  auto to_ndc = [&](const glm::dvec2& p) {
    return lattice ? glm::vec2(float(p.x / half_cells - 1.0), float(p.y / half_cells - 1.0)) : glm::vec2(p);
  };
  if (count < 3 || count > kMaxRegionPolygonVertices) {
    // Too many vertices, or all corners on one line (a sliver thinner than the snap tolerance):
    // the bounding rect, at least one cell (one ulp) wide, is the conservative answer.
    for (int axis = 0; axis < 2; ++axis) {
      if (lo_box[axis] < hi_box[axis]) continue;
      const double top = lattice ? double(lattice_cells) : 1.0;
      const bool grow_up = hi_box[axis] < top;
      if (lattice && grow_up)
        hi_box[axis] += 1.0;
      else if (lattice)
        lo_box[axis] -= 1.0;
      else if (grow_up)
        hi_box[axis] = double(std::nextafter(float(hi_box[axis]), 2.0f));
      else
        lo_box[axis] = double(std::nextafter(float(lo_box[axis]), -2.0f));
    }
    out[0] = to_ndc({lo_box.x, lo_box.y});
    out[1] = to_ndc({hi_box.x, lo_box.y});
    out[2] = to_ndc({hi_box.x, hi_box.y});
    out[3] = to_ndc({lo_box.x, hi_box.y});
    return 4;
  }
  for (uint32_t i = 0; i < count; ++i) out[i] = to_ndc(scratch.hull[i]);
  return count;
}

}  // namespace

uint32_t snap_polygon_conservative(std::span<const glm::dvec2> poly_ndc, uint32_t lattice_cells,
                                   std::span<glm::vec2> out, SnapScratch& scratch, NdcRect* bounds) {
  assert(lattice_cells == 0 || valid_snap_lattice(lattice_cells));
  assert(poly_ndc.size() <= kMaxSnapInputVertices && out.size() >= kMaxRegionPolygonVertices);
  if (poly_ndc.size() < 3) return 0;
  const std::span<const glm::dvec2> poly = on_screen_part(poly_ndc, scratch);
  if (poly.size() < 3) return 0;
  if (lattice_cells != 0) return snap_on_lattice(poly, lattice_cells, out, scratch, bounds);
  const uint32_t n = snap_by_double_hull(poly, 0, out, scratch);
  if (bounds) *bounds = bounds_of(out.first(n));
  return n;
}

namespace detail {

uint32_t snap_polygon_by_double_hull(std::span<const glm::dvec2> poly_ndc, uint32_t lattice_cells,
                                     std::span<glm::vec2> out, SnapScratch& scratch) {
  assert(lattice_cells == 0 || valid_snap_lattice(lattice_cells));
  if (poly_ndc.size() < 3) return 0;
  const std::span<const glm::dvec2> poly = on_screen_part(poly_ndc, scratch);
  return poly.size() < 3 ? 0 : snap_by_double_hull(poly, lattice_cells, out, scratch);
}

}  // namespace detail
}  // namespace lintel
