// Regions on the lattice: dedup of equal / contained polygons, the polygon limit and the rect
// collapse, which must keep everything it was given.
#include "region_lattice.h"

#include <lintel/ndc_snap.h>

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace lintel::detail {
namespace {

std::vector<glm::vec2> snapped(const std::vector<glm::dvec2>& poly, uint32_t cells = 1024) {
  SnapScratch scratch;
  std::vector<glm::vec2> out(kMaxRegionPolygonVertices);
  out.resize(snap_polygon_conservative(poly, cells, out, scratch));
  return out;
}

std::vector<glm::vec2> rect_poly(double x0, double y0, double x1, double y1) {
  return snapped({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
}

bool region_contains(const RegionLattice& r, uint32_t cell, const glm::dvec2& p) {
  for (uint32_t i = 0; i < r.polygon_count(cell); ++i)
    if (convex_contains_point(r.polygon(cell, i), p)) return true;
  return false;
}

TEST(RegionLattice, EqualPolygonIsSkipped) {
  RegionLattice r;
  r.prepare(3, 4);
  const auto a = snapped({{-0.3, -0.2}, {0.4, -0.1}, {0.1, 0.5}});
  EXPECT_EQ(r.add(1, a), RegionAdd::Added);
  EXPECT_EQ(r.add(1, a), RegionAdd::Skipped);
  // The same polygon arriving with a different start vertex and sub-tolerance noise snaps equal.
  const auto b = snapped({{0.1 + 1e-13, 0.5}, {-0.3, -0.2 - 1e-13}, {0.4, -0.1}});
  EXPECT_EQ(b, a);
  EXPECT_EQ(r.add(1, b), RegionAdd::Skipped);
  EXPECT_EQ(r.polygon_count(1), 1u);
}

TEST(RegionLattice, ContainedPolygonIsSkippedAndContainingOneReplaces) {
  RegionLattice r;
  r.prepare(2, 4);
  EXPECT_EQ(r.add(0, rect_poly(-0.5, -0.5, 0.5, 0.5)), RegionAdd::Added);
  EXPECT_EQ(r.add(0, rect_poly(-0.25, -0.25, 0.25, 0.25)), RegionAdd::Skipped);
  EXPECT_EQ(r.add(0, rect_poly(0.6, 0.6, 0.8, 0.8)), RegionAdd::Added);
  EXPECT_EQ(r.polygon_count(0), 2u);
  // A polygon covering both replaces them: one polygon left, union unchanged or larger.
  EXPECT_EQ(r.add(0, rect_poly(-0.75, -0.75, 0.9, 0.9)), RegionAdd::Added);
  EXPECT_EQ(r.polygon_count(0), 1u);
  EXPECT_TRUE(r.pending(0, 0));
}

// Property (overflow is conservative): adding random polygons to a region limited to P polygons,
// every point of every polygon ever added stays inside the region, and after the collapse the
// region is one rect.
TEST(RegionLattice, OverflowCollapsesToASupersetRect) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-0.9, 0.9);
  for (uint32_t limit : {1u, 2u, 3u, 8u}) {
    RegionLattice r;
    r.prepare(1, limit);
    std::vector<std::vector<glm::vec2>> added;
    bool collapsed = false;
    for (int i = 0; i < 20; ++i) {
      const double x = u(rng), y = u(rng);
      const auto p = snapped({{x, y}, {x + 0.05, y}, {x + 0.02, y + 0.04}});
      const RegionAdd result = r.add(0, p);
      collapsed = collapsed || result == RegionAdd::Collapsed;
      added.push_back(p);
      for (const auto& q : added)
        for (const glm::vec2& v : q) EXPECT_TRUE(region_contains(r, 0, glm::dvec2(v)));
      EXPECT_LE(r.polygon_count(0), limit);
    }
    EXPECT_TRUE(collapsed);
    EXPECT_TRUE(r.is_rect(0));
    EXPECT_EQ(r.polygon_count(0), 1u);
  }
}

// Property (cap collapse keeps a superset and never drops what it was about to add): the new
// polygon is added, then the region collapses; every point of all polygons, the new one included,
// is inside the rect, and later adds only grow the rect.
TEST(RegionLattice, CapCollapseKeepsEverythingIncludingTheNewPolygon) {
  RegionLattice r;
  r.prepare(1, 8);
  const auto a = rect_poly(-0.5, -0.5, -0.2, -0.2);
  const auto b = rect_poly(0.1, 0.3, 0.4, 0.6);
  const auto incoming = snapped({{0.7, -0.8}, {0.9, -0.8}, {0.8, -0.6}});
  r.add(0, a);
  r.add(0, b);
  r.add(0, incoming);  // what the traversal does before deciding to collapse
  r.collapse_to_rect(0);
  ASSERT_TRUE(r.is_rect(0));
  for (const auto* p : {&a, &b, &incoming})
    for (const glm::vec2& v : *p) EXPECT_TRUE(region_contains(r, 0, glm::dvec2(v)));
  const NdcRect before = r.rect(0);
  EXPECT_TRUE(r.pending(0, 0));
  r.clear_pending(0, 0);
  EXPECT_EQ(r.add(0, rect_poly(-0.4, -0.4, 0.3, 0.3)), RegionAdd::Skipped);  // inside the rect
  EXPECT_FALSE(r.pending(0, 0));
  EXPECT_EQ(r.add(0, rect_poly(-0.95, 0.0, -0.9, 0.1)), RegionAdd::RectGrew);
  EXPECT_TRUE(r.rect(0).contains(before));
  EXPECT_TRUE(r.pending(0, 0));
  // Still on the lattice.
  for (const glm::vec2& v : r.polygon(0, 0)) {
    const double k = (double(v.x) + 1.0) * 512.0;
    EXPECT_EQ(k, std::floor(k));
  }
}

TEST(RegionLattice, ResetForgetsOnlyTouchedCells) {
  RegionLattice r;
  r.prepare(5, 2);
  r.set_full_screen(2);
  r.add(4, rect_poly(0, 0, 0.5, 0.5));
  EXPECT_EQ(r.touched().size(), 2u);
  EXPECT_EQ(r.add(2, rect_poly(0, 0, 0.5, 0.5)), RegionAdd::Skipped);  // the screen contains all
  r.reset();
  EXPECT_TRUE(r.touched().empty());
  for (uint32_t c = 0; c < 5; ++c) EXPECT_FALSE(r.has_region(c));
}

// The vertex arena is handed out per write and compacted when full (rare in a real build: more
// polygons written in one build than the lattice has slots). Cells 0 and 1 keep three triangles
// each and cell 2 one, all written first (low in the arena, interleaved: not in the order the
// cells were touched), while cell 3 takes a disjoint triangle at every step, kept as polygons up
// to the limit, then as a growing rect rewritten at each step, which fills the arena again and
// again. Every region must read back exactly what a model of it holds after every step, across
// the compactions, and again after a reset.
TEST(RegionLattice, ArenaCompactionKeepsEveryPolygon) {
  constexpr uint32_t kCells = 4, kLimit = 3, kSteps = 250;
  for (uint32_t first_rect_cell_start = 0; first_rect_cell_start < 4; ++first_rect_cell_start) {
    RegionLattice r;
    r.prepare(kCells, kLimit);  // the arena holds (4 x 3 + 1) x 32 vertices
    for (int round = 0; round < 2; ++round) {
      std::vector<std::vector<glm::vec2>> tris[kCells];
      for (uint32_t k = 0; k < kSteps; ++k)
        for (uint32_t c = 0; c < kCells; ++c) {
          const bool takes = c == 3 ? k >= first_rect_cell_start : c == 2 ? k == 0 : k < kLimit;
          if (!takes) continue;
          // Apart while they are polygons; then each reaches a little further right (the rect grows).
          const double n = double(tris[c].size());
          const double x = -0.95 + (n <= kLimit ? 0.03 * n : 0.03 * kLimit + 0.006 * (n - kLimit));
          const double y = -0.9 + 0.45 * c + 0.01 * round;
          tris[c].push_back(snapped({{x, y}, {x + 0.02, y}, {x, y + 0.2}}));
          const RegionAdd got = r.add(c, tris[c].back());
          ASSERT_EQ(got, tris[c].size() <= kLimit       ? RegionAdd::Added
                         : tris[c].size() == kLimit + 1 ? RegionAdd::Collapsed
                                                        : RegionAdd::RectGrew);
          for (uint32_t d = 0; d < kCells; ++d) {
            std::vector<std::vector<glm::vec2>> want = tris[d];
            if (want.size() > kLimit) {
              NdcRect box;
              for (const auto& t : want) box.extend(bounds_of(t));
              want = {{box.min, {box.max.x, box.min.y}, box.max, {box.min.x, box.max.y}}};
            }
            ASSERT_EQ(r.polygon_count(d), want.size());
            for (uint32_t i = 0; i < want.size(); ++i) {
              const auto poly = r.polygon(d, i);
              ASSERT_EQ(std::vector<glm::vec2>(poly.begin(), poly.end()), want[i])
                  << "cell " << d << " polygon " << i << " after step " << k << " of cell " << c;
            }
          }
        }
      r.reset();
      for (uint32_t c = 0; c < kCells; ++c) EXPECT_FALSE(r.has_region(c));
    }
    EXPECT_GE(r.compactions(), 4u) << "the arena filled up in both rounds";
  }
}

// Property (covers is exact enough to skip work, never visibility): for random regions of random
// lattice polygons (and the same regions collapsed to their rect) and random unsnapped convex
// pieces, covers() is true only when every vertex of the piece -- hence, the polygons being
// convex, every point of it -- lies in one polygon of the region; and a piece that is a shrunken
// copy of a region polygon is always covered.
TEST(RegionLattice, CoversOnlyWhatOnePolygonHolds) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.95, 0.95);
  auto random_triangle = [&](double size) {
    const glm::dvec2 c(u(rng), u(rng));
    std::vector<glm::dvec2> t;
    for (int k = 0; k < 3; ++k) t.push_back(c + size * glm::dvec2(u(rng), u(rng)));
    return t;
  };
  int covered = 0, not_covered = 0;
  for (int trial = 0; trial < 400; ++trial) {
    RegionLattice r;
    r.prepare(1, 8);
    for (int k = 0; k < 3; ++k) {
      const auto poly = snapped(random_triangle(0.4));
      if (poly.size() >= 3) r.add(0, poly);
    }
    if (!r.has_region(0)) continue;
    for (int k = 0; k < 50; ++k) {
      const auto piece = random_triangle(0.06);
      bool inside_one = false;
      for (uint32_t i = 0; i < r.polygon_count(0) && !inside_one; ++i) {
        bool all = true;
        for (const glm::dvec2& v : piece) all = all && convex_contains_point(r.polygon(0, i), v);
        inside_one = all;
      }
      const bool covers = r.covers(0, piece);
      if (covers) {
        EXPECT_TRUE(inside_one) << "trial " << trial;
      }
      (covers ? covered : not_covered)++;
    }
    // A region polygon shrunk towards its centroid is covered.
    const auto poly = r.polygon(0, 0);
    glm::dvec2 centroid(0.0);
    for (const glm::vec2& v : poly) centroid += glm::dvec2(v) / double(poly.size());
    std::vector<glm::dvec2> shrunk;
    for (const glm::vec2& v : poly) shrunk.push_back(centroid + 0.9 * (glm::dvec2(v) - centroid));
    EXPECT_TRUE(r.covers(0, shrunk)) << "trial " << trial;
    // Collapsed to its rect, the region covers whatever lies in the rect and nothing beyond it.
    const NdcRect rect = r.rect(0);
    r.collapse_to_rect(0);
    const std::vector<glm::dvec2> inside_rect = {
        {rect.min.x, rect.min.y}, {rect.max.x, rect.min.y}, {rect.max.x, rect.max.y}};
    EXPECT_TRUE(r.covers(0, inside_rect));
    const std::vector<glm::dvec2> beyond = {
        {rect.min.x, rect.min.y}, {rect.max.x + 1e-6, rect.min.y}, {rect.max.x, rect.max.y}};
    EXPECT_FALSE(r.covers(0, beyond));
  }
  EXPECT_GT(covered, 100);  // both answers occur: the property is not vacuous
  EXPECT_GT(not_covered, 100);
}

}  // namespace
}  // namespace lintel::detail
