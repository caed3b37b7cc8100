// cell_volume_contains answers by a ray's signed crossing count where that is unambiguous and by
// the generalized winding number elsewhere. Property (stated over real volumes: the committed
// scenes, a random generated scene and, where Freedoom is installed, a Doom map whose cells are
// many prisms sharing faces): wherever the ray answers, its count equals the rounded exact winding
// number and the exact number is within 1e-6 of that integer; so cell_volume_contains is the
// old |w| > 1/2 rule. Points: random in each volume's box (widened 10 %), the volume's vertices,
// its face centroids and points a hair in front of and behind them, where the ray must defer.
#include "point_in_volume.h"
#include "volume_probes.h"

#include <lintel/cell_locate.h>
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace lintel {
namespace {

struct Tally {
  size_t by_ray = 0, exact = 0;  // random points answered by the ray / by the exact sum
  size_t surface_exact = 0;      // points on faces and vertices that deferred to the exact sum
};

void check_world(const World& world, const std::string& label, uint32_t random_points_per_cell, Tally& tally) {
  std::mt19937_64 rng(7);
  for (uint32_t c = 0; c < world.cells.size(); ++c) {
    const Cell& cell = world.cells[c];
    if (cell.volume_triangles_cell.empty()) continue;
    const glm::dvec3 lo(cell.volume_box_cell.min), hi(cell.volume_box_cell.max);
    const std::vector<glm::dvec3> points = testing::volume_probe_points(cell, random_points_per_cell, 600, false, rng);
    for (size_t k = 0; k < points.size(); ++k) {
      const glm::dvec3& p = points[k];
      const bool random_point = k < random_points_per_cell;
      const double w = volume_winding_exact(cell, p);
      if (const std::optional<int> ray = volume_winding_by_ray(cell, p)) {
        tally.by_ray += random_point;
        ASSERT_EQ(*ray, int(std::lround(w)))
            << label << " cell " << cell.name << " at " << p.x << "," << p.y << "," << p.z;
        ASSERT_NEAR(w, double(*ray), 1e-6) << label << " cell " << cell.name;
      } else {
        tally.exact += random_point;
        tally.surface_exact += !random_point;
      }
      const glm::dvec3 p_world = glm::dvec3(glm::dmat4(cell.cell_to_world) * glm::dvec4(p, 1.0));
      const glm::dvec3 back = glm::dvec3(glm::dmat4(cell.world_to_cell) * glm::dvec4(p_world, 1.0));
      // Points well inside the slack of the box test: the rule must be |w| > 1/2 there.
      if (glm::all(glm::greaterThan(back, lo)) && glm::all(glm::lessThan(back, hi))) {
        EXPECT_EQ(cell_volume_contains(world, c, p_world), std::abs(volume_winding_exact(cell, back)) > 0.5)
            << label << " cell " << cell.name;
      }
    }
  }
}

TEST(PointInVolume, RayCountAgreesWithWindingNumberOnCommittedScenes) {
  Tally tally;
  const auto worlds = testing::committed_and_random_worlds();
  ASSERT_EQ(worlds.size(), 4u);
  for (const auto& [name, world] : worlds) check_world(world, name, 200, tally);
  EXPECT_GT(tally.by_ray, 100 * tally.exact) << "the fast path should answer almost everywhere";
  EXPECT_GT(tally.surface_exact, 0u) << "points on faces and vertices must defer to the exact sum";
}

TEST(PointInVolume, RayCountAgreesWithWindingNumberOnADoomMap) {
  if (!std::filesystem::exists(testing::kFreedoomWad))
    GTEST_SKIP() << testing::kFreedoomWad << " not installed (Debian package freedoom)";
  World world;
  ASSERT_TRUE(testing::import_freedoom_map("E1M5", world).ok());
  Tally tally;
  check_world(world, "E1M5", 20, tally);
  EXPECT_GT(tally.by_ray, 100 * tally.exact) << tally.exact << " random points deferred";
}

// The cell grid (CellGrid) gives locate_cell's answer -- cell, reason, distance -- on a real
// level: 1,019 non-convex sector prisms, steps and slivers, points at random in the map's bounds
// and on the corners and centre of every seventh portal (where sectors meet).
TEST(PointInVolume, CellGridLocatesAsLocateCellOnADoomMap) {
  if (!std::filesystem::exists(testing::kFreedoomWad))
    GTEST_SKIP() << testing::kFreedoomWad << " not installed (Debian package freedoom)";
  World world;
  ASSERT_TRUE(testing::import_freedoom_map("E1M5", world).ok());
  CellGrid grid;
  grid.build(world);
  const std::vector<double> volumes = cell_volumes_m3(world);
  Aabb bounds;
  for (const Cell& cell : world.cells) bounds.extend(transform_aabb(cell.cell_to_world, cell.volume_box_cell));
  std::vector<glm::dvec3> points;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  // About 2,000 points: the brute-force locate_cell visits every sector per point, which under
  // ASan took 250 s for the 4,900 points this test had (the sanitizer run's limit is 300 s).
  for (int k = 0; k < 1200; ++k)
    points.push_back(glm::mix(glm::dvec3(bounds.min), glm::dvec3(bounds.max), glm::dvec3(u(rng), u(rng), u(rng))));
  for (size_t p = 0; p < world.portals.size(); p += 7) {
    points.push_back(glm::dvec3(world.portals[p].centroid_world));
    for (const glm::vec3& v : world.portals[p].polygon_world) points.push_back(glm::dvec3(v));
  }
  size_t contained = 0;
  for (const glm::dvec3& p : points) {
    const CellLocation a = locate_cell(world, p, volumes), b = locate_cell(world, grid, p, volumes);
    ASSERT_EQ(a.cell, b.cell) << p.x << "," << p.y << "," << p.z;
    ASSERT_EQ(a.reason, b.reason);
    ASSERT_EQ(a.distance_m, b.distance_m);
    contained += a.reason == LocateReason::Containment;
  }
  EXPECT_GT(contained, points.size() / 4) << "most points should lie in some sector";
}

}  // namespace
}  // namespace lintel
