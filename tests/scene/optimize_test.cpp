// `lintel optimize` on hand-built scenes (lintel/optimize.h): a stair merges into one cell, a door
// in a wall does not, a thin door cell merges into a neighbour, closable portals (closed, or named
// by a timeline event) are never merged across, and a scene with nothing to merge comes back with
// the same cells, portals, instances and lights.
#include "box_cells.h"

#include <lintel/cell_locate.h>
#include <lintel/optimize.h>
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace lintel {
namespace {

using test::box_mesh;

// A box cell: shell and volume both the box (identity frames).
void add_cell(SceneDesc& scene, const std::string& name, glm::vec3 lo, glm::vec3 hi) {
  test::add_box_cell(scene, name, lo, hi, box_mesh(name, lo, hi));
}

using test::add_portal;

// Three steps 0.2 m apart (1 x 2 m each, ceiling 3 m), their portals over the whole step, then a
// 4 x 4 m hall through a 1 x 2 m door.
SceneDesc stair_and_hall(bool close_middle_step = false) {
  SceneDesc scene;
  add_cell(scene, "s0", {0, 0.0f, 0}, {1, 3, 2});
  add_cell(scene, "s1", {1, 0.2f, 0}, {2, 3, 2});
  add_cell(scene, "s2", {2, 0.4f, 0}, {3, 3, 2});
  add_cell(scene, "hall", {3, 0.4f, -1}, {7, 3, 3});
  add_portal(scene, "p01", "s0", "s1", 1, 0, 2, 0.2f, 3);
  add_portal(scene, "p12", "s1", "s2", 2, 0, 2, 0.4f, 3, !close_middle_step);
  add_portal(scene, "door", "s2", "hall", 3, 0.5f, 1.5f, 0.4f, 2.4f);
  return scene;
}

bool optimize(const SceneDesc& scene, World& out, OptimizeReport& report, const OptimizeOptions& options = {}) {
  SceneDesc merged;
  const Status s = optimize_scene(scene, "test", options, merged, &report);
  EXPECT_TRUE(s.ok()) << s.message();
  if (!s) return false;
  const Status loaded = build_world(merged, "merged", out);
  EXPECT_TRUE(loaded.ok()) << loaded.message();
  return loaded.ok();
}

bool contains(const World& world, const std::string& cell, glm::dvec3 p) {
  const int c = world.find_cell(cell);
  return c >= 0 && cell_volume_contains(world, uint32_t(c), p);
}

TEST(Optimize, StairStepsMergeAndADoorInAWallDoesNot) {
  World world;
  OptimizeReport report;
  ASSERT_TRUE(optimize(stair_and_hall(), world, report));
  EXPECT_EQ(report.cells_before, 4u);
  EXPECT_EQ(report.cells_after, 2u);
  EXPECT_EQ(report.merged_cell_of, (std::vector<uint32_t>{0, 0, 0, 1}));
  ASSERT_EQ(world.cells.size(), 2u);
  ASSERT_EQ(world.portals.size(), 1u);
  EXPECT_EQ(world.portals[0].name, "door");
  // The merged cell is the union of the steps: each step's middle lies in it, the hall's does not.
  for (double x : {0.5, 1.5, 2.5}) EXPECT_TRUE(contains(world, "s0", {x, 1.5, 1.0})) << x;
  EXPECT_FALSE(contains(world, "s0", {5.0, 1.5, 1.0}));
  EXPECT_TRUE(contains(world, "hall", {5.0, 1.5, 1.0}));
  // Its shell is the three step shells (12 triangles each).
  EXPECT_EQ(world.meshes[size_t(world.cells[size_t(world.find_cell("s0"))].shell_mesh)].indices.size(), 3u * 36u);
}

TEST(Optimize, NeverMergesAcrossAClosedPortal) {
  World world;
  OptimizeReport report;
  ASSERT_TRUE(optimize(stair_and_hall(/*close_middle_step=*/true), world, report));
  EXPECT_EQ(report.closable_portals, 1u);
  EXPECT_EQ(report.merged_cell_of, (std::vector<uint32_t>{0, 0, 1, 2}));
  const int p12 = world.find_portal("p12");
  ASSERT_GE(p12, 0);
  EXPECT_FALSE(world.portal_open(uint32_t(p12), PortalDirection::FromTo));
  EXPECT_EQ(world.find_portal("p01"), -1);  // inside the merged cell
}

TEST(Optimize, NeverMergesAcrossAPortalATimelineOpensOrCloses) {
  SceneDesc scene = stair_and_hall();
  Timeline walk;
  walk.name = "walk";
  walk.keys = {{0.0, {0.5f, 1.5f, 1.0f}, {5.0f, 1.5f, 1.0f}}, {1.0, {0.5f, 1.5f, 1.2f}, {5.0f, 1.5f, 1.0f}}};
  walk.events = {{0.5, "p01", false}};
  scene.timelines.push_back(walk);
  World world;
  OptimizeReport report;
  ASSERT_TRUE(optimize(scene, world, report));
  EXPECT_EQ(report.merged_cell_of, (std::vector<uint32_t>{0, 1, 1, 2}));
  ASSERT_EQ(world.timelines.size(), 1u);
  ASSERT_EQ(world.timelines[0].events.size(), 1u);
  EXPECT_EQ(world.timelines[0].events[0].portal_index, world.find_portal("p01"));
}

// Two rooms and a 0.25 m deep door cell between them (a Doom door sector): the door is a sliver
// and joins a room; closed, it stays.
SceneDesc rooms_with_door_cell(bool door_open) {
  SceneDesc scene;
  add_cell(scene, "a", {0, 0, 0}, {4, 3, 4});
  add_cell(scene, "door", {4, 0, 1}, {4.25f, 2.2f, 2});
  add_cell(scene, "b", {4.25f, 0, 0}, {8, 3, 4});
  add_portal(scene, "a_door", "a", "door", 4, 1, 2, 0, 2.2f, door_open);
  add_portal(scene, "door_b", "door", "b", 4.25f, 1, 2, 0, 2.2f, door_open);
  return scene;
}

TEST(Optimize, AThinDoorCellJoinsARoomUnlessItIsClosed) {
  World world;
  OptimizeReport report;
  ASSERT_TRUE(optimize(rooms_with_door_cell(true), world, report));
  EXPECT_EQ(report.sliver_merges, 1u);
  EXPECT_EQ(report.open_wall_merges, 0u);
  EXPECT_EQ(report.merged_cell_of, (std::vector<uint32_t>{0, 0, 1}));
  EXPECT_TRUE(contains(world, "a", {4.1, 1.0, 1.5}));
  ASSERT_EQ(world.portals.size(), 1u);
  EXPECT_EQ(world.portals[0].name, "door_b");

  World closed;
  ASSERT_TRUE(optimize(rooms_with_door_cell(false), closed, report));
  EXPECT_EQ(report.cells_after, 3u);
  EXPECT_EQ(closed.portals.size(), 2u);
}

// With merging switched off the writer alone runs: the cottage (frames, instances, lights,
// textures, a timeline) comes back with every cell, portal, instance and light where it was.
TEST(Optimize, NothingToMergeKeepsTheWorld) {
  World before;
  ASSERT_TRUE(build_world(generate_cottage({}), "cottage", before).ok());
  OptimizeOptions off;
  off.min_open_fraction = 2.0;  // no portal opens more than its whole wall
  off.sliver_volume_m3 = 0.0;
  off.sliver_thickness_m = 0.0;
  SceneDesc merged;
  OptimizeReport report;
  ASSERT_TRUE(optimize_world(before, off, merged, &report).ok());
  World after;
  const Status loaded = build_world(merged, "cottage-optimized", after);
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  ASSERT_EQ(after.cells.size(), before.cells.size());
  ASSERT_EQ(after.portals.size(), before.portals.size());
  ASSERT_EQ(after.instances.size(), before.instances.size());
  ASSERT_EQ(after.lights.size(), before.lights.size());
  ASSERT_EQ(after.groups.size(), before.groups.size());
  EXPECT_EQ(after.timelines.size(), before.timelines.size());
  for (size_t c = 0; c < before.cells.size(); ++c) EXPECT_EQ(after.cells[c].name, before.cells[c].name);
  for (size_t p = 0; p < before.portals.size(); ++p) {
    EXPECT_EQ(after.portals[p].name, before.portals[p].name);
    EXPECT_EQ(after.portals[p].from, before.portals[p].from);
    EXPECT_EQ(after.portals[p].to, before.portals[p].to);
    EXPECT_LT(glm::length(after.portals[p].centroid_world - before.portals[p].centroid_world), 1e-4f);
  }
  // Instances and lights are written cell by cell, so their order may change: match each by name,
  // cell and place.
  auto near = [](glm::vec3 a, glm::vec3 b) { return glm::length(a - b) < 1e-4f; };
  for (const Instance& was : before.instances) {
    size_t matches = 0;
    for (const Instance& is : after.instances)
      matches += is.name == was.name && after.cells[is.cell].name == before.cells[was.cell].name &&
                 after.meshes[is.mesh].name == before.meshes[was.mesh].name &&
                 near(is.bounds_world.min, was.bounds_world.min) && near(is.bounds_world.max, was.bounds_world.max);
    EXPECT_EQ(matches, 1u) << was.name;
  }
  for (const Light& was : before.lights) {
    size_t matches = 0;
    for (const Light& is : after.lights)
      matches += is.name == was.name && after.cells[is.cell].name == before.cells[was.cell].name &&
                 near(is.position_world, was.position_world) && near(is.direction_world, was.direction_world);
    EXPECT_EQ(matches, 1u) << was.name;
  }
}

}  // namespace
}  // namespace lintel
