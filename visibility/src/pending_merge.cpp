// Merged clip windows: see pending_merge.h. The monotone chain (monotone_chain.h) over the
// vertices of two convex polygons (at most 2 x 32 points; k <= 16 pending polygons, so the pair
// loop is small).
#include "pending_merge.h"

#include "monotone_chain.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <limits>

namespace lintel::detail {
namespace {

bool lex_less(const glm::vec2& p, const glm::vec2& q) { return p.x != q.x ? p.x < q.x : p.y < q.y; }

// Writes `poly`'s vertices (convex, either winding) to `out` in (x, y) order: from its smallest
// vertex both ways round rise to its largest, so the two walks are merged as they go. False (and
// `out` unsorted) when a walk does not rise: not convex to the bit.
bool sorted_vertices(std::span<const glm::vec2> poly, glm::vec2* out) {
  const size_t n = poly.size();
  size_t lo = 0;
  for (size_t i = 1; i < n; ++i)
    if (lex_less(poly[i], poly[lo])) lo = i;
  size_t fwd = lo + 1 == n ? 0 : lo + 1, bwd = lo == 0 ? n - 1 : lo - 1;  // next of each walk
  size_t k = 0;
  out[k++] = poly[lo];
  // The walks meet at the largest vertex; n - 1 vertices remain after the smallest.
  for (size_t left = n - 1; left > 0; --left) {
    const bool take_fwd = !lex_less(poly[bwd], poly[fwd]);
    const glm::vec2& v = take_fwd ? poly[fwd] : poly[bwd];
    if (lex_less(v, out[k - 1])) {  // a walk fell: fall back to sorting
      std::copy(poly.begin(), poly.end(), out);
      return false;
    }
    out[k++] = v;
    if (take_fwd) {
      fwd = fwd + 1 == n ? 0 : fwd + 1;
    } else {
      bwd = bwd == 0 ? n - 1 : bwd - 1;
    }
  }
  return true;
}

// The two chains of a canonical polygon (counter-clockwise from its smallest vertex, as the snap,
// the rect fallback and this file's hulls write them): vertices 0..top rise in (x, y) order to the
// largest, top..n-1 and back to 0 fall. False when `poly` is not of that form to the bit.
bool canonical_chains(std::span<const glm::vec2> poly, size_t& top) {
  const size_t n = poly.size();
  top = 0;
  while (top + 1 < n && lex_less(poly[top], poly[top + 1])) ++top;
  for (size_t i = top; i + 1 < n; ++i)
    if (!lex_less(poly[i + 1], poly[i])) return false;
  return top > 0 && lex_less(poly[0], poly[n - 1]);
}

// Andrew's monotone chain over the union of two canonical polygons, fed chain by chain: the
// lower pass takes both rising chains merged (the union's lower hull has no other vertices: a
// vertex above its own polygon's lower chain is above the union's too), the upper pass both
// falling chains merged (the first, the largest point, repeats the lower hull's last and is popped
// by the next push, as a repeated point is in monotone_chain_sorted). The hull is unique, so the
// output is what the chain over all the points sorted gives, bit for bit, without the sort.
uint32_t hull_of_chains(std::span<const glm::vec2> a, size_t top_a, std::span<const glm::vec2> b, size_t top_b,
                        std::span<glm::vec2> out) {
  // The stack never holds more points than were pushed: at most n + 3 (the tops and the bottoms
  // are in both chains of their polygon).
  std::array<glm::dvec2, 2 * kMaxRegionPolygonVertices + 3> hull;
  assert(a.size() + b.size() <= 2 * kMaxRegionPolygonVertices);
  size_t k = 0;
  auto push = [&](const glm::vec2& p, size_t floor) { hull_push(hull, k, glm::dvec2(p), floor); };
  for (size_t i = 0, j = 0; i <= top_a || j <= top_b;) {  // rising: a[0..top_a], b[0..top_b]
    if (j > top_b || (i <= top_a && !lex_less(b[j], a[i])))
      push(a[i++], 2);
    else
      push(b[j++], 2);
  }
  // Falling: a[top_a..n_a-1] then a[0], likewise b; position `i` of a chain of length m + 1.
  const size_t na = a.size(), nb = b.size();
  auto fall_a = [&](size_t i) { return a[top_a + i == na ? 0 : top_a + i]; };
  auto fall_b = [&](size_t j) { return b[top_b + j == nb ? 0 : top_b + j]; };
  const size_t len_a = na - top_a + 1, len_b = nb - top_b + 1;
  const size_t lower = k + 1;
  for (size_t i = 0, j = 0; i < len_a || j < len_b;) {
    const bool take_a = j >= len_b || (i < len_a && !lex_less(fall_a(i), fall_b(j)));
    push(take_a ? fall_a(i++) : fall_b(j++), lower);
  }
  // The last point repeats the first.
  if (k < 4 || k - 1 > out.size()) return 0;
  for (size_t i = 0; i + 1 < k; ++i) out[i] = glm::vec2(hull[i]);  // input vertices: exact in float
  return static_cast<uint32_t>(k - 1);
}

}  // namespace

double twice_area(std::span<const glm::vec2> poly) {
  double sum = 0.0;
  const size_t n = poly.size();
  for (size_t i = 0; i < n; ++i) {
    const glm::dvec2 a(poly[i]), b(poly[i + 1 == n ? 0 : i + 1]);
    sum += a.x * b.y - a.y * b.x;
  }
  return sum;
}

uint32_t convex_hull_of_two(std::span<const glm::vec2> a, std::span<const glm::vec2> b, std::span<glm::vec2> out,
                            std::span<glm::dvec2> scratch) {
  const size_t n = a.size() + b.size();
  assert(scratch.size() > n && n >= 3 && n <= 2 * kMaxRegionPolygonVertices);
  size_t top_a = 0, top_b = 0;
  if (a.size() >= 3 && b.size() >= 3 && canonical_chains(a, top_a) && canonical_chains(b, top_b)) {
    return hull_of_chains(a, top_a, b, top_b, out);
  }
  std::array<glm::vec2, 2 * kMaxRegionPolygonVertices> both, pts;
  const bool sorted_a = sorted_vertices(a, both.data());
  const bool sorted_b = sorted_vertices(b, both.data() + a.size());
  if (sorted_a && sorted_b) {
    std::merge(both.begin(), both.begin() + std::ptrdiff_t(a.size()), both.begin() + std::ptrdiff_t(a.size()),
               both.begin() + std::ptrdiff_t(n), pts.begin(), lex_less);
  } else {
    std::copy_n(both.begin(), n, pts.begin());
    std::sort(pts.begin(), pts.begin() + std::ptrdiff_t(n), lex_less);
  }
  std::array<glm::dvec2, 2 * kMaxRegionPolygonVertices> sorted;
  for (size_t i = 0; i < n; ++i) sorted[i] = glm::dvec2(pts[i]);
  const size_t k = monotone_chain_sorted(std::span<const glm::dvec2>(sorted.data(), n), scratch);
  if (k < 3 || k > out.size()) return 0;
  for (size_t i = 0; i < k; ++i) out[i] = glm::vec2(scratch[i]);  // input vertices: exact in float
  return static_cast<uint32_t>(k);
}

uint32_t merge_pending_windows(std::span<glm::vec2> vertices, std::span<uint32_t> counts, std::span<NdcRect> rects,
                               uint32_t count) {
  constexpr size_t kStride = kMaxRegionPolygonVertices;
  assert(count <= kMaxRegionPolygonsLimit);
  auto poly = [&](uint32_t i) { return std::span<const glm::vec2>(vertices.data() + i * kStride, counts[i]); };
  std::array<double, kMaxRegionPolygonsLimit> area2;
  for (uint32_t i = 0; i < count; ++i) area2[i] = twice_area(poly(i));
  std::array<glm::vec2, kMaxRegionPolygonVertices> merged;
  std::array<glm::dvec2, 2 * kMaxRegionPolygonVertices + 1> scratch;
  // Windows [0, out) are final candidates; polygon i joins the first window it merges with, and
  // a window that grew is tried against the others again (it may now pass with them).
  uint32_t out = 0;
  for (uint32_t i = 0; i < count; ++i) {
    uint32_t into = out;  // the window `i` is (or grows into)
    if (i != out) {
      std::copy_n(vertices.begin() + i * kStride, counts[i], vertices.begin() + out * kStride);
      counts[out] = counts[i];
      rects[out] = rects[i];
      area2[out] = area2[i];
    }
    ++out;
    for (uint32_t j = 0; j < out; ++j) {
      if (j == into) continue;
      // Polygons apart by a gap are not merged: their hull would add the gap (and this keeps the
      // pairs tried few; pieces through neighbouring portals touch or overlap after the snap).
      if (!rects[j].overlaps(rects[into])) continue;
      const double limit = (1.0 + kMergeSlack) * (area2[j] + area2[into]);
      const uint32_t m = convex_hull_of_two(poly(j), poly(into), merged, scratch);
      if (m == 0) continue;
      const double a = twice_area(std::span<const glm::vec2>(merged.data(), m));
      if (a > limit) continue;
      // The lower slot takes the hull; the higher one is refilled by the last window.
      const uint32_t keep = std::min(j, into), drop = std::max(j, into);
      std::copy_n(merged.begin(), m, vertices.begin() + keep * kStride);
      counts[keep] = m;
      NdcRect both = rects[j];  // the hull's bounds
      both.extend(rects[into]);
      rects[keep] = both;
      area2[keep] = a;
      const uint32_t last = out - 1;
      if (drop != last) {
        std::copy_n(vertices.begin() + last * kStride, counts[last], vertices.begin() + drop * kStride);
        counts[drop] = counts[last];
        rects[drop] = rects[last];
        area2[drop] = area2[last];
      }
      --out;
      into = keep;
      j = std::numeric_limits<uint32_t>::max();  // restart: the grown window against all others
    }
  }
  return out;
}

}  // namespace lintel::detail
