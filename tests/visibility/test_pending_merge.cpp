// Merged clip windows (pending_merge.h): the hull of two lattice polygons, and the merge of a
// pop's pending polygons, which must keep every input polygon inside some window.
#include "monotone_chain.h"
#include "pending_merge.h"

#include <lintel/ndc_snap.h>
#include <lintel/portal_clip.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace lintel::detail {
namespace {

std::vector<glm::vec2> snapped(const std::vector<glm::dvec2>& poly) {
  SnapScratch scratch;
  std::vector<glm::vec2> out(kMaxRegionPolygonVertices);
  out.resize(snap_polygon_conservative(poly, 1024, out, scratch));
  return out;
}

std::vector<glm::vec2> hull(const std::vector<glm::vec2>& a, const std::vector<glm::vec2>& b) {
  std::vector<glm::vec2> out(kMaxRegionPolygonVertices);
  std::vector<glm::dvec2> scratch(a.size() + b.size() + 1);
  out.resize(convex_hull_of_two(a, b, out, scratch));
  return out;
}

// The pending arrays of one pop, filled from `polys`; merged; the windows returned.
std::vector<std::vector<glm::vec2>> merged_windows(const std::vector<std::vector<glm::vec2>>& polys) {
  std::vector<glm::vec2> vertices(kMaxRegionPolygonsLimit * kMaxRegionPolygonVertices);
  std::vector<uint32_t> counts(kMaxRegionPolygonsLimit);
  std::vector<NdcRect> rects(kMaxRegionPolygonsLimit);
  for (size_t i = 0; i < polys.size(); ++i) {
    std::copy(polys[i].begin(), polys[i].end(), vertices.begin() + std::ptrdiff_t(i * kMaxRegionPolygonVertices));
    counts[i] = uint32_t(polys[i].size());
    rects[i] = bounds_of(polys[i]);
  }
  const uint32_t n = merge_pending_windows(vertices, counts, rects, uint32_t(polys.size()));
  std::vector<std::vector<glm::vec2>> out;
  for (uint32_t i = 0; i < n; ++i) {
    const auto first = vertices.begin() + std::ptrdiff_t(i * kMaxRegionPolygonVertices);
    out.emplace_back(first, first + counts[i]);
    EXPECT_EQ(rects[i], bounds_of(out.back())) << "window " << i << ": its rect is not its bounds";
  }
  return out;
}

TEST(PendingMerge, HullOfTwoAdjacentRectsIsTheirUnion) {
  const auto left = snapped({{-0.5, -0.25}, {0.0, -0.25}, {0.0, 0.5}, {-0.5, 0.5}});
  const auto right = snapped({{0.0, -0.25}, {0.5, -0.25}, {0.5, 0.5}, {0.0, 0.5}});
  const std::vector<glm::vec2> whole = {{-0.5f, -0.25f}, {0.5f, -0.25f}, {0.5f, 0.5f}, {-0.5f, 0.5f}};
  EXPECT_EQ(hull(left, right), whole);  // counter-clockwise from the smallest vertex, no collinear ones
  EXPECT_EQ(hull(right, left), whole);
  const auto windows = merged_windows({left, right});
  ASSERT_EQ(windows.size(), 1u);
  EXPECT_EQ(windows[0], whole);
}

TEST(PendingMerge, PolygonsApartOrLooseTogetherStaySeparate) {
  // Apart by a gap: never merged, whatever the areas.
  const auto a = snapped({{-0.9, -0.9}, {-0.5, -0.9}, {-0.5, -0.5}, {-0.9, -0.5}});
  const auto b = snapped({{0.5, 0.5}, {0.9, 0.5}, {0.9, 0.9}, {0.5, 0.9}});
  EXPECT_EQ(merged_windows({a, b}).size(), 2u);
  // Two thin slivers crossing like an X: their rects overlap, their hull is far larger than both.
  const auto c = snapped({{-0.8, -0.8}, {-0.7, -0.8}, {0.8, 0.7}, {0.7, 0.8}});
  const auto d = snapped({{0.7, -0.8}, {0.8, -0.7}, {-0.7, 0.8}, {-0.8, 0.7}});
  EXPECT_EQ(merged_windows({c, d}).size(), 2u);
}

TEST(PendingMerge, APolygonInsideAnotherMergesIntoIt) {
  const auto outer = snapped({{-0.6, -0.4}, {0.5, -0.5}, {0.2, 0.7}});
  const auto inner = snapped({{-0.1, -0.1}, {0.1, -0.1}, {0.0, 0.1}});
  const auto windows = merged_windows({inner, outer});
  ASSERT_EQ(windows.size(), 1u);
  EXPECT_EQ(windows[0], outer);
}

// Property (what makes the merged flood conservative): after merging, every vertex of every
// input polygon lies (closed) inside some window, so each input polygon does (the windows are
// convex); every window is a convex counter-clockwise polygon of at most
// kMaxRegionPolygonVertices vertices whose rect is its bounds; there are no more windows than
// inputs. Inputs: a random convex polygon cut into 2-5 vertical strips, each strip snapped (the
// pieces of one portal seen through neighbouring portals), plus random stray triangles.
TEST(PendingMerge, EveryPendingPolygonStaysInsideAWindow) {
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  size_t merges = 0, trials = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<glm::dvec2> quad = {{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}};
    std::vector<std::vector<glm::vec2>> polys;
    const int strips = 2 + int(rng() % 4);
    std::vector<double> cuts = {-1.0, 1.0};
    for (int s = 1; s < strips; ++s) cuts.push_back(u(rng));
    std::sort(cuts.begin(), cuts.end());
    // The quad's hull, counter-clockwise (random points may not be convex or may wind clockwise).
    std::vector<glm::vec2> qf(quad.begin(), quad.end());
    const auto qh = hull(qf, {qf[0], qf[1], qf[2]});
    if (qh.size() < 3) continue;
    const std::vector<glm::dvec2> subject(qh.begin(), qh.end());
    for (size_t s = 0; s + 1 < cuts.size() && polys.size() < 6; ++s) {
      const std::vector<glm::vec2> strip = {
          {float(cuts[s]), -1.0f}, {float(cuts[s + 1]), -1.0f}, {float(cuts[s + 1]), 1.0f}, {float(cuts[s]), 1.0f}};
      std::vector<glm::dvec2> piece(subject.size() + strip.size()), scratch(piece.size());
      piece.resize(clip_convex_by_convex(subject, strip, piece, scratch));
      if (piece.size() < 3 || twice_signed_area(piece) <= 1e-9) continue;
      polys.push_back(snapped(piece));
    }
    const int strays = int(rng() % 3);
    for (int s = 0; s < strays; ++s) {
      const glm::dvec2 c(u(rng), u(rng));
      polys.push_back(snapped({c, c + glm::dvec2(0.2, 0.01), c + glm::dvec2(0.05, 0.15)}));
    }
    polys.erase(std::remove_if(polys.begin(), polys.end(), [](const auto& p) { return p.size() < 3; }), polys.end());
    if (polys.size() < 2) continue;
    ++trials;
    const auto windows = merged_windows(polys);
    ASSERT_LE(windows.size(), polys.size());
    merges += polys.size() - windows.size();
    for (const auto& w : windows) {
      ASSERT_GE(w.size(), 3u);
      ASSERT_LE(w.size(), kMaxRegionPolygonVertices);
      ASSERT_GT(twice_area(w), 0.0);
    }
    for (size_t i = 0; i < polys.size(); ++i)
      for (const glm::vec2& v : polys[i]) {
        const bool inside = std::any_of(windows.begin(), windows.end(),
                                        [&](const auto& w) { return convex_contains_point(w, glm::dvec2(v)); });
        ASSERT_TRUE(inside) << "trial " << trial << ": a vertex of pending polygon " << i << " is in no window";
      }
  }
  EXPECT_GT(trials, 2000u);
  EXPECT_GT(merges, trials);  // strips of one polygon merge: the merge path ran, not only the no-op
}

