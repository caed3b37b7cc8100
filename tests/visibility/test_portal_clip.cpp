// The portal clipper: homogeneous near/far clipping before the divide, and convex-convex clipping.
#include <lintel/doorway_rule.h>
#include <lintel/portal_clip.h>
#include <lintel/view.h>

#include "portal_clip_testing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace lintel {
namespace {

struct Projected {
  std::vector<glm::dvec2> ndc;
  bool near_clipped = false;
};

// Clips at view depth `min_depth` (the near distance: the ordinary near clip) and the far plane.
Projected project_and_clip(const glm::dmat4& vp, const std::vector<glm::dvec3>& poly_world, double min_depth) {
  std::array<glm::dvec4, kMaxPortalVertices> in{};
  std::array<glm::dvec4, kMaxSlabClippedVertices> out{}, scratch{};
  for (size_t i = 0; i < poly_world.size(); ++i) in[i] = vp * glm::dvec4(poly_world[i], 1.0);
  const SlabClipResult r =
      clip_to_depth_slab(std::span<const glm::dvec4>(in.data(), poly_world.size()), min_depth, out, scratch);
  Projected p;
  p.near_clipped = r.near_clipped;
  for (uint32_t i = 0; i < r.count; ++i) {
    EXPECT_GE(out[i].w, min_depth * (1.0 - 1e-12));
    EXPECT_LE(out[i].z, out[i].w + 1e-12);
  }
  p.ndc.resize(r.count);
  perspective_divide(std::span<const glm::dvec4>(out.data(), r.count), p.ndc);
  return p;
}

bool inside_convex(const std::vector<glm::dvec2>& poly, const glm::dvec2& p, double tol) {
  const double orientation = twice_signed_area(poly) >= 0.0 ? 1.0 : -1.0;
  for (size_t i = 0; i < poly.size(); ++i) {
    const glm::dvec2 a = poly[i], b = poly[(i + 1) % poly.size()];
    const glm::dvec2 e = b - a;
    const double side = orientation * (e.x * (p.y - a.y) - e.y * (p.x - a.x));
    if (side < -tol * glm::length(e)) return false;
  }
  return true;
}

// Eye standing in a doorway, 0.2 m in front of its plane, looking 60 degrees off the normal: part
// of the door is behind the eye (w < 0). Property: every point of the door whose depth lies
// between the clip depth and the far plane projects inside the clipped polygon (nothing is lost),
// and the result is finite — for the near plane and for the traversal's portal_clip_depth().
// Projecting first and clipping after (the naive order) loses points: checked too, so the test
// proves it can tell the two apart.
TEST(PortalClip, NearClipInHomogeneousSpaceIsFaithfulWithEyeInDoorway) {
  View v;
  v.eye_world = {0.1f, 1.2f, 0.2f};  // door in the plane z = 0, x in [-0.6, 0.6], y in [0, 2.2]
  v.target_world = v.eye_world + glm::vec3(std::sin(glm::radians(60.0f)), 0.0f, -std::cos(glm::radians(60.0f)));
  v.fov_y_deg = 90.0f;
  v.aspect = 1.5f;
  const glm::dmat4 vp = view_projection_d(v);
  const std::vector<glm::dvec3> door = {{-0.6, 0.0, 0.0}, {0.6, 0.0, 0.0}, {0.6, 2.2, 0.0}, {-0.6, 2.2, 0.0}};
  for (const double min_depth : {double(v.near_m), portal_clip_depth(v)}) {
    const Projected clipped = project_and_clip(vp, door, min_depth);
    ASSERT_GE(clipped.ndc.size(), 3u);
    EXPECT_TRUE(clipped.near_clipped);

    std::vector<glm::dvec2> naive;
    for (const glm::dvec3& p : door) {
      const glm::dvec4 c = vp * glm::dvec4(p, 1.0);
      naive.emplace_back(c.x / c.w, c.y / c.w);
    }
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int visible_samples = 0, naive_misses = 0;
    for (int i = 0; i < 4000; ++i) {
      const glm::dvec3 p(-0.6 + 1.2 * u(rng), 2.2 * u(rng), 0.0);
      const glm::dvec4 c = vp * glm::dvec4(p, 1.0);
      if (c.w < min_depth || c.z > c.w) continue;
      ++visible_samples;
      const glm::dvec2 ndc(c.x / c.w, c.y / c.w);
      EXPECT_TRUE(inside_convex(clipped.ndc, ndc, 1e-9)) << "visible door point lost at " << ndc.x << ", " << ndc.y;
      if (!inside_convex(naive, ndc, 1e-9)) ++naive_misses;
    }
    EXPECT_GT(visible_samples, 100);
    EXPECT_GT(naive_misses, 0) << "the scenario should defeat divide-then-clip";
  }
}

// A vertex exactly on the eye plane (w = 0) must not reach the divide.
TEST(PortalClip, VertexAtWZeroIsClippedAway) {
  View v;
  v.eye_world = {0.0f, 0.0f, 0.0f};
  v.target_world = {0.0f, 0.0f, -1.0f};
  const glm::dmat4 vp = view_projection_d(v);
  const std::vector<glm::dvec3> tri = {{1.0, 0.0, 0.0}, {-1.0, -1.0, -3.0}, {1.0, 1.0, -3.0}};
  ASSERT_NEAR((vp * glm::dvec4(tri[0], 1.0)).w, 0.0, 1e-12);
  const Projected p = project_and_clip(vp, tri, double(v.near_m));
  ASSERT_GE(p.ndc.size(), 3u);
  EXPECT_TRUE(p.near_clipped);
  for (const glm::dvec2& q : p.ndc) EXPECT_TRUE(std::isfinite(q.x) && std::isfinite(q.y));
}

TEST(PortalClip, PolygonFullyBehindTheEyeIsEmpty) {
  View v;
  v.eye_world = {0.0f, 0.0f, 0.0f};
  v.target_world = {0.0f, 0.0f, -1.0f};
  const glm::dmat4 vp = view_projection_d(v);
  const std::vector<glm::dvec3> behind = {{-1.0, -1.0, 2.0}, {1.0, -1.0, 2.0}, {1.0, 1.0, 2.0}, {-1.0, 1.0, 2.0}};
  EXPECT_EQ(project_and_clip(vp, behind, double(v.near_m)).ndc.size(), 0u);
  EXPECT_EQ(project_and_clip(vp, behind, portal_clip_depth(v)).ndc.size(), 0u);
  // Between the eye and the near plane: also nothing.
  const std::vector<glm::dvec3> too_close = {{-1, -1, -0.01}, {1, -1, -0.01}, {1, 1, -0.01}, {-1, 1, -0.01}};
  EXPECT_EQ(project_and_clip(vp, too_close, double(v.near_m)).ndc.size(), 0u);
  // Beyond the far plane: nothing either.
  const std::vector<glm::dvec3> too_far = {{-1, -1, -2000.0}, {1, -1, -2000.0}, {1, 1, -2000.0}};
  EXPECT_EQ(project_and_clip(vp, too_far, double(v.near_m)).ndc.size(), 0u);
}

TEST(PortalClip, FullyVisiblePolygonIsUnchanged) {
  View v;
  const glm::dmat4 vp = view_projection_d(v);
  const std::vector<glm::dvec3> quad = {{-0.5, -0.5, -3.0}, {0.5, -0.5, -3.0}, {0.5, 0.5, -3.0}, {-0.5, 0.5, -3.0}};
  const Projected p = project_and_clip(vp, quad, double(v.near_m));
  ASSERT_EQ(p.ndc.size(), 4u);
  EXPECT_FALSE(p.near_clipped);
  for (size_t i = 0; i < 4; ++i) {
    const glm::dvec4 c = vp * glm::dvec4(quad[i], 1.0);
    EXPECT_NEAR(p.ndc[i].x, c.x / c.w, 1e-12);
    EXPECT_NEAR(p.ndc[i].y, c.y / c.w, 1e-12);
  }
}

double clip_area(const std::vector<glm::dvec2>& subject, const std::vector<glm::vec2>& window) {
  std::array<glm::dvec2, kMaxRegionClippedVertices> out{}, scratch{};
  const uint32_t n = clip_convex_by_convex(subject, window, out, scratch);
  return n < 3 ? 0.0 : 0.5 * twice_signed_area(std::span<const glm::dvec2>(out.data(), n));
}

TEST(PortalClip, ConvexConvexKnownCases) {
  const std::vector<glm::vec2> square = {{-0.5f, -0.5f}, {0.5f, -0.5f}, {0.5f, 0.5f}, {-0.5f, 0.5f}};
  // A big square clipped by the small one: the small one (area 1).
  EXPECT_NEAR(clip_area({{-2, -2}, {2, -2}, {2, 2}, {-2, 2}}, square), 1.0, 1e-12);
  // Inside: unchanged.
  EXPECT_NEAR(clip_area({{-0.25, -0.25}, {0.25, -0.25}, {0.25, 0.25}}, square), 0.125, 1e-12);
  // Half overlap: the right half of [-0.5,0.5]^2 covered by x >= 0.
  EXPECT_NEAR(clip_area({{0, -2}, {2, -2}, {2, 2}, {0, 2}}, square), 0.5, 1e-12);
  // Disjoint and touching: nothing (touching leaves zero area).
  EXPECT_EQ(clip_area({{1, 1}, {2, 1}, {2, 2}}, square), 0.0);
  EXPECT_NEAR(clip_area({{0.5, -0.5}, {1.5, -0.5}, {1.5, 0.5}, {0.5, 0.5}}, square), 0.0, 1e-15);
  // Diamond in a square: the square's corners cut off.
  EXPECT_NEAR(clip_area({{0, -0.7}, {0.7, 0}, {0, 0.7}, {-0.7, 0}}, square), 0.98 - 4 * 0.04, 1e-12);
}

// A convex polygon of n vertices at random angles on the circle of radius r about c,
// counter-clockwise.
std::vector<glm::dvec2> random_convex(std::mt19937& rng, int n, double r, glm::dvec2 c) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> angles;
  for (int i = 0; i < n; ++i) angles.push_back(3.14159265358979 * (u(rng) + 1.0));
  std::sort(angles.begin(), angles.end());
  std::vector<glm::dvec2> poly;
  for (double a : angles) poly.push_back(c + r * glm::dvec2(std::cos(a), std::sin(a)));
  return poly;
}

