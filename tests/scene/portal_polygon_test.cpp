// The geometry behind portal validation, tested directly (private headers of Lintel::scene):
// polygon extraction (welding, flat corners, any triangulation, winding), its refusals, the
// polygon-vs-box touch test and the volume closedness count (against its sorted reference).
#include "read/closed_mesh.h"
#include "read/polygon_box_overlap.h"
#include "read/portal_polygon.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace lintel::scene_read {
namespace {

using Points = std::vector<glm::dvec3>;
using Indices = std::vector<uint32_t>;

// A unit square in the XY plane, counter-clockwise about +Z.
const Points kSquare = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};

TEST(PortalPolygon, SquareFromTwoTrianglesKeepsFourCornersAndRightHandNormal) {
  ConvexPolygon p;
  ASSERT_EQ(extract_convex_polygon(kSquare, {0, 1, 2, 0, 2, 3}, p), "");
  EXPECT_EQ(p.vertices.size(), 4u);
  EXPECT_NEAR(p.normal.z, 1.0, 1e-12);
  EXPECT_NEAR(p.area, 1.0, 1e-12);
  EXPECT_NEAR(glm::length(p.centroid - glm::dvec3(0.5, 0.5, 0)), 0.0, 1e-12);
  EXPECT_NEAR(p.plane_d, 0.0, 1e-12);
}

TEST(PortalPolygon, ClockwiseTrianglesGiveMinusZAndAVertexOrderThatAgrees) {
  // Orientation between cells is the caller's job (flip_polygon); extraction keeps the file's.
  ConvexPolygon p;
  ASSERT_EQ(extract_convex_polygon(kSquare, {0, 2, 1, 0, 3, 2}, p), "");
  EXPECT_NEAR(p.normal.z, -1.0, 1e-12);
  glm::dvec3 newell(0.0);
  for (size_t i = 0; i < p.vertices.size(); ++i)
    newell += glm::cross(p.vertices[i], p.vertices[(i + 1) % p.vertices.size()]);
  EXPECT_GT(glm::dot(glm::normalize(newell), p.normal), 0.999);
  const glm::dvec3 before = p.normal;
  flip_polygon(p);
  EXPECT_NEAR(glm::dot(before, p.normal), -1.0, 1e-12);
}

TEST(PortalPolygon, DuplicatedCornersWithRoundingAreWelded) {
  Points soup = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1e-7, 0, 0}, {1, 1 + 1e-7, 0}, {0, 1, 0}};
  ConvexPolygon p;
  ASSERT_EQ(extract_convex_polygon(soup, {0, 1, 2, 3, 4, 5}, p), "");
  EXPECT_EQ(p.vertices.size(), 4u);
}

TEST(PortalPolygon, VertexOnAnEdgeIsAcceptedAndDropped) {
  Points pts = kSquare;
  pts.push_back({0.5, 0, 0});  // 4: on the bottom edge
  ConvexPolygon p;
  ASSERT_EQ(extract_convex_polygon(pts, {0, 4, 3, 4, 1, 2, 4, 2, 3}, p), "");
  EXPECT_EQ(p.vertices.size(), 4u);
}

TEST(PortalPolygon, HexagonFanAndStripTriangulationsGiveTheSamePolygon) {
  Points hex;
  for (int k = 0; k < 6; ++k) hex.push_back({std::cos(k * M_PI / 3), std::sin(k * M_PI / 3), 2.0});
  ConvexPolygon fan, strip;
  ASSERT_EQ(extract_convex_polygon(hex, {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5}, fan), "");
  ASSERT_EQ(extract_convex_polygon(hex, {0, 1, 2, 0, 2, 5, 5, 2, 3, 5, 3, 4}, strip), "");
  EXPECT_EQ(fan.vertices.size(), 6u);
  EXPECT_NEAR(fan.area, strip.area, 1e-12);
  EXPECT_NEAR(fan.plane_d, 2.0, 1e-12);
}

TEST(PortalPolygon, SixtyFourCornersAreAllowedSixtyFiveAreNot) {
  for (int n : {64, 65}) {
    Points ring;
    Indices tris;
    for (int k = 0; k < n; ++k) ring.push_back({std::cos(2 * M_PI * k / n), std::sin(2 * M_PI * k / n), 0});
    for (int k = 1; k + 1 < n; ++k) tris.insert(tris.end(), {0u, uint32_t(k), uint32_t(k + 1)});
    ConvexPolygon p;
    const std::string why = extract_convex_polygon(ring, tris, p);
    if (n == 64)
      EXPECT_EQ(why, "");
    else
      EXPECT_NE(why.find("more than 64 distinct vertices"), std::string::npos) << why;
  }
}

