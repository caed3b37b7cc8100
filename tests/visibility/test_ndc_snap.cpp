// Conservative snapping to the NDC lattice and its canonical order.
#include <lintel/clip_region.h>
#include <lintel/ndc_snap.h>

#include "ndc_snap_testing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace lintel {
namespace {

std::vector<glm::dvec2> random_convex(std::mt19937& rng, int n, double radius, glm::dvec2 center) {
  std::uniform_real_distribution<double> u(0.0, 6.283185307179586);
  std::vector<double> angles(n);
  for (double& a : angles) a = u(rng);
  std::sort(angles.begin(), angles.end());
  std::vector<glm::dvec2> poly;
  for (double a : angles) poly.push_back(center + radius * glm::dvec2(std::cos(a), std::sin(a)));
  return poly;
}

std::vector<glm::vec2> snap(const std::vector<glm::dvec2>& poly, uint32_t cells) {
  SnapScratch scratch;
  std::vector<glm::vec2> out(kMaxRegionPolygonVertices);
  const uint32_t n = snap_polygon_conservative(poly, cells, out, scratch);
  out.resize(n);
  return out;
}

double cross(glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// Property (conservative): for random convex polygons, partly off screen or not, of any size
// down to slivers, the snapped polygon contains every on-screen point of the input — checked on
// the input's vertices clamped into the screen when inside it, and on random interior points —
// up to the documented tolerance kSnapToleranceCells cells.
TEST(NdcSnap, SnappedPolygonContainsTheInput) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (uint32_t cells : {2u, 16u, 1024u, 65536u, kMaxSnapLatticeCells}) {
    const double tol = kSnapToleranceCells * 2.0 / cells + 1e-12;
    for (int trial = 0; trial < 400; ++trial) {
      const double radius = std::pow(10.0, -4.0 + 4.5 * (0.5 * u(rng) + 0.5));
      const auto poly = random_convex(rng, 3 + trial % 40, radius, {1.2 * u(rng), 1.2 * u(rng)});
      const auto s = snap(poly, cells);
      if (s.empty()) {  // allowed only when the input misses the screen
        for (const glm::dvec2& v : poly) EXPECT_FALSE(std::abs(v.x) < 1.0 && std::abs(v.y) < 1.0);
        continue;
      }
      ASSERT_GE(s.size(), 3u);
      for (int i = 0; i < 300; ++i) {
        // Random point of the input: a random convex combination of three vertices.
        const glm::dvec2 a = poly[rng() % poly.size()], b = poly[rng() % poly.size()], c = poly[rng() % poly.size()];
        double w0 = std::abs(u(rng)), w1 = std::abs(u(rng)), w2 = std::abs(u(rng));
        const double sum = w0 + w1 + w2 + 1e-300;
        const glm::dvec2 p = (w0 * a + w1 * b + w2 * c) / sum;
        if (std::abs(p.x) > 1.0 || std::abs(p.y) > 1.0) continue;
        EXPECT_TRUE(convex_contains_point(s, p, tol)) << "cells " << cells << " trial " << trial;
      }
      for (const glm::dvec2& v : poly)
        EXPECT_TRUE(!(std::abs(v.x) <= 1.0 && std::abs(v.y) <= 1.0) || convex_contains_point(s, v, tol));
    }
  }
}

// Property (lattice, canonical): output vertices are lattice points inside the screen, strictly
// convex and counter-clockwise, starting at the lexicographically smallest vertex; the result
// does not depend on which vertex the input starts at; snapping it again changes nothing.
// Property (fast path = reference): on every lattice, the integer snap (packed keys, corners of
// degenerate cells dropped, insertion sort, integer hull) returns exactly the polygon the snap as
// first written returns (all corners in double, std::sort, double hull), vertex for vertex and
// bit for bit, for random convex polygons of any size, partly off screen or not, with vertices
// exactly on lattice lines, within the snap tolerance of them, and on the screen border; and the
// bounds it reports are its output's.
TEST(NdcSnap, IntegerLatticePathMatchesTheDoubleReference) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  SnapScratch scratch_a, scratch_b;
  std::vector<glm::vec2> fast(kMaxRegionPolygonVertices), slow(kMaxRegionPolygonVertices);
  int compared = 0;
  for (uint32_t cells : {2u, 16u, 1024u, 65536u, kMaxSnapLatticeCells}) {
    for (int trial = 0; trial < 3000; ++trial) {
      const double radius = std::pow(10.0, -6.0 + 6.5 * (0.5 * u(rng) + 0.5));
      auto poly = random_convex(rng, 3 + trial % 38, radius, {1.1 * u(rng), 1.1 * u(rng)});
      // Some vertices exactly on, or within the tolerance of, a lattice line or the border.
      for (glm::dvec2& v : poly) {
        const int mode = int(rng() % 6);
        auto on_line = [&](double c, double offset) {
          return std::round((c + 1.0) * 0.5 * cells) / (0.5 * cells) - 1.0 + offset;
        };
        if (mode == 1) v.x = on_line(v.x, 0.0);
        if (mode == 2) v.y = on_line(v.y, 0.4 * kSnapToleranceCells * 2.0 / cells);
        if (mode == 3) v.x = on_line(v.x, -0.4 * kSnapToleranceCells * 2.0 / cells);
        if (mode == 4) v = glm::clamp(v, glm::dvec2(-1.0), glm::dvec2(1.0));
      }
      NdcRect bounds;
      const uint32_t n = snap_polygon_conservative(poly, cells, fast, scratch_a, &bounds);
      const uint32_t m = detail::snap_polygon_by_double_hull(poly, cells, slow, scratch_b);
      ASSERT_EQ(n, m) << "cells " << cells << " trial " << trial;
      // The bounds the snap reports are its output's (the region insert takes them instead).
      if (n > 0) {
        ASSERT_EQ(bounds, bounds_of(std::span<const glm::vec2>(fast.data(), n))) << "trial " << trial;
      }
      for (uint32_t i = 0; i < n; ++i) {
        ASSERT_EQ(fast[i].x, slow[i].x) << "cells " << cells << " trial " << trial << " vertex " << i;
        ASSERT_EQ(fast[i].y, slow[i].y) << "cells " << cells << " trial " << trial << " vertex " << i;
      }
      if (n > 0) ++compared;
    }
  }
  EXPECT_GT(compared, 10000);  // most inputs meet the screen: the comparison is not vacuous
}