// Property: for random convex polygons A (subject) and B (window), a point is in the result iff it
// is in both (checked on random points, with a small tolerance at the boundaries).
TEST(PortalClip, ConvexConvexIsIntersectionOnRandomPolygons) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    const auto a = random_convex(rng, 3 + trial % 20, 0.3 + 0.7 * std::abs(u(rng)), {0.5 * u(rng), 0.5 * u(rng)});
    const auto bd = random_convex(rng, 3 + trial % 7, 0.3 + 0.7 * std::abs(u(rng)), {0.5 * u(rng), 0.5 * u(rng)});
    if (std::abs(twice_signed_area(a)) < 1e-3 || std::abs(twice_signed_area(bd)) < 1e-3) continue;
    std::vector<glm::vec2> b;
    for (const auto& p : bd) b.emplace_back(p);
    std::vector<glm::dvec2> bb(b.begin(), b.end());
    std::array<glm::dvec2, kMaxRegionClippedVertices> out{}, scratch{};
    const uint32_t n = clip_convex_by_convex(a, b, out, scratch);
    const std::vector<glm::dvec2> result(out.begin(), out.begin() + n);
    for (int i = 0; i < 200; ++i) {
      const glm::dvec2 p(u(rng), u(rng));
      const bool in_both = inside_convex(a, p, -1e-9) && inside_convex(bb, p, -1e-9);  // strictly inside
      const bool in_either_loose = inside_convex(a, p, 1e-9) && inside_convex(bb, p, 1e-9);
      const bool in_result = n >= 3 && inside_convex(result, p, 1e-9);
      EXPECT_TRUE(!in_both || in_result) << "trial " << trial;
      EXPECT_TRUE(!in_result || in_either_loose) << "trial " << trial;
    }
  }
}

