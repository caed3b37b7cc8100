// The slice-integrated union area the benchmark reports for polygon regions.
#include <lintel/reference/region_area.h>

#include <gtest/gtest.h>

namespace {

std::vector<glm::dvec2> square(double x0, double y0, double s) {
  return {{x0, y0}, {x0 + s, y0}, {x0 + s, y0 + s}, {x0, y0 + s}};
}

TEST(RegionArea, OverlapsCountOnce) {
  const std::vector<std::vector<glm::dvec2>> polys{square(0, 0, 1), square(0.5, 0, 1)};
  EXPECT_NEAR(lintel::union_area_ndc(polys), 1.5, 1e-9);
}

TEST(RegionArea, TriangleWithinSliceError) {
  const std::vector<std::vector<glm::dvec2>> polys{{{-1, -1}, {1, -1}, {0, 1}}};
  EXPECT_NEAR(lintel::union_area_ndc(polys), 2.0, 1e-3);
}

TEST(RegionArea, DisjointAndEmpty) {
  EXPECT_EQ(lintel::union_area_ndc({}), 0.0);
  const std::vector<std::vector<glm::dvec2>> polys{square(-1, -1, 0.5), square(0.5, 0.5, 0.5)};
  EXPECT_NEAR(lintel::union_area_ndc(polys), 0.5, 1e-9);
}

}  // namespace