TEST(NdcSnap, OutputIsCanonicalLatticePolygon) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const uint32_t cells = 1024;
  for (int trial = 0; trial < 300; ++trial) {
    const auto poly = random_convex(rng, 3 + trial % 30, 0.05 + 0.6 * std::abs(u(rng)), {0.5 * u(rng), 0.5 * u(rng)});
    const auto s = snap(poly, cells);
    ASSERT_GE(s.size(), 3u);
    for (size_t i = 0; i < s.size(); ++i) {
      const double k = (double(s[i].x) + 1.0) * cells / 2.0, l = (double(s[i].y) + 1.0) * cells / 2.0;
      EXPECT_EQ(k, std::round(k));
      EXPECT_EQ(l, std::round(l));
      EXPECT_LE(std::abs(s[i].x), 1.0f);
      EXPECT_LE(std::abs(s[i].y), 1.0f);
      const glm::dvec2 a(s[i]), b(s[(i + 1) % s.size()]), c(s[(i + 2) % s.size()]);
      EXPECT_GT(cross(a, b, c), 0.0) << "not strictly convex CCW";
      EXPECT_TRUE(i == 0 || s[0].x < s[i].x || (s[0].x == s[i].x && s[0].y < s[i].y));
    }
    auto rotated = poly;
    std::rotate(rotated.begin(), rotated.begin() + 1 + trial % (poly.size() - 1), rotated.end());
    EXPECT_EQ(snap(rotated, cells), s);
    auto reversed = poly;
    std::reverse(reversed.begin(), reversed.end());
    EXPECT_EQ(snap(reversed, cells), s);
    const std::vector<glm::dvec2> again(s.begin(), s.end());
    EXPECT_EQ(snap(again, cells), s);
  }
}

// Rounding noise below the tolerance on a lattice polygon does not push it out a cell: this is
// what lets a polygon that went round a cycle of portals be recognised as already seen. At the
// finest lattice the tolerance is 1e-12 NDC; the clipper's noise is a few double ulps (1e-15).
TEST(NdcSnap, NoiseBelowToleranceSnapsBackToTheSamePolygon) {
  for (uint32_t cells : {1024u, kMaxSnapLatticeCells}) {
    const double g = 2.0 / cells;
    const std::vector<glm::dvec2> exact = {
        {-100 * g, -50 * g}, {30 * g, -50 * g}, {70 * g, 20 * g}, {-100 * g, 90 * g}};
    const auto s = snap(exact, cells);
    // Vertices stay where they were: the lattice coordinates are exact in float.
    ASSERT_EQ(s.size(), 4u);
    EXPECT_EQ(glm::dvec2(s[0]), exact[0]) << cells;
    std::mt19937 rng(9);
    const double noise = 0.5 * kSnapToleranceCells * g;  // 1e-12 NDC at 1024 cells, 5e-13 at 2^21
    std::uniform_real_distribution<double> u(-noise, noise);
    for (int trial = 0; trial < 100; ++trial) {
      auto noisy = exact;
      for (auto& v : noisy) v += glm::dvec2(u(rng), u(rng));
      EXPECT_EQ(snap(noisy, cells), s) << cells;
    }
  }
}

