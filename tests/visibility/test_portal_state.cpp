// Run-time world changes: door state (portals open/closed per direction), timeline door events,
// bit-exact stationary timeline stretches, and World::revision (a reload into the same World).
#include "test_worlds.h"

#include <lintel/timeline.h>
#include <lintel/viewer_tracker.h>
#include <lintel/visibility_builder.h>

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

namespace lintel {
namespace {

using testing::make_chain;
using testing::TestWorld;

std::vector<uint32_t> cells_of(const VisibleSet& v) {
  std::vector<uint32_t> out;
  for (const VisibleCell& c : v.cells) out.push_back(c.cell);
  return out;
}

// Chain rooms 4 m long along layout +X, doors at x = 4, 8, 12 (portal i joins rooms i and i + 1).
TEST(PortalState, AClosedDoorHidesEverythingBehindItAndReopens) {
  TestWorld t = make_chain(4);
  const View view = t.view({1.0f, 1.2f, 0.0f}, {20.0f, 1.2f, 0.0f});
  VisibilityBuilder builder;
  VisibleSet open, closed, reopened;
  ASSERT_TRUE(builder.build(t.world, view, 0, {}, open).ok());
  ASSERT_EQ(cells_of(open), (std::vector<uint32_t>{0, 1, 2, 3}));
  t.world.set_portal_open(1, false);
  EXPECT_FALSE(t.world.portal_open(1, PortalDirection::FromTo));
  ASSERT_TRUE(builder.build(t.world, view, 0, {}, closed).ok());
  EXPECT_EQ(cells_of(closed), (std::vector<uint32_t>{0, 1}));
  EXPECT_GT(closed.stats.closed_portals_skipped, 0u);
  t.world.set_portal_open(1, true);
  ASSERT_TRUE(builder.build(t.world, view, 0, {}, reopened).ok());
  EXPECT_EQ(reopened, open);  // toggling leaves no trace
}

// Per direction: a door closed only for sight from `from` still lets `to` look back through it.
TEST(PortalState, DirectionsAreIndependent) {
  TestWorld t = make_chain(2);
  t.world.set_portal_open(0, PortalDirection::FromTo, false);
  VisibilityBuilder builder;
  VisibleSet from_room0, from_room1;
  ASSERT_TRUE(builder.build(t.world, t.view({1.0f, 1.2f, 0.0f}, {8.0f, 1.2f, 0.0f}), 0, {}, from_room0).ok());
  EXPECT_EQ(cells_of(from_room0), (std::vector<uint32_t>{0}));
  ASSERT_TRUE(builder.build(t.world, t.view({7.0f, 1.2f, 0.0f}, {0.0f, 1.2f, 0.0f}), 1, {}, from_room1).ok());
  EXPECT_EQ(cells_of(from_room1), (std::vector<uint32_t>{0, 1}));
}

// A camera may pass a closed door (a cutscene, collision off): the tracker still follows it.
TEST(PortalState, TheTrackerFollowsCrossingsThroughClosedDoors) {
  TestWorld t = make_chain(3);
  t.world.set_portal_open(0, false);
  ViewerTracker tracker;
  ASSERT_TRUE(tracker.reset(t.world, t.to_world({3.5f, 1.2f, 0.0f})).ok());
  ASSERT_TRUE(tracker.update(t.world, t.to_world({4.5f, 1.2f, 0.0f})).ok());
  EXPECT_EQ(tracker.cell(), 1u);
  ASSERT_EQ(tracker.transitions().size(), 1u);
  EXPECT_EQ(tracker.transitions()[0].reason, TransitionReason::PortalCrossing);
}

// Door events: resolved by name, applied in time order up to each frame's time; a door closing
// in front of the camera removes the cells behind it on the first frame at or after its time.
TEST(PortalState, TimelineEventsCloseADoorOnTheirFrame) {
  TestWorld t = make_chain(4);
  t.world.portals[1].name = "middle_door";
  Timeline timeline;
  timeline.name = "doors";
  timeline.fps = 10.0;
  timeline.keys = {{0.0, t.to_world({1.0f, 1.2f, 0.0f}), t.to_world({20.0f, 1.2f, 0.0f})},
                   {2.0, t.to_world({1.0f, 1.2f, 0.0f}), t.to_world({20.0f, 1.2f, 0.0f})}};
  timeline.events = {{1.0, "middle_door", false}, {1.5, "middle_door", true}};
  ASSERT_TRUE(resolve_timeline_events(t.world, timeline).ok());
  VisibilityBuilder builder;
  size_t next = 0;
  for (size_t f = 0; f < timeline_frame_count(timeline); ++f) {
    const double time = double(f) / timeline.fps;
    next = apply_timeline_events(timeline, time, next, t.world);
    VisibleSet v;
    ASSERT_TRUE(builder.build(t.world, timeline_view(timeline, time), 0, {}, v).ok());
    const bool closed = f >= 10 && f < 15;
    const std::vector<uint32_t> expected = closed ? std::vector<uint32_t>{0, 1} : std::vector<uint32_t>{0, 1, 2, 3};
    EXPECT_EQ(cells_of(v), expected) << "frame " << f;
  }
  EXPECT_EQ(next, 2u);
  Timeline bad = timeline;
  bad.events[1].portal = "no_such_door";
  const Status s = resolve_timeline_events(t.world, bad);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("no_such_door"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("event 1"), std::string::npos) << s.message();
}

// A stationary stretch (two equal keys) samples to exactly the key, bit for bit, at every frame.
TEST(PortalState, StationaryTimelineStretchIsBitExact) {
  Timeline timeline;
  const glm::vec3 eye(123.456f, 1.7f, -98.765f), target(0.1f, 1.6f, 0.3f);
  timeline.keys = {{0.0, eye, target}, {3.0, eye, target}, {4.0, eye + glm::vec3(1.0f), target}};
  for (int f = 0; f <= 180; ++f) {
    const CameraPose pose = sample_timeline(timeline, f / 60.0);
    EXPECT_EQ(std::memcmp(&pose.eye_world, &eye, sizeof eye), 0) << "frame " << f;
    EXPECT_EQ(std::memcmp(&pose.target_world, &target, sizeof target), 0) << "frame " << f;
  }
}

// Reload: a different level with the same counts assigned into the same World object gives the
// same result as a fresh builder and tracker (the prepared instance bounds are not stale).
TEST(PortalState, AnotherLevelInTheSameWorldIsNoticed) {
  testing::WorldOptions furnished;
  furnished.furnish = true;
  testing::WorldOptions shifted = furnished;
  shifted.frame_seed = 99;
  shifted.door_half_width = 0.3f;
  const TestWorld a = make_chain(4, furnished);
  TestWorld b = make_chain(4, shifted);
  // Same counts, different content: b's furniture is 100 m away, out of every view below.
  for (Instance& inst : b.world.instances) inst.mesh_to_world[3] += glm::vec4(0.0f, 100.0f, 0.0f, 0.0f);
  ASSERT_TRUE(finalize_world(b.world).ok());
  ASSERT_EQ(a.world.instances.size(), b.world.instances.size());
  ASSERT_NE(a.world.revision, b.world.revision);

  const View view = a.view({1.0f, 1.5f, 0.0f}, {20.0f, 1.0f, 0.0f});
  World level = a.world;
  VisibilityBuilder reused, fresh;
  ViewerTracker tracker;
  VisibleSet before, after, expected;
  ASSERT_TRUE(tracker.reset(level, view.eye_world).ok());
  ASSERT_TRUE(reused.build(level, view, tracker.cell(), {}, before).ok());
  level = b.world;  // the reload: same address, same counts
  ASSERT_TRUE(tracker.update(level, view.eye_world).ok());
  ASSERT_TRUE(reused.build(level, view, tracker.cell(), {}, after).ok());
  ASSERT_TRUE(fresh.build(b.world, view, tracker.cell(), {}, expected).ok());
  EXPECT_EQ(after, expected);
  EXPECT_FALSE(before.instances.empty()) << "the two levels must differ for this test to mean anything";
  EXPECT_TRUE(after.instances.empty());
}

}  // namespace
}  // namespace lintel
