// Door state and timeline door events through the real file path (writer -> GLB -> loader), and
// a reload of another level into the same World object (World::revision, finalize_world()).
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>
#include <lintel/timeline.h>
#include <lintel/viewer_tracker.h>
#include <lintel/visibility_builder.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace lintel {
namespace {

NodeDesc& node_named(SceneDesc& desc, const std::string& name) {
  for (NodeDesc& n : desc.nodes)
    if (n.name == name) return n;
  ADD_FAILURE() << "no node " << name;
  return desc.nodes.front();
}

TEST(DoorState, OpenFieldAndEventsSurviveTheWriterAndLoader) {
  SceneDesc desc = generate_cottage({});
  node_named(desc, "front_door").portal_open = false;
  ASSERT_FALSE(desc.timelines.empty());
  desc.timelines[0].events = {{1.0, "front_door", true}, {2.5, "back_door", false}};
  std::vector<uint8_t> glb;
  ASSERT_TRUE(scene_to_glb(desc, glb).ok());
  World world;
  ASSERT_TRUE(load_world_from_memory(glb.data(), glb.size(), "cottage-doors.glb", "", world).ok());
  const int front = world.find_portal("front_door"), back = world.find_portal("back_door");
  ASSERT_GE(front, 0);
  ASSERT_GE(back, 0);
  EXPECT_FALSE(world.portal_open(uint32_t(front), PortalDirection::FromTo));
  EXPECT_FALSE(world.portal_open(uint32_t(front), PortalDirection::ToFrom));
  for (uint32_t p = 0; p < world.portals.size(); ++p) {
    if (int(p) != front) {
      EXPECT_TRUE(world.portals[p].open_from_to && world.portals[p].open_to_from) << p;
    }
  }
  const Timeline& t = world.timelines[0];
  ASSERT_EQ(t.events.size(), 2u);
  EXPECT_EQ(t.events[0].portal_index, front);
  EXPECT_TRUE(t.events[0].open);
  EXPECT_EQ(t.events[1].portal_index, back);
  EXPECT_DOUBLE_EQ(t.events[1].t, 2.5);

  // The default state is not written: a scene without door events keeps its bytes (the cottage
  // with its doorway walk only: its "door" timeline closes a door).
  SceneDesc no_events = generate_cottage({});
  no_events.timelines.resize(1);
  ASSERT_EQ(no_events.timelines[0].name, "doorway");
  std::vector<uint8_t> plain;
  ASSERT_TRUE(scene_to_glb(no_events, plain).ok());
  const std::string text(plain.begin(), plain.end());
  EXPECT_EQ(text.find("\"open\""), std::string::npos);
  EXPECT_EQ(text.find("\"events\""), std::string::npos);
}

// Reload: a second level with the same counts (the cottage with its furniture moved 100 m up)
// loaded into the same World object gives, on every frame of the doorway walk, exactly what a
// fresh builder and tracker give; and the two levels really differ on some frame.
TEST(DoorState, ReloadingAnotherLevelIntoTheSameWorldMatchesAFreshLoad) {
  const SceneDesc first = generate_cottage({});
  SceneDesc second = first;
  for (NodeDesc& n : second.nodes)
    if (n.mesh >= 0 && n.kind == NodeDesc::Kind::Plain && n.parent >= 0) n.translation.y += 100.0f;
  World level;
  ASSERT_TRUE(build_world(first, "first", level).ok());
  const Timeline walk = level.timelines[0];
  const uint64_t first_revision = level.revision;
  VisibilityBuilder reused;
  ViewerTracker reused_tracker;
  std::vector<std::vector<uint32_t>> first_instances;
  VisibleSet v;
  for (size_t f = 0; f < timeline_frame_count(walk); f += 7) {
    const View view = timeline_view(walk, walk.keys.front().t + double(f) / walk.fps);
    ASSERT_TRUE(
        (f == 0 ? reused_tracker.reset(level, view.eye_world) : reused_tracker.update(level, view.eye_world)).ok());
    ASSERT_TRUE(reused.build(level, view, reused_tracker.cell(), {}, v).ok());
    first_instances.push_back(v.instances);
  }
  ASSERT_TRUE(build_world(second, "second", level).ok());  // the reload, same object
  EXPECT_NE(level.revision, first_revision);
  World fresh_world;
  ASSERT_TRUE(build_world(second, "second", fresh_world).ok());
  VisibilityBuilder fresh;
  ViewerTracker fresh_tracker;
  VisibleSet expected;
  size_t differing = 0, k = 0;
  for (size_t f = 0; f < timeline_frame_count(walk); f += 7, ++k) {
    const View view = timeline_view(walk, walk.keys.front().t + double(f) / walk.fps);
    ASSERT_TRUE(
        (f == 0 ? fresh_tracker.reset(fresh_world, view.eye_world) : fresh_tracker.update(fresh_world, view.eye_world))
            .ok());
    ASSERT_TRUE(reused_tracker.update(level, view.eye_world).ok());
    EXPECT_EQ(reused_tracker.cell(), fresh_tracker.cell()) << "frame " << f;
    ASSERT_TRUE(reused.build(level, view, reused_tracker.cell(), {}, v).ok());
    ASSERT_TRUE(fresh.build(fresh_world, view, fresh_tracker.cell(), {}, expected).ok());
    EXPECT_EQ(v, expected) << "frame " << f;
    differing += v.instances != first_instances[k];
  }
  EXPECT_GT(differing, 0u) << "the two levels must differ for this test to mean anything";
}

}  // namespace
}  // namespace lintel