// Property: the clip with its skipped passes (every vertex inside an edge: the pass is the
// identity; every vertex outside: empty) returns, bit for bit, what running every
// Sutherland-Hodgman pass returns (detail::clip_convex_by_convex_plain, the clip as first written).
// The subjects are random convex polygons around, inside, across and outside the windows, with
// vertices on the window's edges and corners (lattice windows, as the traversal's regions are),
// so that every kind of pass occurs.
TEST(PortalClip, ConvexClipMatchesThePlainPasses) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> lattice(0, 64);
  size_t skipped_kinds[3] = {0, 0, 0};  // results: empty, unchanged subject, cut
  for (int trial = 0; trial < 20000; ++trial) {
    // Window: a convex polygon with vertices on a 64-cell lattice (as snapped regions are).
    std::vector<glm::vec2> window;
    for (const glm::dvec2& p :
         random_convex(rng, 3 + trial % 9, 0.2 + 0.8 * std::abs(u(rng)), {0.3 * u(rng), 0.3 * u(rng)}))
      window.emplace_back(std::round(p.x * 32.0) / 32.0, std::round(p.y * 32.0) / 32.0);
    std::vector<glm::dvec2> wd(window.begin(), window.end());
    if (twice_signed_area(wd) <= 1e-6) continue;  // rounding made it degenerate or clockwise
    std::vector<glm::dvec2> subject =
        random_convex(rng, 3 + trial % 7, 0.05 + 1.2 * std::abs(u(rng)), {0.8 * u(rng), 0.8 * u(rng)});
    if (trial % 4 == 1) subject[0] = wd[size_t(lattice(rng)) % wd.size()];  // a vertex on a window corner
    if (trial % 4 == 2) {                                                   // a vertex on a window edge
      const size_t e = size_t(lattice(rng)) % wd.size();
      subject[0] = wd[e] + (wd[(e + 1) % wd.size()] - wd[e]) * (double(lattice(rng)) / 64.0);
    }
    if (trial % 4 == 3) subject = wd;  // the window itself
    std::array<glm::dvec2, kMaxRegionClippedVertices> out{}, scratch{}, ref_out{}, ref_scratch{};
    const uint32_t n = clip_convex_by_convex(subject, window, out, scratch);
    const uint32_t ref = detail::clip_convex_by_convex_plain(subject, window, ref_out, ref_scratch);
    ASSERT_EQ(n, ref) << "trial " << trial;
    for (uint32_t i = 0; i < n; ++i) {
      ASSERT_EQ(out[i].x, ref_out[i].x) << "trial " << trial << " vertex " << i;
      ASSERT_EQ(out[i].y, ref_out[i].y) << "trial " << trial << " vertex " << i;
    }
    const bool unchanged = n == subject.size() && std::equal(subject.begin(), subject.end(), out.begin());
    ++skipped_kinds[n == 0 ? 0 : unchanged ? 1 : 2];
  }
  // Each kind of result occurred often enough for the comparison to mean something.
  for (size_t k : skipped_kinds) EXPECT_GT(k, 1000u);
}

}  // namespace
}  // namespace lintel
