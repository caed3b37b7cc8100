// Two-phase hierarchical-Z occlusion in the renderer (CameraCull::PortalHiz, hiz_pass.h), under
// the Khronos validation layers with synchronization validation and GPU-AV (any message fails).
//
// Property (nothing visible is lost, in any frame): walking a timeline frame after frame, so that
// each frame starts from the occlusion the previous one left (objects coming out from behind
// walls, through doors, as the camera turns and crosses portals), the PortalHiz renderer's
// images — cell ids and final colour — are exactly the Portal renderer's. An instance the
// occlusion test wrongly rejected, or one drawn a frame late, would change pixels.
// Property (doors and movers): the same along the cottage's "door" timeline, with its door event
// and moving chair and door leaf applied to both renderers (update_world) before every frame: the
// occlusion test reads the moved boxes.
// Property (a mover comes out): a crate hidden behind a wall for a few frames, then moved in front
// of it, is drawn on the frame it moves (the late test reads its new box, not its old one).
// Property (it culls): over the walk, some draws of the portal cull are rejected as occluded, and
// from the second frame on most draws come from the first phase (last frame's survivors).
// About 6 s on the 2-core lavapipe machine.
#include "render_test_support.h"

#include <lintel/dynamic_instances.h>
#include <lintel/scene_io.h>
#include <lintel/timeline.h>
#include <lintel/viewer_tracker.h>

#include "box_cells.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>

