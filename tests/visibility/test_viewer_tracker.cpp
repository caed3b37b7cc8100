// The viewer tracker: portal crossings, stickiness, no flap, and the containment / nearest
// fallbacks (cell_locate.h).
#include "test_worlds.h"

#include <lintel/cell_locate.h>
#include <lintel/doorway_rule.h>
#include <lintel/viewer_tracker.h>
#include <lintel/visibility_builder.h>

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <vector>

namespace lintel {
namespace {

using testing::make_chain;
using testing::TestWorld;
using testing::WorldBuilder;
using testing::WorldOptions;

// Chain rooms: room i spans layout x in [4i, 4i + 4]; doors at x = 4(i + 1), |z| <= 0.6, y in [0, 2.2].
TEST(ViewerTracker, WalkingThroughADoorSwitchesExactlyOnce) {
  const TestWorld t = make_chain(3);
  ViewerTracker tracker;
  ASSERT_TRUE(tracker.reset(t.world, t.to_world({2.0f, 1.2f, 0.1f})).ok());
  EXPECT_EQ(tracker.cell(), 0u);
  ASSERT_EQ(tracker.transitions().size(), 1u);
  EXPECT_EQ(tracker.transitions()[0].from, kNoCell);
  EXPECT_EQ(tracker.transitions()[0].reason, TransitionReason::Containment);
  int switches = 0;
  for (float x = 2.25f; x <= 6.0f; x += 0.25f) {
    ASSERT_TRUE(tracker.update(t.world, t.to_world({x, 1.2f, 0.1f})).ok());
    for (const CellTransition& tr : tracker.transitions()) {
      ++switches;
      EXPECT_EQ(tr, (CellTransition{0, 1, TransitionReason::PortalCrossing, 0}));
    }
    EXPECT_EQ(tracker.cell(), x > 4.0f ? 1u : 0u) << "x " << x;
  }
  EXPECT_EQ(switches, 1);
}

TEST(ViewerTracker, FollowsSeveralCrossingsInOneMoveInOrder) {
  const TestWorld t = make_chain(5);
  TrackerOptions o;
  o.jump_distance_m = 50.0f;
  ViewerTracker tracker(o);
  ASSERT_TRUE(tracker.reset(t.world, t.to_world({1.0f, 1.0f, 0.0f})).ok());
  ASSERT_TRUE(tracker.update(t.world, t.to_world({15.0f, 1.0f, 0.2f})).ok());
  EXPECT_EQ(tracker.cell(), 3u);
  const std::vector<CellTransition> expected = {{0, 1, TransitionReason::PortalCrossing, 0},
                                                {1, 2, TransitionReason::PortalCrossing, 1},
                                                {2, 3, TransitionReason::PortalCrossing, 2}};
  EXPECT_EQ(std::vector<CellTransition>(tracker.transitions().begin(), tracker.transitions().end()), expected);
  // And back in one move.
  ASSERT_TRUE(tracker.update(t.world, t.to_world({1.0f, 1.0f, -0.3f})).ok());
  EXPECT_EQ(tracker.cell(), 0u);
  EXPECT_EQ(tracker.transitions().size(), 3u);
}

TEST(ViewerTracker, CrossingsPerMoveAreBoundedThenContainmentTakesOver) {
  const TestWorld t = make_chain(5);
  TrackerOptions o;
  o.jump_distance_m = 50.0f;
  o.max_crossings_per_move = 2;
  ViewerTracker tracker(o);
  ASSERT_TRUE(tracker.reset(t.world, t.to_world({1.0f, 1.0f, 0.0f})).ok());
  ASSERT_TRUE(tracker.update(t.world, t.to_world({15.0f, 1.0f, 0.0f})).ok());
  ASSERT_EQ(tracker.transitions().size(), 3u);
  EXPECT_EQ(tracker.transitions()[1].to, 2u);
  EXPECT_EQ(tracker.transitions()[2], (CellTransition{2, 3, TransitionReason::Containment, kNoCell}));
  EXPECT_EQ(tracker.cell(), 3u);
}

TEST(ViewerTracker, StaysWhenNoPortalIsCrossed) {
  const TestWorld t = make_chain(3);
  ViewerTracker tracker;
  ASSERT_TRUE(tracker.reset(t.world, t.to_world({6.0f, 1.0f, 0.0f})).ok());
  ASSERT_EQ(tracker.cell(), 1u);
  // Wander around the room, brushing the door plane without passing through the door.
  const glm::vec3 path[] = {{7.9f, 1.0f, 1.0f}, {7.99f, 1.0f, 1.5f}, {4.01f, 2.8f, -1.8f}, {5.0f, 0.1f, 1.9f}};
  for (const glm::vec3& p : path) {
    ASSERT_TRUE(tracker.update(t.world, t.to_world(p)).ok());
    EXPECT_TRUE(tracker.transitions().empty());
    EXPECT_EQ(tracker.cell(), 1u);
  }
}

// Property (no flap, real switches): a camera oscillating across a door's plane, jittering along
// it, never switches while the amplitude is within the door's hysteresis band (it stays in the
// cell it was placed in); with a larger amplitude it is in `to` exactly on the frames where its
// signed distance is > 0 and switches once per side change (each passes the band). The visible
// cell set is the same on every frame either way (the doorway rule covers the band).
TEST(ViewerTracker, OscillationSwitchesOnlyBeyondTheBand) {
  WorldOptions wo;
  wo.frame_seed = 5;
  wo.layout_to_world = testing::layout_to_world_centred_at({8.0f, 1.3f, 0.0f});  // resolve 1e-7 m
  const TestWorld t = make_chain(4, wo);
  const Portal& door = t.world.portals[1];  // rooms 1 | 2 at x = 8
  const double band = hysteresis_band_m(door);
  std::mt19937 rng(13);
  std::uniform_real_distribution<float> jitter(-0.3f, 0.3f);
  VisibilityBuilder builder;
  for (double amplitude : {1e-7, 1e-6, 0.5 * band, 0.9 * band, 2.0 * band, 1e-4, 1e-3, 1e-2}) {
    ViewerTracker tracker;
    ASSERT_TRUE(tracker.reset(t.world, t.to_world({7.0f, 1.3f, 0.0f})).ok());
    ASSERT_EQ(tracker.cell(), 1u);
    bool was_to = false;
    std::vector<uint32_t> reference;
    int switches = 0, expected_switches = 0;
    for (int frame = 0; frame < 120; ++frame) {
      const float side = (frame % 3 == 2) ? 1.0f : ((frame % 2) ? 1.0f : -1.0f);  // irregular pattern
      const glm::vec3 eye_layout(8.0f + side * float(amplitude), 1.3f + 0.5f * jitter(rng), 0.5f * jitter(rng));
      const glm::vec3 eye = t.to_world(eye_layout);
      ASSERT_TRUE(tracker.update(t.world, eye).ok());
      const bool is_to = amplitude > band && portal_signed_distance(door, door.from, glm::dvec3(eye)) > 0.0;
      expected_switches += is_to != was_to;
      was_to = is_to;
      EXPECT_EQ(tracker.cell(), is_to ? 2u : 1u) << "amplitude " << amplitude << " frame " << frame;
      for (const CellTransition& tr : tracker.transitions()) {
        ++switches;
        EXPECT_EQ(tr.reason, TransitionReason::PortalCrossing);
        EXPECT_EQ(tr.portal, 1u);
      }
      VisibleSet v;
      ASSERT_TRUE(
          builder.build(t.world, t.view(eye_layout, eye_layout + glm::vec3(1.0f, 0.0f, 0.3f)), tracker.cell(), {}, v)
              .ok());
      std::vector<uint32_t> cells;
      for (const VisibleCell& c : v.cells) cells.push_back(c.cell);
      if (reference.empty()) reference = cells;
      EXPECT_EQ(cells, reference) << "amplitude " << amplitude << " frame " << frame;
    }
    EXPECT_EQ(switches, expected_switches) << "amplitude " << amplitude;
    if (amplitude > band) {
      EXPECT_GT(switches, 40) << "amplitude " << amplitude;
    } else {
      EXPECT_EQ(switches, 0) << "amplitude " << amplitude;
    }
  }
}

TEST(ViewerTracker, WalkingThroughAWallIsLostAndFoundByContainment) {
  const TestWorld t = make_chain(3);
  ViewerTracker tracker;
  ASSERT_TRUE(tracker.reset(t.world, t.to_world({3.5f, 1.0f, 1.5f})).ok());
  ASSERT_EQ(tracker.cell(), 0u);
  ASSERT_TRUE(tracker.update(t.world, t.to_world({4.6f, 1.0f, 1.5f})).ok());  // through the wall beside the door
  EXPECT_EQ(tracker.cell(), 1u);
  ASSERT_EQ(tracker.transitions().size(), 1u);
  EXPECT_EQ(tracker.transitions()[0], (CellTransition{0, 1, TransitionReason::Containment, kNoCell}));
  // Past the hysteresis band into another room's volume it is found there at once (a tracked cell
  // that does not contain the eye would hide the room it stands in): 0.1 m into room 1.
  ViewerTracker found;
  ASSERT_TRUE(found.reset(t.world, t.to_world({3.5f, 1.0f, 1.5f})).ok());
  ASSERT_TRUE(found.update(t.world, t.to_world({4.1f, 1.0f, 1.5f})).ok());
  EXPECT_EQ(found.cell(), 1u);
  // Outside every volume (above the roof) but within the lost tolerance it stays put (sticky).
  ViewerTracker sticky;
  ASSERT_TRUE(sticky.reset(t.world, t.to_world({3.5f, 2.9f, 1.5f})).ok());
  ASSERT_TRUE(sticky.update(t.world, t.to_world({3.5f, 3.1f, 1.5f})).ok());
  EXPECT_EQ(sticky.cell(), 0u);
  EXPECT_TRUE(sticky.transitions().empty());
}

TEST(ViewerTracker, JumpFallsBackToContainment) {
  const TestWorld t = make_chain(5);
  ViewerTracker tracker;
  ASSERT_TRUE(tracker.reset(t.world, t.to_world({1.0f, 1.0f, 0.0f})).ok());
  ASSERT_TRUE(tracker.update(t.world, t.to_world({17.0f, 1.0f, 1.5f})).ok());  // 16 m: a teleport
  EXPECT_EQ(tracker.cell(), 4u);
  ASSERT_EQ(tracker.transitions().size(), 1u);
  EXPECT_EQ(tracker.transitions()[0], (CellTransition{0, 4, TransitionReason::Containment, kNoCell}));
}

TEST(ViewerTracker, OutsideEveryVolumeFallsBackToTheNearestCell) {
  const TestWorld t = make_chain(5);
  ViewerTracker tracker;
  ASSERT_TRUE(tracker.reset(t.world, t.to_world({1.0f, 1.0f, 0.0f})).ok());
  ASSERT_TRUE(tracker.update(t.world, t.to_world({9.0f, 9.0f, 0.5f})).ok());  // above room 2
  EXPECT_EQ(tracker.cell(), 2u);
  ASSERT_EQ(tracker.transitions().size(), 1u);
  EXPECT_EQ(tracker.transitions()[0].reason, TransitionReason::Nearest);
  const CellLocation where = locate_cell(t.world, glm::dvec3(t.to_world({9.0f, 9.0f, 0.5f})));
  EXPECT_EQ(where.reason, LocateReason::Nearest);
  EXPECT_NEAR(where.distance_m, 6.0, 1e-4);
}

TEST(ViewerTracker, BadEyesAreErrorsAndLeaveTheStateAlone) {
  const TestWorld t = make_chain(2);
  ViewerTracker tracker;
  EXPECT_FALSE(tracker.update(t.world, {0.0f, 0.0f, 0.0f}).ok());  // before reset
  ASSERT_TRUE(tracker.reset(t.world, t.to_world({1.0f, 1.0f, 0.0f})).ok());
  const glm::vec3 nan(std::numeric_limits<float>::quiet_NaN());
  EXPECT_FALSE(tracker.update(t.world, nan).ok());
  EXPECT_EQ(tracker.cell(), 0u);
  EXPECT_EQ(tracker.eye_world(), t.to_world({1.0f, 1.0f, 0.0f}));
  EXPECT_FALSE(tracker.reset(t.world, nan).ok());
  World empty;
  EXPECT_FALSE(tracker.reset(empty, {0.0f, 0.0f, 0.0f}).ok());
}

TEST(ViewerTracker, OneWayPortalsAreStillPhysicalOpenings) {
  WorldOptions o;
  o.one_way = true;
  const TestWorld t = make_chain(3, o);
  ViewerTracker tracker;
  ASSERT_TRUE(tracker.reset(t.world, t.to_world({5.0f, 1.0f, 0.0f})).ok());
  ASSERT_EQ(tracker.cell(), 1u);
  ASSERT_TRUE(tracker.update(t.world, t.to_world({3.5f, 1.0f, 0.0f})).ok());  // back through 0 -> 1
  EXPECT_EQ(tracker.cell(), 0u);
  ASSERT_EQ(tracker.transitions().size(), 1u);
  EXPECT_EQ(tracker.transitions()[0].reason, TransitionReason::PortalCrossing);
}

// Several containing volumes: the smallest wins (a closet inside a hall), whichever comes first.
TEST(CellLocate, SmallestContainingVolumeWins) {
  for (bool closet_first : {false, true}) {
    WorldBuilder b(testing::default_layout_to_world(), {});
    const auto add_hall = [&] { return b.add_box_cell("hall", {0, 0, 0}, {10, 3, 10}); };
    const auto add_closet = [&] { return b.add_box_cell("closet", {2, 0, 2}, {3, 2.5f, 3}); };
    const uint32_t first = closet_first ? add_closet() : add_hall();
    const uint32_t second = closet_first ? add_hall() : add_closet();
    const uint32_t closet = closet_first ? first : second, hall = closet_first ? second : first;
    const World w = b.finish();
    const glm::dvec3 in_closet(b.to_world({2.5f, 1.0f, 2.5f})), in_hall(b.to_world({7.0f, 1.0f, 7.0f}));
    EXPECT_EQ(locate_cell(w, in_closet).cell, closet);
    EXPECT_EQ(locate_cell(w, in_hall).cell, hall);
    EXPECT_TRUE(cell_volume_contains(w, hall, in_closet));
    EXPECT_NEAR(cell_volume_m3(w, hall), 300.0, 1e-3);
    EXPECT_NEAR(cell_volume_m3(w, closet), 2.5, 1e-4);
  }
}

// Containment uses the triangle volume, not its bounding box: an L-shaped cell does not contain
// the empty corner of its box.
TEST(CellLocate, TriangleVolumesAreNotTheirBoxes) {
  WorldBuilder b(testing::default_layout_to_world(), {});
  std::vector<glm::vec3> l_shape = testing::box_triangles({0, 0, 0}, {4, 3, 2});
  const std::vector<glm::vec3> leg = testing::box_triangles({0, 0, 2}, {2, 3, 4});
  // Two boxes sharing a face: the shared faces cancel in the winding number.
  l_shape.insert(l_shape.end(), leg.begin(), leg.end());
  const uint32_t c = b.add_cell("l", l_shape, {1, 1, 1});
  const World w = b.finish();
  EXPECT_TRUE(cell_volume_contains(w, c, glm::dvec3(b.to_world({1.0f, 1.0f, 3.0f}))));
  EXPECT_TRUE(cell_volume_contains(w, c, glm::dvec3(b.to_world({3.0f, 1.0f, 1.0f}))));
  EXPECT_FALSE(cell_volume_contains(w, c, glm::dvec3(b.to_world({3.0f, 1.0f, 3.0f}))));
  EXPECT_NEAR(cell_volume_distance_m(w, c, glm::dvec3(b.to_world({3.0f, 1.0f, 3.5f}))), 1.0, 1e-5);
}

}  // namespace
}  // namespace lintel