// A 0.3 m square whose corner is 0.76 mm off its plane: a bend as float32 rounding makes it 1e4 m
// from the frame (the report). Relative tolerance alone (0.42 mm) refuses it; with the
// rounding floor of such coordinates it is accepted, and a bend of 0.1 m still is not.
TEST(PortalPolygon, RoundingFloorAcceptsFarSmallPortalsButNotRealBends) {
  const std::vector<glm::vec3> far_mesh = {{1e4f, 1e4f, 1e4f}};
  const double floor_m = rounding_floor(glm::dmat4(1.0), far_mesh);
  EXPECT_GT(floor_m, 1e-3);  // 4 x FLT_EPSILON x 1e4 m
  EXPECT_LT(floor_m, 1e-2);
  Points noisy = {{0, 0, 0}, {0.3, 0, 0}, {0.3, 0.3, 0.00076}, {0, 0.3, 0}};
  ConvexPolygon p;
  EXPECT_NE(extract_convex_polygon(noisy, {0, 1, 2, 0, 2, 3}, p).find("is not planar"), std::string::npos);
  EXPECT_EQ(extract_convex_polygon(noisy, {0, 1, 2, 0, 2, 3}, p, floor_m), "");
  EXPECT_EQ(p.vertices.size(), 4u);
  Points bent = noisy;
  bent[2].z = 0.1;
  EXPECT_NE(extract_convex_polygon(bent, {0, 1, 2, 0, 2, 3}, p, floor_m).find("is not planar"), std::string::npos);
}

TEST(PortalPolygon, PortalTooSmallForItsCoordinatesIsRefusedByName) {
  const std::vector<glm::vec3> far_mesh = {{1e5f, 0.0f, 0.0f}};
  const double floor_m = rounding_floor(glm::translate(glm::dmat4(1.0), glm::dvec3(-1e5, 0, 0)), far_mesh);
  Points tiny = {{0, 0, 0}, {0.01, 0, 0}, {0.01, 0.01, 0}, {0, 0.01, 0}};
  ConvexPolygon p;
  EXPECT_EQ(extract_convex_polygon(tiny, {0, 1, 2, 0, 2, 3}, p), "");
  EXPECT_NE(extract_convex_polygon(tiny, {0, 1, 2, 0, 2, 3}, p, floor_m).find("is too small for its coordinates"),
            std::string::npos);
}

TEST(PortalPolygon, RefusesBentQuad) {
  Points bent = kSquare;
  bent[2].z = 0.1;  // 7% of the size, far over the 0.1% tolerance
  ConvexPolygon p;
  EXPECT_NE(extract_convex_polygon(bent, {0, 1, 2, 0, 2, 3}, p).find("is not planar"), std::string::npos);
}

TEST(PortalPolygon, AcceptsRoundingBelowThePlanarityTolerance) {
  Points almost = kSquare;
  almost[2].z = 1e-5;
  ConvexPolygon p;
  ASSERT_EQ(extract_convex_polygon(almost, {0, 1, 2, 0, 2, 3}, p), "");
  for (const glm::dvec3& v : p.vertices) EXPECT_NEAR(glm::dot(p.normal, v), p.plane_d, 1e-12);  // projected
}

TEST(PortalPolygon, RefusesReflexCorner) {
  const Points l = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
  ConvexPolygon p;
  EXPECT_NE(extract_convex_polygon(l, {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5}, p).find("is not convex"),
            std::string::npos);
}

TEST(PortalPolygon, RefusesOverlapThatHidesAHoleFromTheAreaTest) {
  // ABC + ABD have the square's area but cover the triangle near AB twice and leave one uncovered.
  ConvexPolygon p;
  EXPECT_NE(extract_convex_polygon(kSquare, {0, 1, 2, 0, 1, 3}, p).find("not one convex polygon"), std::string::npos);
}

TEST(PortalPolygon, RefusesMissingTriangle) {
  const Points hex = {{1, 0, 0}, {0.5, 0.8, 0}, {-0.5, 0.8, 0}, {-1, 0, 0}, {-0.5, -0.8, 0}, {0.5, -0.8, 0}};
  ConvexPolygon p;
  // A fan with its second triangle missing: every corner is used, the middle is not covered.
  EXPECT_NE(extract_convex_polygon(hex, {0, 1, 2, 0, 3, 4, 0, 4, 5}, p).find("not one convex polygon"),
            std::string::npos);
}

TEST(PortalPolygon, RefusesDoubledTriangulation) {
  ConvexPolygon p;
  EXPECT_NE(extract_convex_polygon(kSquare, {0, 1, 2, 0, 2, 3, 0, 1, 2, 0, 2, 3}, p).find("not one convex polygon"),
            std::string::npos);
}