namespace lintel::render::test {
namespace {

class HizRenderTest : public ValidatedGpu {};

// Renderers of the same world at 96x54 with cell ids read back and no GI (the g-buffer is what
// occlusion changes; lighting is the same either way): `portal` culls by portals alone, `hiz`
// adds the two-phase occlusion. Null on an error (the test has failed).
void make_portal_and_hiz(gpu::Context& ctx, const World& world, std::unique_ptr<Renderer>& portal,
                         std::unique_ptr<Renderer>& hiz) {
  RenderOptions options = test_options(96, 54);
  options.readback_cells = true;
  options.gi = false;
  portal = make_renderer(ctx, world, options);
  options.camera_cull = CameraCull::PortalHiz;
  hiz = make_renderer(ctx, world, options);
}

void walk_both(gpu::Context& ctx, const World& world, uint32_t stride, uint32_t max_frames) {
  std::unique_ptr<Renderer> a, b;
  make_portal_and_hiz(ctx, world, a, b);
  ASSERT_TRUE(a && b);
  const std::vector<TimelineFrame> frames = timeline_frames(world, world.timelines[0], stride);
  uint64_t tested = 0, passed = 0, early = 0, drawn = 0;
  uint32_t n = 0;
  for (const TimelineFrame& f : frames) {
    if (n++ >= max_frames) break;
    RenderedFrame fa, fb;
    const Status sa = a->render(f.view, f.start_cell, fa), sb = b->render(f.view, f.start_cell, fb);
    ASSERT_TRUE(sa.ok()) << sa.message();
    ASSERT_TRUE(sb.ok()) << "frame " << f.index << ": " << sb.message();
    ASSERT_EQ(fa.cell_ids, fb.cell_ids) << "frame " << f.index;
    ASSERT_EQ(fa.rgba8, fb.rgba8) << "frame " << f.index;
    // Every draw the portal cull made is tested; a drawable drawn early passed last frame's test.
    EXPECT_LE(fb.occlusion.passed, fb.occlusion.tested);
    EXPECT_LE(fb.occlusion.drawn_late, fb.occlusion.passed);
    tested += fb.occlusion.tested;
    passed += fb.occlusion.passed;
    if (n > 1) early += fb.occlusion.drawn_early, drawn += fb.occlusion.drawn_early + fb.occlusion.drawn_late;
  }
  std::printf("%u frames: %llu draws tested, %llu passed; after the first frame %llu of %llu drawn early\n", n,
              (unsigned long long)tested, (unsigned long long)passed, (unsigned long long)early,
              (unsigned long long)drawn);
  EXPECT_LT(passed, tested);    // something was occluded
  EXPECT_GT(early * 2, drawn);  // most draws come from last frame's survivors
}

TEST_F(HizRenderTest, CottageWalkImagesEqualPortalCulling) {
  World world;
  ASSERT_TRUE(load_committed_scene("cottage.gltf", world));
  walk_both(ctx(), world, 12, 60);  // big steps: each frame's history is from 0.4 s before
}

TEST_F(HizRenderTest, GridWalkImagesEqualPortalCulling) {
  World world;
  ASSERT_TRUE(load_committed_scene("grid16.gltf", world));
  walk_both(ctx(), world, 24, 30);
}

TEST_F(HizRenderTest, DoorTimelineWithMoversImagesEqualPortalCulling) {
  World world;
  ASSERT_TRUE(load_committed_scene("cottage.gltf", world));
  const int index = world.find_timeline("door");
  ASSERT_GE(index, 0);
  Timeline timeline = world.timelines[size_t(index)];
  std::vector<InstanceTrack> tracks;
  ASSERT_TRUE(resolve_timeline_instances(world, timeline, tracks).ok());
  ASSERT_FALSE(tracks.empty());
  std::unique_ptr<Renderer> a, b;
  make_portal_and_hiz(ctx(), world, a, b);
  ASSERT_TRUE(a && b);
  DynamicInstances movers;
  ASSERT_TRUE(movers.reset(world).ok());
  ViewerTracker tracker;
  size_t next_event = 0;
  uint32_t rendered = 0;
  const size_t frames = timeline_frame_count(timeline);
  for (size_t f = 0; f < frames; ++f) {
    const double t = timeline.keys.front().t + double(f) / timeline.fps;
    const View view = timeline_view(timeline, t);
    ASSERT_TRUE(advance_world(timeline, tracks, t, world, movers, next_event));
    const std::span<const uint32_t> moved = movers.take_moved();
    ASSERT_TRUE((f == 0 ? tracker.reset(world, view.eye_world) : tracker.update(world, view.eye_world)).ok());
    ASSERT_TRUE(a->update_world(world, moved).ok());
    ASSERT_TRUE(b->update_world(world, moved).ok());
    if (f % 10 != 0) continue;  // every 10th frame rendered; every frame's changes applied
    RenderedFrame fa, fb;
    const Status sa = a->render(view, tracker.cell(), fa), sb = b->render(view, tracker.cell(), fb);
    ASSERT_TRUE(sa.ok()) << sa.message();
    ASSERT_TRUE(sb.ok()) << "frame " << f << ": " << sb.message();
    ASSERT_EQ(fa.cell_ids, fb.cell_ids) << "frame " << f;
    ASSERT_EQ(fa.rgba8, fb.rgba8) << "frame " << f;
    ++rendered;
  }
  EXPECT_GT(rendered, 10u);
}

TEST_F(HizRenderTest, CrateMovedOutFromBehindAWallIsDrawnAtOnce) {
  SceneDesc scene;
  const int room = lintel::test::add_box_cell(scene, "room", {-6, 0, -6}, {6, 3, 6},
                                              lintel::test::inward_box_mesh("room shell", {-6, 0, -6}, {6, 3, 6}));
  lintel::test::add_box_instance(scene, room, "wall", {-2, 0, -0.1f}, {2, 2.5f, 0.1f});
  lintel::test::add_box_instance(scene, room, "crate", {-0.4f, 0, -2.4f}, {0.4f, 0.8f, -1.6f});
  World world;
  ASSERT_TRUE(build_world(scene, "room with wall", world).ok());
  uint32_t crate = 0;
  while (crate < world.instances.size() && world.instances[crate].name != "crate") ++crate;
  ASSERT_LT(crate, world.instances.size());
  std::unique_ptr<Renderer> a, b;
  make_portal_and_hiz(ctx(), world, a, b);
  ASSERT_TRUE(a && b);
  View view;
  view.eye_world = {0.0f, 1.2f, 4.0f};
  view.target_world = {0.0f, 1.0f, 0.0f};
  view.aspect = 96.0f / 54.0f;
  DynamicInstances movers;
  ASSERT_TRUE(movers.reset(world).ok());
  for (int f = 0; f < 4; ++f) {
    if (f == 3) {  // out in front of the wall, in plain view
      const glm::mat4 m =
          glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 3.0f)) * world.instances[crate].mesh_to_world;
      ASSERT_TRUE(movers.move(world, crate, m).ok());
      const std::span<const uint32_t> moved = movers.take_moved();
      ASSERT_TRUE(a->update_world(world, moved).ok());
      ASSERT_TRUE(b->update_world(world, moved).ok());
    }
    RenderedFrame fa, fb;
    ASSERT_TRUE(a->render(view, 0, fa).ok());
    const Status sb = b->render(view, 0, fb);
    ASSERT_TRUE(sb.ok()) << sb.message();
    ASSERT_EQ(fa.cell_ids, fb.cell_ids) << "frame " << f;
    ASSERT_EQ(fa.rgba8, fb.rgba8) << "frame " << f;
    if (f == 2) {
      EXPECT_LT(fb.occlusion.passed, fb.occlusion.tested) << "the crate behind the wall is not occluded";
    }
  }
}

}  // namespace
}  // namespace lintel::render::test
