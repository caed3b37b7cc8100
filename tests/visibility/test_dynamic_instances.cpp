// Moving instances (dynamic_instances.h): membership by centre crossings, reach re-derived per move,
// the dirty list, the builder's fast path, moving back restores the state, doors and reach, and an
// object carried through three rooms in front of a walking camera.
#include "ray_walk.h"
#include "test_worlds.h"

#include <lintel/dynamic_instances.h>
#include <lintel/visibility_builder.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace lintel {
namespace {

using testing::make_chain;
using testing::TestWorld;

// A 0.4 m cube (mesh space [-0.2, 0.2]^3) added to a chain world in room 0 at layout (2, 1, 0).
uint32_t add_crate(TestWorld& t) {
  Mesh mesh;
  mesh.name = "crate";
  for (int i = 0; i < 8; ++i)
    mesh.positions.push_back({(i & 1) ? 0.2f : -0.2f, (i & 2) ? 0.2f : -0.2f, (i & 4) ? 0.2f : -0.2f});
  mesh.bounds_mesh.extend(glm::vec3(-0.2f));
  mesh.bounds_mesh.extend(glm::vec3(0.2f));
  t.world.meshes.push_back(mesh);
  t.world.groups.push_back({uint32_t(t.world.meshes.size() - 1), {}});
  Instance inst;
  inst.name = "crate";
  inst.cell = 0;
  inst.mesh = uint32_t(t.world.meshes.size() - 1);
  inst.group = uint32_t(t.world.groups.size() - 1);
  inst.mesh_to_world = glm::translate(t.layout_to_world, glm::vec3(2.0f, 1.0f, 0.0f));
  t.world.instances.push_back(inst);
  EXPECT_TRUE(finalize_world(t.world).ok());
  return uint32_t(t.world.instances.size() - 1);
}

glm::mat4 at_layout(const TestWorld& t, const glm::vec3& p) { return glm::translate(t.layout_to_world, p); }

std::vector<uint32_t> reach_of(const InstanceReach& r, uint32_t i) { return {r.begin(i), r.end(i)}; }

// Every derived field a move touches agrees with what finalize_world() and a fresh
// InstanceReach::compute() derive from the moved world.
void expect_consistent(const World& world, const DynamicInstances& movers) {
  World fresh = world;
  ASSERT_TRUE(finalize_world(fresh).ok());
  for (size_t c = 0; c < world.cells.size(); ++c) EXPECT_EQ(world.cells[c].instances, fresh.cells[c].instances) << c;
  InstanceReach reach;
  reach.compute(world);
  for (uint32_t i = 0; i < world.instances.size(); ++i) {
    EXPECT_EQ(world.instances[i].bounds_world.min, fresh.instances[i].bounds_world.min);
    EXPECT_EQ(world.instances[i].bounds_world.max, fresh.instances[i].bounds_world.max);
    EXPECT_EQ(reach_of(movers.reach(), i), reach_of(reach, i)) << "instance " << i;
  }
}

// Carried along the chain's axis through doors at x = 4 and 8 (layout), the crate's cell changes
// exactly when its centre is past each door plane (beyond the hysteresis band, < 1 mm), by a
// portal crossing; while the box straddles a door (|x - door| < 0.2 m) it reaches both rooms.
TEST(DynamicInstances, CarriedThroughTwoDoorsChangesCellAtEachCrossing) {
  TestWorld t = make_chain(3);
  const uint32_t crate = add_crate(t);
  DynamicInstances movers;
  ASSERT_TRUE(movers.reset(t.world).ok());
  int crossings = 0;
  for (int step = 1; step <= 80; ++step) {
    const float x = 2.0f + 0.1f * float(step);
    ASSERT_TRUE(movers.move(t.world, crate, at_layout(t, {x, 1.0f, 0.0f})).ok());
    crossings += int(movers.last_crossings().size());
    EXPECT_FALSE(movers.last_relocated()) << "x " << x;
    const uint32_t expected = x < 4.0f ? 0 : x < 8.0f ? 1 : 2;
    if (std::abs(x - 4.0f) > 1e-3f && std::abs(x - 8.0f) > 1e-3f) {
      EXPECT_EQ(t.world.instances[crate].cell, expected) << "x " << x;
    }
    const std::vector<uint32_t> reach = reach_of(movers.reach(), crate);
    for (float door : {4.0f, 8.0f})
      if (std::abs(x - door) < 0.19f) {
        EXPECT_EQ(reach.size(), 2u) << "x " << x << ": a box straddling a door reaches both rooms";
      }
    expect_consistent(t.world, movers);
  }
  EXPECT_EQ(crossings, 2);
  EXPECT_EQ(t.world.instances[crate].cell, 2u);
}

// Moving an instance anywhere (by steps, through doors, or by a jump) and back along the same
// path restores the World's instance fields, the cells' lists, its reach and the visible set bit
// for bit; the dirty list names it once.
TEST(DynamicInstances, MovingAndMovingBackRestoresTheState) {
  TestWorld t = make_chain(3, {.furnish = true});
  const uint32_t crate = add_crate(t);
  const World before = t.world;
  DynamicInstances movers;
  ASSERT_TRUE(movers.reset(t.world).ok());
  const View view = t.view({0.5f, 1.5f, 0.3f}, {12.0f, 1.0f, 0.0f});
  VisibilityBuilder builder;
  VisibleSet start, end;
  ASSERT_TRUE(builder.build(t.world, view, 0, {}, start).ok());
  const InstanceReach reach_before = movers.reach();
  std::vector<glm::vec3> path;
  for (int step = 0; step <= 30; ++step) path.push_back({2.0f + 0.25f * float(step), 1.0f, 0.1f * float(step % 3)});
  path.push_back({5.0f, 2.5f, 1.5f});  // a jump (> 2 m) inside room 1
  for (const glm::vec3& p : path) ASSERT_TRUE(movers.move(t.world, crate, at_layout(t, p)).ok());
  for (auto it = path.rbegin() + 1; it != path.rend(); ++it)
    ASSERT_TRUE(movers.move(t.world, crate, at_layout(t, *it)).ok());
  ASSERT_TRUE(movers.move(t.world, crate, before.instances[crate].mesh_to_world).ok());
  const std::span<const uint32_t> moved = movers.take_moved();
  ASSERT_EQ(std::vector<uint32_t>(moved.begin(), moved.end()), std::vector<uint32_t>{crate});
  builder.instances_moved(t.world, movers);
  for (size_t i = 0; i < before.instances.size(); ++i) {
    EXPECT_EQ(t.world.instances[i].mesh_to_world, before.instances[i].mesh_to_world);
    EXPECT_EQ(t.world.instances[i].bounds_world.min, before.instances[i].bounds_world.min);
    EXPECT_EQ(t.world.instances[i].bounds_world.max, before.instances[i].bounds_world.max);
    EXPECT_EQ(t.world.instances[i].cell, before.instances[i].cell);
    EXPECT_EQ(reach_of(movers.reach(), uint32_t(i)), reach_of(reach_before, uint32_t(i)));
  }
  for (size_t c = 0; c < before.cells.size(); ++c) EXPECT_EQ(t.world.cells[c].instances, before.cells[c].instances);
  ASSERT_TRUE(builder.build(t.world, view, 0, {}, end).ok());
  end.stats.instances_tested = start.stats.instances_tested;  // the crate is now tested in the mover slots
  EXPECT_EQ(end, start);
}

// The dirty list: each moved instance once, ascending, then empty until the next move.
TEST(DynamicInstances, TakeMovedListsEachMovedInstanceOnceAscending) {
  TestWorld t = make_chain(3, {.furnish = true});
  DynamicInstances movers;
  ASSERT_TRUE(movers.reset(t.world).ok());
  for (uint32_t i : {2u, 0u, 2u, 1u, 0u}) {
    glm::mat4 m = t.world.instances[i].mesh_to_world;
    m[3] += glm::vec4(0.01f, 0.0f, 0.0f, 0.0f);
    ASSERT_TRUE(movers.move(t.world, i, m).ok());
  }
  const std::span<const uint32_t> moved = movers.take_moved();
  EXPECT_EQ(std::vector<uint32_t>(moved.begin(), moved.end()), (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(movers.taken_through(), t.world.instance_moves);
  EXPECT_EQ(movers.take_moved().size(), 0u);
}

// Bad input is an error and changes nothing: an index out of range, NaN, a projective matrix.
TEST(DynamicInstances, BadTransformsAreErrorsAndChangeNothing) {
  TestWorld t = make_chain(2, {.furnish = true});
  const World before = t.world;
  DynamicInstances movers;
  ASSERT_TRUE(movers.reset(t.world).ok());
  EXPECT_EQ(movers.move(t.world, 99, glm::mat4(1.0f)).kind(), StatusKind::BadInput);
  glm::mat4 nan(1.0f);
  nan[3][0] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(movers.move(t.world, 0, nan).ok());
  glm::mat4 projective(1.0f);
  projective[2][3] = -1.0f;
  EXPECT_FALSE(movers.move(t.world, 0, projective).ok());
  EXPECT_EQ(t.world.instances[0].mesh_to_world, before.instances[0].mesh_to_world);
  EXPECT_EQ(t.world.instance_moves, 0u);
  EXPECT_TRUE(movers.take_moved().empty());
}

// A jump (a move of the centre longer than jump_distance_m) re-locates by containment, also into
// a room that no portal of the old one leads to; a centre pushed through a wall lands in the room
// that contains it (found elsewhere), not the stale one.
TEST(DynamicInstances, JumpsAndWallsRelocateByContainment) {
  TestWorld t = make_chain(3);
  const uint32_t crate = add_crate(t);
  DynamicInstances movers;
  ASSERT_TRUE(movers.reset(t.world).ok());
  ASSERT_TRUE(movers.move(t.world, crate, at_layout(t, {10.0f, 1.0f, 0.0f})).ok());
  EXPECT_TRUE(movers.last_relocated());
  EXPECT_EQ(t.world.instances[crate].cell, 2u);
  // Back to room 1 through the wall beside the door (z = 1.5 is outside the door's [-0.6, 0.6]).
  ASSERT_TRUE(movers.move(t.world, crate, at_layout(t, {8.5f, 1.0f, 1.5f})).ok());
  ASSERT_TRUE(movers.move(t.world, crate, at_layout(t, {7.5f, 1.0f, 1.5f})).ok());
  EXPECT_TRUE(movers.last_crossings().empty());
  EXPECT_EQ(t.world.instances[crate].cell, 1u);
  expect_consistent(t.world, movers);
}

// The builder's fast path (instances_moved with the dirty list) and a builder never told (it sees
// World::instance_moves change and re-derives) give the same VisibleSet as a fresh builder, frame
// after frame, while every table of a furnished grid moves.
TEST(DynamicInstances, TheBuilderFastPathMatchesAFreshBuilder) {
  TestWorld t = testing::make_grid(3, 3, {.furnish = true});
  DynamicInstances movers;
  ASSERT_TRUE(movers.reset(t.world).ok());
  VisibilityBuilder told, untold;
  VisibleSet a, b, c;
  const View view = t.view({2.0f, 1.6f, 2.0f}, {9.0f, 0.5f, 10.0f}, 90.0f);
  ASSERT_TRUE(told.build(t.world, view, 0, {}, a).ok());
  ASSERT_TRUE(untold.build(t.world, view, 0, {}, b).ok());
  const std::vector<Instance> start = t.world.instances;
  for (int frame = 1; frame <= 40; ++frame) {
    for (uint32_t i = 0; i < start.size(); ++i) {
      if ((frame + int(i)) % 3 == 0) continue;  // not every instance every frame
      const glm::vec3 drift(0.09f * float(frame) * (i % 2 ? 1.0f : -1.0f), 0.0f, 0.05f * float(frame));
      ASSERT_TRUE(
          movers.move(t.world, i, glm::translate(glm::mat4(1.0f), t.dir_to_world(drift)) * start[i].mesh_to_world)
              .ok());
    }
    movers.take_moved();
    told.instances_moved(t.world, movers);
    VisibilityBuilder fresh;
    ASSERT_TRUE(told.build(t.world, view, 0, {}, a).ok());
    ASSERT_TRUE(untold.build(t.world, view, 0, {}, b).ok());
    ASSERT_TRUE(fresh.build(t.world, view, 0, {}, c).ok());
    EXPECT_EQ(a.instances, c.instances) << "frame " << frame;
    EXPECT_EQ(b.instances, c.instances) << "frame " << frame;
  }
}

// Doors and reach. Reach is where the box is, so a crate straddling door 0 is listed from room 1
// (looking at the door from room 1) whether the door is open or closed — the part past the door
// plane is in room 1. A crate wholly in room 0 behind the closed door is not listed from room 1.
TEST(DynamicInstances, ReachIgnoresDoorsButSightDoesNot) {
  TestWorld t = make_chain(2);
  const uint32_t crate = add_crate(t);
  DynamicInstances movers;
  ASSERT_TRUE(movers.reset(t.world).ok());
  const View view = t.view({7.0f, 1.2f, 0.0f}, {0.0f, 1.0f, 0.0f});
  VisibilityBuilder builder;
  VisibleSet visible;
  auto listed = [&] {
    movers.take_moved();
    builder.instances_moved(t.world, movers);
    EXPECT_TRUE(builder.build(t.world, view, 1, {}, visible).ok());
    return std::binary_search(visible.instances.begin(), visible.instances.end(), crate);
  };
  ASSERT_TRUE(movers.move(t.world, crate, at_layout(t, {3.9f, 1.0f, 0.0f})).ok());  // straddles x = 4
  EXPECT_EQ(t.world.instances[crate].cell, 0u);
  EXPECT_TRUE(listed());
  t.world.set_portal_open(0, false);
  EXPECT_TRUE(listed()) << "the part in room 1 is still there";
  ASSERT_TRUE(movers.move(t.world, crate, at_layout(t, {3.0f, 1.0f, 0.0f})).ok());  // wholly in room 0
  EXPECT_FALSE(listed());
  t.world.set_portal_open(0, true);
  EXPECT_TRUE(listed());
}

// The carry walk: a camera walks behind a crate carried from room 0 through rooms 1 and 2 of a
// chain (non-identity cell frames), 1.5 m ahead of the eye. On every frame: the crate is listed
// (the ray from the eye to its centre walks through open doors into the cell holding the centre:
// the centre is seen, so a miss would be a false negative), and every cell the crate is listed
// from reaches it geometrically: its box overlaps that cell's volume bounds. Then door 1 closes
// with the crate in room 2 and the camera in room 0: the crate is no longer listed (no cell it
// reaches is visible).
TEST(DynamicInstances, ACarriedObjectNeverVanishesAndIsListedOnlyFromCellsItReaches) {
  TestWorld t = make_chain(3);
  const uint32_t crate = add_crate(t);
  DynamicInstances movers;
  ViewerTracker tracker;
  ASSERT_TRUE(movers.reset(t.world).ok());
  VisibilityBuilder builder;
  VisibleSet visible;
  int frames = 0, oracle_confirms = 0;
  // Steps of 5 cm from 0.513 m: the eye never stands within 1 cm of a door plane (x = 4, 8), where
  // the ray-walk oracle below cannot tell which side the eye is on (the eye-on-plane cases have
  // their own tests: test_viewer_tracker, test_tracker_hysteresis).
  for (int step = 0; 0.513f + 0.05f * float(step) <= 9.0f; ++step, ++frames) {
    const float x = 0.513f + 0.05f * float(step);
    const glm::vec3 eye(x, 1.4f, 0.05f), carried(x + 1.5f, 1.0f, 0.0f);
    ASSERT_TRUE(movers.move(t.world, crate, at_layout(t, carried)).ok());
    movers.take_moved();
    builder.instances_moved(t.world, movers);
    const View view = t.view(eye, carried + glm::vec3(1.0f, 0.0f, 0.0f));
    ASSERT_TRUE(frames == 0 ? tracker.reset(t.world, view.eye_world).ok()
                            : tracker.update(t.world, view.eye_world).ok());
    ASSERT_TRUE(builder.build(t.world, view, tracker.cell(), {}, visible).ok());
    const glm::dmat4 vp = view_projection_d(view);
    const glm::dvec4 clip = vp * glm::dvec4(glm::dvec3(t.world.instances[crate].bounds_world.center()), 1.0);
    const glm::dvec2 ndc(clip.x / clip.w, clip.y / clip.w);
    const testing::RayWalk walk = testing::walk_view_ray(t.world, view, tracker.cell(), ndc);
    const bool centre_seen = std::find(walk.seen_cells.begin(), walk.seen_cells.end(), t.world.instances[crate].cell) !=
                             walk.seen_cells.end();
    // The oracle's own check that the frame tests what it means to (the centre is seen through
    // the doors). Its ray walk is fragile a few cm from a door plane in the clang sanitize build
    // (not under GCC), so it is counted, not asserted per frame; the listing below is asserted on
    // every frame regardless.
    oracle_confirms += centre_seen || walk.ambiguous;
    EXPECT_TRUE(std::binary_search(visible.instances.begin(), visible.instances.end(), crate)) << "x " << x;
    for (const uint32_t* c = movers.reach().begin(crate); c != movers.reach().end(crate); ++c) {
      const Cell& cell = t.world.cells[*c];
      EXPECT_TRUE(boxes_overlap(t.world.instances[crate].bounds_world,
                                transform_aabb(cell.cell_to_world, cell.volume_box_cell)))
          << "x " << x << " cell " << *c;
    }
  }
  EXPECT_EQ(t.world.instances[crate].cell, 2u);
  EXPECT_GT(frames, 150);
  EXPECT_GE(oracle_confirms, frames * 9 / 10) << "the ray oracle must confirm the crate is seen on most frames";
  const View back = t.view({2.0f, 1.4f, 0.0f}, {12.0f, 1.0f, 0.0f});
  ASSERT_TRUE(builder.build(t.world, back, 0, {}, visible).ok());
  EXPECT_TRUE(std::binary_search(visible.instances.begin(), visible.instances.end(), crate));
  t.world.set_portal_open(1, false);
  ASSERT_TRUE(builder.build(t.world, back, 0, {}, visible).ok());
  EXPECT_FALSE(std::binary_search(visible.instances.begin(), visible.instances.end(), crate));
}

}  // namespace
}  // namespace lintel
