// Property: GTAO at half resolution with the depth- and cell-aware upsample (the default) stays
// close to GTAO on every pixel, on the cottage's three golden views at 160x90: the AO debug view
// differs by at most kAoMean/255 on average and on at most kAoShare of the pixels by more than
// 16/255, and the final image by at most kFinalMean/255 and kFinalShare. Both AO images must have
// occlusion (pixels below 200/255), so an upsample that loses it (all 1.0) fails.
//
// Measured when written (lavapipe): AO view mean 3.9-5.0/255 with 5.0-7.5 % of pixels over 16/255
// — much of it GTAO's per-pixel noise, which the full-resolution image has and the upsampled one
// averages; final image mean 0.7-1.5/255, 0.4-1.0 % over 16/255 (the goldens were regenerated
// with half-resolution AO for that reason). The tolerances are those figures with some room.
// About 30 s on the 2-core lavapipe machine.
#include "image_diff.h"
#include "render_test_support.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace lintel::render::test {
namespace {

constexpr double kAoMean = 6.0, kAoShare = 0.10;
constexpr double kFinalMean = 2.0, kFinalShare = 0.015;
constexpr uint32_t kThreshold = 16;

class AoHalfTest : public ValidatedGpu {};

uint32_t occluded_pixels(const RenderedFrame& f) {
  uint32_t n = 0;
  for (size_t i = 0; i < f.rgba8.size(); i += 4) n += f.rgba8[i] < 200;
  return n;
}

TEST_F(AoHalfTest, HalfResolutionAoIsCloseToFullResolution) {
  World world;
  ASSERT_TRUE(load_committed_scene("cottage.gltf", world));
  const int walk = world.find_timeline("doorway");
  ASSERT_GE(walk, 0);
  const std::vector<TimelineFrame> frames = timeline_frames(world, world.timelines[size_t(walk)], 1);
  constexpr uint32_t kWidth = 160, kHeight = 90;
  std::unique_ptr<Renderer> renderers[2];  // [half]
  for (int half = 0; half < 2; ++half) {
    RenderOptions o = test_options(kWidth, kHeight);
    o.ao_half_resolution = half == 1;
    renderers[half] = make_renderer(ctx(), world, o);
    ASSERT_NE(renderers[half], nullptr);
  }
  for (uint32_t frame : {150u, 258u, 450u}) {
    ASSERT_LT(frame, frames.size());
    RenderedFrame images[2][2];  // [half][final, ao]
    for (int half = 0; half < 2; ++half) {
      for (int v = 0; v < 2; ++v) {
        ASSERT_TRUE(renderers[half]->set_debug_view(v == 0 ? kViewFinal : kViewAo).ok());
        const Status s = renderers[half]->render(frames[frame].view, frames[frame].start_cell, images[half][v]);
        ASSERT_TRUE(s.ok()) << s.message();
      }
    }
    auto image = [](const RenderedFrame& f) { return Rgba8Image{f.width, f.height, f.rgba8}; };
    const ImageDiff ao = diff_images(image(images[1][1]), image(images[0][1]), kThreshold);
    const ImageDiff fin = diff_images(image(images[1][0]), image(images[0][0]), kThreshold);
    std::printf(
        "frame %u: AO view mean |diff| %.3f/255, %.2f%% over %u/255; final mean %.3f/255, %.2f%% over; "
        "occluded pixels full %u half %u\n",
        frame, ao.mean_abs, 100.0 * ao.share_over, kThreshold, fin.mean_abs, 100.0 * fin.share_over,
        occluded_pixels(images[0][1]), occluded_pixels(images[1][1]));
    EXPECT_GT(occluded_pixels(images[0][1]), 0u) << "no occlusion at all: the comparison would prove nothing";
    EXPECT_GT(occluded_pixels(images[1][1]), 0u) << "the half-resolution AO lost all occlusion";
    EXPECT_LE(ao.mean_abs, kAoMean) << "frame " << frame;
    EXPECT_LE(ao.share_over, kAoShare) << "frame " << frame;
    EXPECT_LE(fin.mean_abs, kFinalMean) << "frame " << frame;
    EXPECT_LE(fin.share_over, kFinalShare) << "frame " << frame;
  }
}

}  // namespace
}  // namespace lintel::render::test
