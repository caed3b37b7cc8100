// CellVolumeIndex (cell_volume_index.cpp) answers as cell_volume_contains, the exact reference it
// shortcuts, for every point asked: the committed scenes and a random one (random points, vertices,
// face centroids and a hair off them), a subdivided box filed in a grid (faces, edges, corners,
// NaN points and a NaN vertex), and, where Freedoom is installed, E1M5's 2,804 portals probed as
// the loader orients them (the volume-probe rule of docs/scene-format.md, at its three steps and
// others down to a millionth of the portal's size) from both cells, with the points where the ray
// is ambiguous (and the exact winding number decides) counted to show they were reached.
#include "point_in_volume.h"
#include "volume_probes.h"

#include <lintel/cell_locate.h>
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace lintel {
namespace {

struct Tally {
  size_t points = 0, inside = 0, ambiguous = 0;
};

// Both answers for p_world in cell c; the ray's ambiguity (cell space) counted.
void expect_same(const World& world, const CellVolumeIndex& index, uint32_t c, const glm::dvec3& p_world,
                 const std::string& label, Tally& tally) {
  const bool reference = cell_volume_contains(world, c, p_world);
  ASSERT_EQ(index.contains(world, c, p_world), reference)
      << label << " cell " << world.cells[c].name << " at " << p_world.x << "," << p_world.y << "," << p_world.z;
  ++tally.points;
  tally.inside += reference;
  const Cell& cell = world.cells[c];
  if (cell.volume_triangles_cell.empty()) return;
  const glm::dvec3 p = glm::dvec3(glm::dmat4(cell.world_to_cell) * glm::dvec4(p_world, 1.0));
  tally.ambiguous += !volume_winding_by_ray(cell, p).has_value();
}

// Random points in each volume's box (widened 10 %), its vertices, face centroids and points a
// hair in front of and behind them.
void check_world(const World& world, const std::string& label, uint32_t random_points_per_cell, Tally& tally) {
  CellVolumeIndex index;
  index.build(world);
  std::mt19937_64 rng(11);
  for (uint32_t c = 0; c < world.cells.size(); ++c) {
    const Cell& cell = world.cells[c];
    const std::vector<glm::dvec3> points = testing::volume_probe_points(cell, random_points_per_cell, 800, true, rng);
    for (const glm::dvec3& p : points)
      expect_same(world, index, c, glm::dvec3(glm::dmat4(cell.cell_to_world) * glm::dvec4(p, 1.0)), label, tally);
  }
}

TEST(CellVolumeIndex, AnswersAsCellVolumeContainsOnCommittedScenes) {
  Tally tally;
  const auto worlds = testing::committed_and_random_worlds();
  ASSERT_EQ(worlds.size(), 4u);
  for (const auto& [name, world] : worlds) check_world(world, name, 200, tally);
  EXPECT_GT(tally.inside, tally.points / 10);
  EXPECT_GT(tally.ambiguous, 0u) << "points on vertices and edges must reach the exact sum";
}

// A 1 m box of 6 x 2 x 6 x 6 triangles (enough for a grid), rotated and moved into the world.
World subdivided_box_world() {
  World world;
  Cell cell;
  cell.name = "box";
  cell.cell_to_world =
      glm::mat4(glm::mat3(glm::vec3(0.6f, 0.8f, 0.0f), glm::vec3(-0.8f, 0.6f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f)));
  cell.cell_to_world[3] = glm::vec4(10.0f, -3.0f, 2.0f, 1.0f);
  cell.world_to_cell = glm::inverse(cell.cell_to_world);
  constexpr int n = 6;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side)
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          auto corner = [&](int di, int dj) {
            glm::vec3 p;
            p[axis] = float(side);
            p[(axis + 1) % 3] = float(i + di) / n;
            p[(axis + 2) % 3] = float(j + dj) / n;
            return p;
          };
          const glm::vec3 a = corner(0, 0), b = corner(1, 0), c = corner(1, 1), d = corner(0, 1);
          for (const glm::vec3& v :
               side ? std::vector<glm::vec3>{a, b, c, a, c, d} : std::vector<glm::vec3>{a, c, b, a, d, c})
            cell.volume_triangles_cell.push_back(v);
        }
  for (const glm::vec3& v : cell.volume_triangles_cell) cell.volume_box_cell.extend(v);
  world.cells.push_back(cell);
  return world;
}

TEST(CellVolumeIndex, AnswersAsCellVolumeContainsOnAGridBoxWithNaNs) {
  World world = subdivided_box_world();
  Tally tally;
  check_world(world, "box", 3000, tally);
  // On the grid's own lines: every vertex of the subdivision, and the box's faces, edges, corners.
  CellVolumeIndex index;
  index.build(world);
  for (int x = 0; x <= 6; ++x)
    for (int y = 0; y <= 6; ++y)
      for (int z = 0; z <= 6; ++z) {
        const glm::dvec3 p(x / 6.0, y / 6.0, z / 6.0);
        expect_same(world, index, 0, glm::dvec3(glm::dmat4(world.cells[0].cell_to_world) * glm::dvec4(p, 1.0)),
                    "lattice", tally);
      }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expect_same(world, index, 0, glm::dvec3(nan, 0.0, 0.0), "NaN point", tally);
  expect_same(world, index, 0, glm::dvec3(10.3, nan, 2.5), "NaN point", tally);
  EXPECT_GT(tally.ambiguous, 0u);
  // A NaN vertex: the index files nothing for that cell and every triangle meets the ray as before.
  world.cells[0].volume_triangles_cell[40].y = std::numeric_limits<float>::quiet_NaN();
  check_world(world, "box with a NaN vertex", 1000, tally);
}

TEST(CellVolumeIndex, AnswersAsCellVolumeContainsAtTheOrientationProbesOfADoomMap) {
  if (!std::filesystem::exists(testing::kFreedoomWad))
    GTEST_SKIP() << testing::kFreedoomWad << " not installed (Debian package freedoom)";
  World world;
  ASSERT_TRUE(testing::import_freedoom_map("E1M5", world).ok());
  ASSERT_EQ(world.portals.size(), 2831u);  // whole sectors, 13 sealed platforms lowered (docs/levels.md)
  CellVolumeIndex index;
  index.build(world);
  Tally tally;
  for (const Portal& portal : world.portals) {
    const glm::dvec3 centroid(portal.centroid_world), normal(portal.normal_world);
    double size = 0.0;
    for (const glm::vec3& a : portal.polygon_world)
      for (const glm::vec3& b : portal.polygon_world)
        size = std::max(size, glm::distance(glm::dvec3(a), glm::dvec3(b)));
    std::vector<glm::dvec3> points;
    for (double fraction : {1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 5e-2, 0.2})
      for (double side : {-1.0, 1.0}) points.push_back(centroid + side * fraction * size * normal);
    for (size_t v = 0; v < portal.polygon_world.size(); ++v) {
      const glm::dvec3 a(portal.polygon_world[v]), b(portal.polygon_world[(v + 1) % portal.polygon_world.size()]);
      for (double side : {-1.0, 1.0}) {
        points.push_back(a + side * 1e-3 * size * normal);
        points.push_back((a + b) / 2.0 + side * 1e-3 * size * normal);
      }
    }
    for (const glm::dvec3& p : points)
      for (uint32_t c : {portal.from, portal.to}) expect_same(world, index, c, p, portal.name, tally);
  }
  EXPECT_GT(tally.inside, tally.points / 3);
  EXPECT_GT(tally.ambiguous, 0u) << "some probes should reach the exact winding number";
}

}  // namespace
}  // namespace lintel
