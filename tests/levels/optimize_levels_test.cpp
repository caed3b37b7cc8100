// `lintel optimize` against the ray-cast ground truth: on Freedoom maps (skipped without the WAD)
// and on a generated scene, the merged scene loads, has fewer cells, its doorway walk does not
// flap, and no view misses a cell or instance the Embree ray cast sees.
#include "timeline_walk.h"

#include <lintel/reference/accuracy_bench.h>
#include <lintel/reference/bench_views.h>
#include <lintel/cell_locate.h>
#include <lintel/reference/cull_method.h>
#include <lintel/doom_import.h>
#include <lintel/optimize.h>
#include <lintel/reference/ray_ground_truth.h>
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>
#include <lintel/timeline.h>
#include <lintel/viewer_tracker.h>
#include <lintel/visibility_builder.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace lintel {
namespace {

const char* const kWad = "/usr/share/games/doom/freedoom1.wad";

bool optimized_world(const SceneDesc& scene, const std::string& label, World& world, OptimizeReport& report) {
  SceneDesc merged;
  const Status s = optimize_scene(scene, label, {}, merged, &report);
  EXPECT_TRUE(s.ok()) << s.message();
  if (!s) return false;
  const Status loaded = build_world(merged, label + " optimized", world);
  EXPECT_TRUE(loaded.ok()) << loaded.message();
  return loaded.ok();
}

// Property: every cell and instance some ground-truth ray hits (128 x 128 rays, `views` views) is
// in the visible set (default options). Drawn but unseen cells are over-inclusion, accepted.
void expect_no_false_negatives(const World& world, const std::string& label, uint32_t views_wanted) {
  AccuracyScene scene;
  scene.label = label;
  scene.world = world;
  RayGroundTruth rays;
  ASSERT_TRUE(rays.build(scene.world).ok());
  std::vector<BenchView> views = make_bench_views(scene.world, rays, views_wanted, 1);
  // A view at a portal may stand beyond a thin cell (0.3 m off the plane): root it in the cell that
  // holds the eye, as `bench levels` does (docs/levels.md).
  for (BenchView& v : views)
    if (!cell_volume_contains(scene.world, v.start_cell, glm::dvec3(v.view.eye_world)))
      v.start_cell = locate_cell(scene.world, glm::dvec3(v.view.eye_world)).cell;
  EXPECT_GE(views.size(), views_wanted * 5 / 6);
  std::vector<std::unique_ptr<CullMethod>> methods;
  methods.push_back(make_polygon_method(kDefaultSnapLatticeCells, 16));
  std::vector<MethodScore> scores;
  ASSERT_TRUE(score_scene(scene, rays, views, methods, 128, scores).ok());
  ASSERT_EQ(scores.size(), 1u);
  EXPECT_EQ(scores[0].cell_false_negatives, 0u)
      << (scores[0].false_negative_examples.empty() ? "" : scores[0].false_negative_examples[0]);
  EXPECT_EQ(scores[0].instance_false_negatives, 0u);
  EXPECT_GT(scores[0].true_cells, 0u);
}

// Property: along the doorway timeline the tracked cell never returns to the cell it just left
// within 3 frames, and every frame's visible set holds the viewer's cell.
void expect_walk_without_flaps(const World& world) {
  test::WalkCounts walk;
  test::walk_first_timeline(world, walk);
  if (::testing::Test::HasFatalFailure()) return;
  EXPECT_EQ(walk.flaps, 0u);
}

TEST(OptimizeLevels, FreedoomMapsMergeWithoutFalseNegativesOrFlaps) {
  if (!std::filesystem::exists(kWad)) GTEST_SKIP() << kWad << " is missing (apt-get install freedoom)";
  for (const char* map : {"E1M1", "E1M8"}) {
    SCOPED_TRACE(map);
    SceneDesc scene;
    ASSERT_TRUE(import_doom(kWad, map, {}, scene).ok());
    World world;
    OptimizeReport report;
    ASSERT_TRUE(optimized_world(scene, map, world, report));
    EXPECT_LT(report.cells_after, report.cells_before);
    EXPECT_LT(report.portals_after, report.portals_before);
    EXPECT_EQ(world.cells.size(), report.cells_after);
    expect_walk_without_flaps(world);
    expect_no_false_negatives(world, map, 120);
  }
}

// With doors closed every door portal survives the merge, still closed.
TEST(OptimizeLevels, ClosedDoorsSurviveTheMerge) {
  if (!std::filesystem::exists(kWad)) GTEST_SKIP() << kWad << " is missing (apt-get install freedoom)";
  DoomImportOptions closed;
  closed.doors_open = false;
  SceneDesc scene;
  ASSERT_TRUE(import_doom(kWad, "E1M1", closed, scene).ok());
  World before;
  ASSERT_TRUE(build_world(scene, "E1M1 closed", before).ok());
  World after;
  OptimizeReport report;
  ASSERT_TRUE(optimized_world(scene, "E1M1 closed", after, report));
  size_t closed_before = 0;
  for (uint32_t p = 0; p < before.portals.size(); ++p) {
    if (before.portal_open(p, PortalDirection::FromTo)) continue;
    ++closed_before;
    const int q = after.find_portal(before.portals[p].name);
    ASSERT_GE(q, 0) << before.portals[p].name;
    EXPECT_FALSE(after.portal_open(uint32_t(q), PortalDirection::FromTo));
  }
  EXPECT_GT(closed_before, 0u);
  EXPECT_EQ(report.closable_portals, closed_before);
}

TEST(OptimizeLevels, GeneratedSceneKeepsNoFalseNegatives) {
  RandomOptions options;
  options.cells = 24;
  options.seed = 7;
  World world;
  OptimizeReport report;
  ASSERT_TRUE(optimized_world(generate_random(options), "random", world, report));
  EXPECT_EQ(world.cells.size(), report.cells_after);
  expect_no_false_negatives(world, "random", 60);
}

}  // namespace
}  // namespace lintel