// At the finest lattice (2 / 2^21 = 9.5e-7 NDC) a vertex off the lattice moves out by less than
// one cell per axis, and a vertex near the screen corner (where float is coarsest, ulp 6e-8) lands
// on an exact lattice point.
TEST(NdcSnap, FinestLatticeSnapsByLessThanOneMicroNdc) {
  const double g = 2.0 / kMaxSnapLatticeCells;
  EXPECT_LT(g, 1e-6);
  const std::vector<glm::dvec2> tri = {{0.99999912345, 0.99999954321}, {-0.3, 0.2}, {0.1234567891, -0.7654321}};
  const auto s = snap(tri, kMaxSnapLatticeCells);
  ASSERT_GE(s.size(), 3u);
  for (const glm::vec2& v : s) {
    const double k = (double(v.x) + 1.0) / g, l = (double(v.y) + 1.0) / g;
    EXPECT_EQ(k, std::round(k));
    EXPECT_EQ(l, std::round(l));
  }
  for (const glm::dvec2& v : tri) {
    EXPECT_TRUE(convex_contains_point(s, v));
    double nearest = 1e9;
    for (const glm::vec2& w : s) nearest = std::min(nearest, glm::length(glm::dvec2(w) - v));
    EXPECT_LE(nearest, std::sqrt(2.0) * g);
  }
}

TEST(NdcSnap, TooManyVerticesBecomesTheBoundingRect) {
  std::mt19937 rng(1);
  // A 90-gon circle at 65536 cells keeps far more than kMaxRegionPolygonVertices hull vertices.
  std::vector<glm::dvec2> circle;
  for (int i = 0; i < 90; ++i)
    circle.emplace_back(0.8 * std::cos(i * 0.0698131700797732), 0.8 * std::sin(i * 0.0698131700797732));
  const auto s = snap(circle, 65536);
  ASSERT_EQ(s.size(), 4u);
  const NdcRect r = bounds_of(s);
  for (const glm::dvec2& v : circle) {
    EXPECT_LE(double(r.min.x), v.x);
    EXPECT_GE(double(r.max.y), v.y);
  }
  for (const glm::dvec2& v : circle) EXPECT_TRUE(convex_contains_point(s, v));
}

TEST(NdcSnap, SliversAndOffscreen) {
  // A sliver thinner than the tolerance still snaps to a non-empty polygon containing it.
  const std::vector<glm::dvec2> sliver = {{-0.5, 0.25}, {0.5, 0.25 + 1e-12}, {0.5, 0.25 + 2e-12}};
  const auto s = snap(sliver, 1024);
  ASSERT_GE(s.size(), 3u);
  for (const auto& v : sliver) EXPECT_TRUE(convex_contains_point(s, v, 1e-9));
  // Entirely off screen: nothing.
  EXPECT_TRUE(snap({{1.5, 1.5}, {2.0, 1.5}, {2.0, 2.0}}, 1024).empty());
  // Fewer than three vertices: nothing.
  EXPECT_TRUE(snap({{0.0, 0.0}, {0.5, 0.5}}, 1024).empty());
}

// The test-only float mode is conservative as well, and keeps growing by an ulp each round: the
// property the drift-hang test relies on.
TEST(NdcSnap, FloatModeWidensByAnUlp) {
  const std::vector<glm::dvec2> poly = {{-0.25, -0.25}, {0.25, -0.25}, {0.25, 0.25}, {-0.25, 0.25}};
  auto s = snap(poly, 0);
  ASSERT_EQ(s.size(), 4u);
  for (const auto& v : poly) EXPECT_TRUE(convex_contains_point(s, v));
  EXPECT_LT(s[0].x, -0.25f);
  const std::vector<glm::dvec2> again(s.begin(), s.end());
  const auto s2 = snap(again, 0);
  EXPECT_LT(s2[0].x, s[0].x);
}

TEST(NdcSnap, ValidLattices) {
  EXPECT_TRUE(valid_snap_lattice(2));
  EXPECT_TRUE(valid_snap_lattice(1024));
  EXPECT_TRUE(valid_snap_lattice(65536));
  EXPECT_TRUE(valid_snap_lattice(1u << 21));
  EXPECT_FALSE(valid_snap_lattice(0));
  EXPECT_FALSE(valid_snap_lattice(1));
  EXPECT_FALSE(valid_snap_lattice(1000));
  EXPECT_FALSE(valid_snap_lattice(1u << 22));
}

}  // namespace
}  // namespace lintel