// Property: convex_hull_of_two, which feeds the monotone chain the two polygons' rising and falling
// chains merged instead of sorting all their points, returns exactly (vertex for vertex) what
// Andrew's chain over all the points sorted returns, for canonical polygons (as snapped) and for
// the same polygons started at another vertex (not canonical: the sorting path). Inputs: snapped
// random triangles and quads on a coarse lattice (16 cells: many shared, repeated and collinear
// vertices) and on the default one, and pairs of neighbouring strips of one polygon.
TEST(PendingMerge, HullByChainsEqualsHullOfAllPointsSorted) {
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> u(-1.1, 1.1);
  auto random_snapped = [&](uint32_t lattice) {
    std::vector<glm::dvec2> pts;
    const int n = 3 + int(rng() % 3);
    for (int i = 0; i < n; ++i) pts.push_back({u(rng), u(rng)});
    std::vector<glm::vec2> f(pts.begin(), pts.end());
    const auto h = hull(f, {f[0], f[1], f[2]});  // convex, counter-clockwise
    if (h.size() < 3) return std::vector<glm::vec2>{};
    SnapScratch scratch;
    std::vector<glm::vec2> out(kMaxRegionPolygonVertices);
    out.resize(snap_polygon_conservative(std::vector<glm::dvec2>(h.begin(), h.end()), lattice, out, scratch));
    return out;
  };
  auto reference = [](const std::vector<glm::vec2>& a, const std::vector<glm::vec2>& b) {
    std::vector<glm::vec2> all(a);
    all.insert(all.end(), b.begin(), b.end());
    std::sort(all.begin(), all.end(),
              [](const glm::vec2& p, const glm::vec2& q) { return p.x != q.x ? p.x < q.x : p.y < q.y; });
    std::vector<glm::dvec2> sorted(all.begin(), all.end()), h(sorted.size() + 1);
    const uint32_t k = monotone_chain_sorted(sorted, h);
    return k > kMaxRegionPolygonVertices ? std::vector<glm::vec2>{} : std::vector<glm::vec2>(h.begin(), h.begin() + k);
  };
  size_t compared = 0, shared_vertices = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const uint32_t lattice = trial % 2 ? 16 : 1024;
    const auto a = random_snapped(lattice), b = random_snapped(lattice);
    if (a.size() < 3 || b.size() < 3) continue;
    ++compared;
    for (const glm::vec2& v : a) shared_vertices += std::count(b.begin(), b.end(), v);
    const auto expected = reference(a, b);
    ASSERT_EQ(hull(a, b), expected) << "trial " << trial;
    ASSERT_EQ(hull(b, a), expected) << "trial " << trial;
    std::vector<glm::vec2> rotated(a);
    std::rotate(rotated.begin(), rotated.begin() + 1, rotated.end());
    ASSERT_EQ(hull(rotated, b), expected) << "trial " << trial << " (not canonical)";
  }
  EXPECT_GT(compared, 15000u);
  EXPECT_GT(shared_vertices, 1000u);  // the coarse lattice made repeated points, as neighbouring pieces do
}

}  // namespace
}  // namespace lintel::detail
