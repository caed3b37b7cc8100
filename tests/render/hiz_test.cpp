// Two-phase hierarchical-Z occlusion in the renderer (CameraCull::PortalHiz, hiz_pass.h), under
// the Khronos validation layers with synchronization validation and GPU-AV (any message fails).
//
// Property (nothing visible is lost, in any frame): walking a timeline frame after frame, so that
// each frame starts from the occlusion the previous one left (objects coming out from behind
// walls, through doors, as the camera turns and crosses portals), the PortalHiz renderer's
// images — cell ids and final colour — are exactly the Portal renderer's. An instance the
// occlusion test wrongly rejected, or one drawn a frame late, would change pixels.
// Property (it culls): over the walk, some draws of the portal cull are rejected as occluded, and
// from the second frame on most draws come from the first phase (last frame's survivors).
// About 6 s on the 2-core lavapipe machine.
#include "render_test_support.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace lintel::render::test {
namespace {

class HizRenderTest : public ValidatedGpu {};

void walk_both(gpu::Context& ctx, const World& world, uint32_t stride, uint32_t max_frames) {
  RenderOptions portal = test_options(96, 54);
  portal.readback_cells = true;
  portal.gi = false;  // the g-buffer is what occlusion changes; lighting is the same either way
  RenderOptions hiz = portal;
  hiz.camera_cull = CameraCull::PortalHiz;
  std::unique_ptr<Renderer> a = make_renderer(ctx, world, portal), b = make_renderer(ctx, world, hiz);
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

}  // namespace
}  // namespace lintel::render::test
