// Property: along the cottage's "door" timeline, walked as `lintel walk --frames` walks it (door
// events and instance keys applied to the World before each frame, Renderer::update_world, the
// viewer cell tracked), the frame on which the living-room door closes in front of the camera
// drops the living room from the visible set, and no pixel behind the door is lit from the other
// side: every pixel of the living room's cell still drawn (its shell's box reaches into the hall,
// and the instance reach lists do not follow doors, so the shell shows through the hole the door
// leaves) has exactly 0.0 radiance, where the frame before lit most of them. (The living lamp
// does still reach the hall, legitimately, through the kitchen's two doors.)
// The carried chair, once in the hall (it is moved every frame before that), is drawn on every
// rendered frame; the door leaf, swung shut by the timeline's rotation keys, is drawn filling a
// good part of the view once the door is closed. About 10 s on the 2-core lavapipe machine.
#include "render_test_support.h"

#include <lintel/dynamic_instances.h>
#include <lintel/timeline.h>
#include <lintel/viewer_tracker.h>
#include <lintel/visibility_builder.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

namespace lintel::render::test {
namespace {

constexpr uint32_t kWidth = 96, kHeight = 54;

uint32_t pixels_of(const RenderedFrame& f, uint32_t cell) {
  return uint32_t(std::count(f.cell_ids.begin(), f.cell_ids.end(), cell));
}

uint32_t lit_pixels_of(const RenderedFrame& f, uint32_t cell) {
  uint32_t n = 0;
  for (size_t p = 0; p < f.cell_ids.size(); ++p)
    n += f.cell_ids[p] == cell && (f.hdr[p].r != 0.0f || f.hdr[p].g != 0.0f || f.hdr[p].b != 0.0f);
  return n;
}

class DoorWalkTest : public ValidatedGpu {};

TEST_F(DoorWalkTest, DoorClosingInFrontOfTheCamera) {
  const double t0 = now_ms();
  World world;
  ASSERT_TRUE(load_committed_scene("cottage.gltf", world));
  const int index = world.find_timeline("door");
  ASSERT_GE(index, 0) << "the cottage has no 'door' timeline";
  Timeline timeline = world.timelines[size_t(index)];
  ASSERT_FALSE(timeline.events.empty());
  std::vector<InstanceTrack> tracks;
  ASSERT_TRUE(resolve_timeline_instances(world, timeline, tracks).ok());
  ASSERT_EQ(tracks.size(), 2u) << "the carried chair and the door leaf";
  const int chair_track = world.instances[tracks[0].instance].name == "living_chair" ? 0 : 1;
  const uint32_t chair = tracks[size_t(chair_track)].instance, leaf = tracks[size_t(1 - chair_track)].instance;
  ASSERT_EQ(world.instances[chair].name, "living_chair");
  ASSERT_EQ(world.instances[leaf].name, "hall_living_door_leaf");
  // The chair stands in the hall from its last key on; the leaf starts to swing shut at its first.
  const double arrived = timeline.instance_keys[tracks[size_t(chair_track)].keys.back()].t;
  const double swing = timeline.instance_keys[tracks[size_t(1 - chair_track)].keys.front()].t;
  const int living = world.find_cell("living"), hall = world.find_cell("hall");
  ASSERT_GE(living, 0);
  ASSERT_GE(hall, 0);

  RenderOptions o = test_options(kWidth, kHeight);
  o.readback_hdr = true;
  o.readback_cells = true;
  o.count_fragments = true;
  std::unique_ptr<Renderer> r = make_renderer(ctx(), world, o);
  ASSERT_NE(r, nullptr);
  DynamicInstances movers;
  ASSERT_TRUE(movers.reset(world).ok());
  ViewerTracker tracker;
  VisibilityBuilder builder;
  VisibleSet visible;
  size_t next_event = 0;
  const size_t frames = timeline_frame_count(timeline);
  const double door_time = timeline.events.front().t;
  bool before_seen = false, door_seen = false;
  for (size_t f = 0; f < frames; ++f) {
    const double t = timeline.keys.front().t + double(f) / timeline.fps;
    View view = timeline_view(timeline, t);
    view.aspect = float(kWidth) / float(kHeight);
    ASSERT_TRUE(advance_world(timeline, tracks, t, world, movers, next_event));
    const std::span<const uint32_t> moved = movers.take_moved();
    ASSERT_TRUE((f == 0 ? tracker.reset(world, view.eye_world) : tracker.update(world, view.eye_world)).ok());
    ASSERT_EQ(tracker.cell(), uint32_t(hall)) << "frame " << f;
    ASSERT_TRUE(r->update_world(world, moved).ok());
    // Only the frames around the door event and a few others are rendered.
    const bool last_open = t < door_time && t + 1.0 / timeline.fps >= door_time;
    const bool first_closed = t >= door_time && t - 1.0 / timeline.fps < door_time;
    const bool leaf_still_open = t < swing && t + 1.0 / timeline.fps >= swing;
    if (!(last_open || first_closed || leaf_still_open || f % 20 == 0)) continue;
    ASSERT_TRUE(builder.build(world, view, tracker.cell(), {}, visible).ok());
    const bool living_visible = visible.cell_visible(uint32_t(living));
    RenderedFrame frame;
    const Status s = r->render(view, tracker.cell(), frame);
    ASSERT_TRUE(s.ok()) << s.message();
    std::printf("frame %zu (t %.3f): living %s, %u living pixels (%u lit), %u lights, chair %u, leaf %u fragments\n", f,
                t, living_visible ? "visible" : "hidden", pixels_of(frame, uint32_t(living)),
                lit_pixels_of(frame, uint32_t(living)), frame.active_lights, frame.fragment_counts[chair],
                frame.fragment_counts[leaf]);
    if (t >= arrived) {
      EXPECT_GT(frame.fragment_counts[chair], 0u) << "the carried chair vanished on frame " << f;
    }
    if (t < door_time) {
      EXPECT_TRUE(living_visible) << "frame " << f << ": the portal is open until the door event";
      if (t < swing) {  // the leaf still stands open: the living room shows through the doorway, lit
        EXPECT_GT(lit_pixels_of(frame, uint32_t(living)), pixels_of(frame, uint32_t(living)) / 2)
            << "frame " << f << ": the living room should show, lit";
      }
      before_seen = before_seen || last_open;
      continue;
    }
    EXPECT_FALSE(living_visible) << "frame " << f << ": the living room is behind the closed door";
    EXPECT_EQ(lit_pixels_of(frame, uint32_t(living)), 0u) << "frame " << f << ": lit from behind the closed door";
    EXPECT_GT(frame.fragment_counts[leaf], kWidth * kHeight / 20) << "frame " << f << ": the closed door's leaf";
    door_seen = door_seen || first_closed;
  }
  EXPECT_TRUE(before_seen && door_seen) << "the walk should render the frames on both sides of the door event";
  std::printf("door walk: %zu frames, %.0f ms\n", frames, now_ms() - t0);
}

}  // namespace
}  // namespace lintel::render::test
