// Property: GI amortised over frames (GiOptions::amortized_bounces, with probes kept between
// frames) converges to the image of running every iteration every frame, and runs the full count
// exactly when the kept probes are cold: on the first frame, on a frame that activates a cell not
// active the frame before, and after a door change (which resets the probes). The light/gather
// iterations are a fixed-point iteration on the probes, so iterations spread over frames reach the
// same point; the first frame, equal in both renderers, is compared bit for bit.
// About 6 s on the 2-core lavapipe machine.
#include "render_test_support.h"

#include <lintel/cell_locate.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>

namespace lintel::render::test {
namespace {

constexpr uint32_t kWidth = 128, kHeight = 72;

RenderOptions options(uint32_t amortized) {
  RenderOptions o = test_options(kWidth, kHeight);
  o.gi_persist = true;
  o.gi_options.amortized_bounces = amortized;
  o.readback_hdr = true;
  return o;
}

// Mean over pixels of |a - b| (luminance), relative to the mean luminance of b.
double relative_difference(const RenderedFrame& a, const RenderedFrame& b) {
  double diff = 0.0, total = 0.0;
  for (size_t p = 0; p < a.hdr.size(); ++p) {
    const glm::vec3 w(0.2126f, 0.7152f, 0.0722f);
    const double la = glm::dot(glm::vec3(a.hdr[p]), w), lb = glm::dot(glm::vec3(b.hdr[p]), w);
    diff += std::abs(la - lb);
    total += lb;
  }
  return total > 0.0 ? diff / total : 0.0;
}

class GiAmortizeTest : public ValidatedGpu {};

TEST_F(GiAmortizeTest, ConvergesToTheFullImageAndRunsInFullWhenCold) {
  World world;
  ASSERT_TRUE(load_committed_scene("cottage.gltf", world));
  const Timeline& walk = world.timelines[0];
  // Two views of the doorway walk: in the hall, then a second far enough on to see another cell.
  std::vector<TimelineFrame> frames = timeline_frames(world, walk, 1);
  ASSERT_GT(frames.size(), 300u);
  const TimelineFrame first = frames[150];
  uint32_t later = 0;
  std::unique_ptr<Renderer> amortized = make_renderer(ctx(), world, options(2));
  std::unique_ptr<Renderer> full = make_renderer(ctx(), world, options(0));
  ASSERT_TRUE(amortized && full);
  const uint32_t bounces = options(0).gi_options.bounces;

  RenderedFrame a, b;
  ASSERT_TRUE(amortized->render(first.view, first.start_cell, a).ok());
  ASSERT_TRUE(full->render(first.view, first.start_cell, b).ok());
  EXPECT_EQ(a.gi_bounces, bounces) << "the first frame starts from zero probes: every iteration";
  EXPECT_EQ(b.gi_bounces, bounces);
  ASSERT_EQ(a.hdr.size(), b.hdr.size());
  EXPECT_EQ(std::memcmp(a.hdr.data(), b.hdr.data(), a.hdr.size() * sizeof(glm::vec4)), 0)
      << "the same iterations from the same probes give the same image";

  // The same view again: warm probes, 2 iterations a frame against 8; after 7 frames the two
  // images agree (both near the fixed point; measured: 4.4 % after one frame, 1.0 % after five).
  double difference = 0.0;
  for (int k = 1; k <= 7; ++k) {
    ASSERT_TRUE(amortized->render(first.view, first.start_cell, a).ok());
    ASSERT_TRUE(full->render(first.view, first.start_cell, b).ok());
    EXPECT_EQ(a.gi_bounces, 2u) << "frame " << k << ": warm probes, no new cell";
    difference = relative_difference(a, b);
    std::printf("static frame %d: amortised %u iterations (%u in all), full %u; mean relative difference %.5f\n", k,
                a.gi_bounces, bounces + 2 * k, b.gi_bounces, difference);
  }
  EXPECT_LT(difference, 0.01) << "amortised GI should converge to the full iterations' image";

  // On along the walk until a frame activates a cell the previous frame did not: a full frame.
  bool saw_full = false;
  for (size_t f = 151; f < frames.size() && !saw_full; f += 3) {
    ASSERT_TRUE(amortized->render(frames[f].view, frames[f].start_cell, a).ok());
    saw_full = a.gi_bounces == bounces;
    later = uint32_t(f);
    EXPECT_TRUE(a.gi_bounces == bounces || a.gi_bounces == 2u);
  }
  EXPECT_TRUE(saw_full) << "walking on from frame 150 should activate a new cell";
  std::printf("frame %u activates a new cell: %u iterations\n", later, a.gi_bounces);
  ASSERT_TRUE(amortized->render(frames[later].view, frames[later].start_cell, a).ok());
  EXPECT_EQ(a.gi_bounces, 2u) << "the same cells again: warm";

  // A door change resets the probes: the next frame runs in full.
  world.set_portal_open(0, false);
  ASSERT_TRUE(amortized->update_world(world, {}).ok());
  ASSERT_TRUE(amortized->render(frames[later].view, frames[later].start_cell, a).ok());
  EXPECT_EQ(a.gi_bounces, bounces) << "after a door change the probes start from zero";
}

}  // namespace
}  // namespace lintel::render::test
