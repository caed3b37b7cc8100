// Property: how a file frames its cells changes no pass. The same world written with every cell's
// geometry in a different random frame (the closed-shell house with two frame seeds; its world
// geometry, lights and colours do not depend on the seed) renders every pass — final, albedo, normal, depth, shadow, GI,
// AO — within 2/255 per channel on average, from every view. Visibility is already frame-invariant;
// before the fix the GI pass of a rotated-frame world was 25-30 % darker (probes laid out over
// the cell-space box). (`gen grid --jitter` is not usable here: it draws the frames from
// the same random stream as the rest of the grid, so the world changes too.) About 60 s on the
// shared 2-core lavapipe machine, most of it pipeline creation under GPU-AV.
#include "closed_house.h"
#include "image_diff.h"
#include "render_test_support.h"

#include <lintel/cell_locate.h>
#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <cstdio>

namespace lintel::render::test {
namespace {

constexpr uint32_t kWidth = 96, kHeight = 54;
constexpr double kMeanTolerance = 2.0;  // 1/255 steps per channel
const char* const kPassNames[] = {"final", "albedo", "normal", "depth", "shadow", "gi", "ao"};

class ReframeTest : public ValidatedGpu {
 protected:
  static Rgba8Image render(Renderer& r, const World& world, uint32_t pass, const View& view) {
    EXPECT_TRUE(r.set_debug_view(pass).ok());
    RenderedFrame frame;
    const Status s = r.render(view, locate_cell(world, glm::dvec3(view.eye_world)).cell, frame);
    EXPECT_TRUE(s.ok()) << s.message();
    return {frame.width, frame.height, frame.rgba8};
  }

  void compare(const World& a, const World& b, const std::vector<View>& views, const std::string& label) {
    ASSERT_EQ(a.cells.size(), b.cells.size());
    const RenderOptions o = test_options(kWidth, kHeight);
    std::unique_ptr<Renderer> ra = make_renderer(ctx(), a, o), rb = make_renderer(ctx(), b, o);
    ASSERT_TRUE(ra && rb);
    for (uint32_t pass = kViewFinal; pass <= kViewAo; ++pass)
      for (size_t v = 0; v < views.size(); ++v) {
        const ImageDiff d = diff_images(render(*ra, a, pass, views[v]), render(*rb, b, pass, views[v]), 16);
        ASSERT_TRUE(d.same_size);
        std::printf("  %s %s view %zu: mean %.3f/255, %.2f %% over 16/255\n", label.c_str(), kPassNames[pass], v,
                    d.mean_abs, 100.0 * d.share_over);
        std::fflush(stdout);
        EXPECT_LE(d.mean_abs, kMeanTolerance) << label << " pass " << kPassNames[pass] << " view " << v;
      }
  }
};

TEST_F(ReframeTest, ClosedHouseWithOtherCellFrames) {
  const float aspect = float(kWidth) / float(kHeight);
  ClosedHouse one = closed_house(1, aspect), two = closed_house(3, aspect);
  World a, b;
  ASSERT_TRUE(build_world(one.scene, "house (frames 1)", a).ok());
  ASSERT_TRUE(build_world(two.scene, "house (frames 3)", b).ok());
  // The same world: the cell frames differ, the world-space geometry does not.
  ASSERT_NE(a.cells[4].cell_to_world, b.cells[4].cell_to_world);
  const std::vector<View> views = {one.views[0], one.views[3], one.views[5]};
  compare(a, b, views, "house");
}

}  // namespace
}  // namespace lintel::render::test