TEST(PortalPolygon, RefusesSliverAndCollinearAndEmpty) {
  const Points sliver = {{0, 0, 0}, {1, 0, 0}, {1, 1e-8, 0}, {0, 1e-8, 0}};
  const Points line = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  ConvexPolygon p;
  EXPECT_NE(extract_convex_polygon(sliver, {0, 1, 2, 0, 2, 3}, p).find("degenerate"), std::string::npos);
  EXPECT_NE(extract_convex_polygon(line, {0, 1, 2}, p).find("degenerate"), std::string::npos);
  EXPECT_NE(extract_convex_polygon(line, {}, p).find("no triangles"), std::string::npos);
}

TEST(PortalPolygon, ToleranceScalesWithSize) {
  // The same bent quad at 1 mm and at 1 km: both are bent by 10% of their size.
  for (double scale : {1e-3, 1e3}) {
    Points bent;
    for (const glm::dvec3& v : kSquare) bent.push_back(v * scale);
    bent[2].z = 0.1 * scale;
    ConvexPolygon p;
    EXPECT_NE(extract_convex_polygon(bent, {0, 1, 2, 0, 2, 3}, p).find("is not planar"), std::string::npos) << scale;
  }
}

TEST(PolygonBoxTouch, PolygonOnAFaceTouchesPolygonAwayDoesNot) {
  const glm::dvec3 lo(-1, 0, -1), hi(1, 2, 1);
  const Points on_face = {{1, 0.5, -0.2}, {1, 0.5, 0.2}, {1, 1.5, 0.2}, {1, 1.5, -0.2}};
  EXPECT_TRUE(polygon_touches_box(on_face, lo, hi, 0.0));
  Points apart = on_face;
  for (glm::dvec3& v : apart) v.x += 0.01;
  EXPECT_FALSE(polygon_touches_box(apart, lo, hi, 0.001));
  EXPECT_TRUE(polygon_touches_box(apart, lo, hi, 0.02));
}

TEST(PolygonBoxTouch, DiagonalPolygonPassingACornerIsSeparatedByAnEdgeAxis) {
  // Near the box corner (1, 1, 1) but outside it; only a cross-product axis separates them.
  const Points tilted = {{2.2, 0, 1}, {0, 2.2, 1}, {0, 2.2, 3}, {2.2, 0, 3}};
  EXPECT_FALSE(polygon_touches_box(tilted, {0, 0, 0}, {1, 1, 1}, 0.0));
  const Points crossing = {{1.8, 0, 0.5}, {0, 1.8, 0.5}, {0, 1.8, 2}, {1.8, 0, 2}};
  EXPECT_TRUE(polygon_touches_box(crossing, {0, 0, 0}, {1, 1, 1}, 0.0));
}

std::vector<glm::vec3> tetrahedron() {
  const glm::vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0), d(0, 0, 1);
  return {a, c, b, a, b, d, a, d, c, b, c, d};
}

TEST(ClosedMesh, TetrahedronIsClosedAndLosingAFaceOpensThreeEdges) {
  std::vector<glm::vec3> tris = tetrahedron();
  EXPECT_EQ(count_open_edges(tris), 0u);
  tris.resize(9);
  EXPECT_EQ(count_open_edges(tris), 3u);
}

// The hashed count against the sort of edge positions it replaced, on random soups drawn from a
// few positions (shared edges, repeated and degenerate triangles, -0 beside +0).
TEST(ClosedMesh, CountMatchesTheSortByPosition) {
  std::mt19937 rng(3);
  size_t open_soups = 0;
  for (int n = 0; n < 20000; ++n) {
    std::vector<glm::vec3> pool(1 + rng() % 12);
    for (glm::vec3& p : pool) p = glm::vec3(float(int(rng() % 3) - 1), float(int(rng() % 3) - 1), float(rng() % 2));
    if (rng() % 5 == 0) pool[0].x = -0.0f;
    std::vector<glm::vec3> tris(rng() % 40);
    for (glm::vec3& t : tris) t = pool[rng() % pool.size()];
    const size_t open = count_open_edges(tris);
    ASSERT_EQ(open, count_open_edges_by_position(tris)) << "soup " << n;
    open_soups += open > 0;
  }
  EXPECT_GT(open_soups, 1000u);
  EXPECT_LT(open_soups, 19000u);
}

// A NaN position equals none, itself included: each corner there is a vertex of its own.
TEST(ClosedMesh, ANaNCornerOpensItsEdges) {
  std::vector<glm::vec3> tris = tetrahedron();
  for (glm::vec3& v : tris)
    if (v == glm::vec3(0, 0, 1)) v.z = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(count_open_edges(tris), 6u);  // the three faces at the NaN corner: two edges each
}

}  // namespace
}  // namespace lintel::scene_read
