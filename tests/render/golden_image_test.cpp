// Property: the cottage, rendered from three fixed views of its "doorway" timeline at 160x90,
// matches the committed PNGs in tests/render/golden/ within a stated tolerance — so a change to
// shadows, GI, AO, materials or the cull shows up as a failure, while reruns on lavapipe pass.
//
// The views (frame = t x 30 fps): 150 (t = 5.0 s: from the hall into the living room, the
// living lamp throwing the table's shadow), 258 (t = 8.6 s: the kitchen, its spot light and the
// sun through the window on the wall and floor) and 450 (t = 15.0 s: the study, sun through the
// window on the floor).
//
// Tolerance: mean |difference| <= 2/255 per channel AND at most 0.5% of the pixels (72 of
// 14400) with some channel off by more than 16/255. Lavapipe reruns are bit-identical (the
// frame depends only on its view: gi_persist off, fixed GI seed), so the slack is for another
// Mesa/LLVM build rounding differently; real changes move far more. Measured when this was
// written, as the share of pixels over 16/255: no shadows at all 80-97%, no point-light shadows
// 74-96%, shadow maps 256 instead of 512 4-29%, one GI bounce instead of the default 35-77% (measured with 2 as the default), AO off
// 1.0-10% (every one fails). The GI case is checked below on every run: the frames without GI
// must FAIL this tolerance.
//
// Regenerated when GTAO moved to half resolution with a depth-aware upsample (issue 12 item 3):
// against the full-resolution goldens the frames were 0.4-1.0 % of pixels over 16/255, mean
// 0.7-1.5/255 (render_ao_half_test keeps that comparison).
//
// Regenerate after an intended change: LINTEL_UPDATE_GOLDEN=1 ./render_golden_test (rewrites
// the PNGs in the source tree; look at them before committing). A failing frame is written to
// <build>/tests/render_golden_actual/ for inspection. About 1 s on the 2-core lavapipe machine.
#include "image_diff.h"
#include "render_test_support.h"

#include <lintel/render/image_io.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace lintel::render::test {
namespace {

constexpr uint32_t kWidth = 160, kHeight = 90;
constexpr uint32_t kGoldenFrames[] = {150, 258, 450};
constexpr double kMeanTolerance = 2.0;    // in 1/255 steps, per channel
constexpr uint32_t kPixelThreshold = 16;  // a pixel "differs" when some channel is off by more
constexpr double kShareTolerance = 0.005;

std::string golden_path(uint32_t frame) {
  return std::string(LINTEL_SOURCE_DIR) + "/tests/render/golden/cottage_doorway_" + std::to_string(frame) + ".png";
}

bool within_tolerance(const ImageDiff& d) {
  return d.same_size && d.mean_abs <= kMeanTolerance && d.share_over <= kShareTolerance;
}

class GoldenImageTest : public ValidatedGpu {
 protected:
  // Renders the golden frames with `options`; empty on failure.
  std::vector<Rgba8Image> render_frames(const RenderOptions& options) {
    World world;
    if (!load_committed_scene("cottage.gltf", world)) return {};
    const int walk = world.find_timeline("doorway");
    EXPECT_GE(walk, 0) << "the cottage has no 'doorway' timeline";
    if (walk < 0) return {};
    const std::vector<TimelineFrame> frames = timeline_frames(world, world.timelines[size_t(walk)], 1);
    std::unique_ptr<Renderer> renderer = make_renderer(ctx(), world, options);
    if (!renderer) return {};
    std::vector<Rgba8Image> out;
    for (uint32_t f : kGoldenFrames) {
      EXPECT_LT(f, frames.size());
      if (f >= frames.size()) return {};
      RenderedFrame frame;
      const Status s = renderer->render(frames[f].view, frames[f].start_cell, frame);
      EXPECT_TRUE(s.ok()) << s.message();
      if (!s) return {};
      out.push_back({frame.width, frame.height, std::move(frame.rgba8)});
    }
    return out;
  }
};

TEST_F(GoldenImageTest, CottageViewsMatchGoldens) {
  const double t0 = now_ms();
  const std::vector<Rgba8Image> images = render_frames(test_options(kWidth, kHeight));
  ASSERT_EQ(images.size(), std::size(kGoldenFrames));
  const bool update = std::getenv("LINTEL_UPDATE_GOLDEN") && std::string(std::getenv("LINTEL_UPDATE_GOLDEN")) == "1";
  for (size_t i = 0; i < images.size(); ++i) {
    const std::string path = golden_path(kGoldenFrames[i]);
    if (update) {
      const Status s = write_png(path, images[i]);
      EXPECT_TRUE(s.ok()) << s.message();
      std::printf("updated %s\n", path.c_str());
      continue;
    }
    Rgba8Image golden;
    const Status s = read_png(path, golden);
    ASSERT_TRUE(s.ok()) << s.message() << " (LINTEL_UPDATE_GOLDEN=1 writes it)";
    const ImageDiff d = diff_images(images[i], golden, kPixelThreshold);
    std::printf("frame %u: mean |diff| %.3f/255, %u pixels (%.2f%%) over %u/255, max %u/255\n", kGoldenFrames[i],
                d.mean_abs, d.pixels_over, 100.0 * d.share_over, kPixelThreshold, d.max_abs);
    EXPECT_TRUE(within_tolerance(d)) << path << ": mean |diff| " << d.mean_abs << "/255 (tolerance " << kMeanTolerance
                                     << "), " << 100.0 * d.share_over << "% of pixels over " << kPixelThreshold
                                     << "/255 (tolerance " << 100.0 * kShareTolerance << "%)";
    if (!within_tolerance(d)) {
      const std::filesystem::path dir = std::filesystem::path(LINTEL_BINARY_DIR) / "tests" / "render_golden_actual";
      std::filesystem::create_directories(dir);
      const std::string actual = (dir / std::filesystem::path(path).filename()).string();
      if (write_png(actual, images[i]).ok()) std::printf("wrote the rendered frame to %s\n", actual.c_str());
    }
  }
  std::printf("golden frames rendered and compared in %.0f ms\n", now_ms() - t0);
}

// The tolerance is not so loose that it hides a real change: the same views without GI (direct
// light only) must fall outside it, every one.
TEST_F(GoldenImageTest, ToleranceRejectsFramesWithoutGi) {
  if (std::getenv("LINTEL_UPDATE_GOLDEN")) GTEST_SKIP() << "goldens are being rewritten";
  RenderOptions options = test_options(kWidth, kHeight);
  options.gi = false;
  const std::vector<Rgba8Image> images = render_frames(options);
  ASSERT_EQ(images.size(), std::size(kGoldenFrames));
  for (size_t i = 0; i < images.size(); ++i) {
    Rgba8Image golden;
    ASSERT_TRUE(read_png(golden_path(kGoldenFrames[i]), golden).ok());
    const ImageDiff d = diff_images(images[i], golden, kPixelThreshold);
    std::printf("frame %u without GI: mean |diff| %.3f/255, %.2f%% of pixels over %u/255\n", kGoldenFrames[i],
                d.mean_abs, 100.0 * d.share_over, kPixelThreshold);
    EXPECT_FALSE(within_tolerance(d)) << "frame " << kGoldenFrames[i] << ": turning GI off stays within the tolerance";
  }
}

}  // namespace
}  // namespace lintel::render::test
