// Property: a base-colour texture reaches the g-buffer through the indirect draws. The cottage's
// hall shell, given a black/white checker (8x8 texels in 4x4 blocks, uv = world x,z / 0.5 m),
// shows both colours in the albedo pass (each on at least 15% of the hall's pixels), where the
// untextured hall shows no black at all; and the final image of the textured hall is darker.
// A sampler, descriptor, vertex-attribute or layer mix-up makes one of the colours vanish.
#include "render_test_support.h"

#include <gtest/gtest.h>

#include <lintel/render/image_io.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace lintel::render::test {
namespace {

constexpr uint32_t kSize = 128;

// 8 x 8 texels in 4 x 4 blocks, black and white.
Texture checker() { return block_checker(8, 4, {0, 0, 0, 255}, {255, 255, 255, 255}); }

struct Counts {
  size_t hall = 0, dark = 0, light = 0;
  double mean_final = 0.0;
};

class TextureTest : public ValidatedGpu {
 protected:
  // The cottage and its hall; frame 150 of its timeline looks from the hall into the living room,
  // the hall's floor and walls filling the frame.
  struct HallView {
    World world;
    uint32_t hall = 0;
    TimelineFrame frame;
  };
  static bool hall_view(HallView& out) {
    if (!load_committed_scene("cottage.gltf", out.world)) return false;
    const int hall = out.world.find_cell("hall");
    const std::vector<TimelineFrame> frames = timeline_frames(out.world, out.world.timelines.front(), 150);
    if (hall < 0 || frames.size() < 2) return false;
    out.hall = uint32_t(hall);
    out.frame = frames[1];
    return out.frame.start_cell == out.hall;
  }

  // Debug view `view` of frame `f`, square, with cell ids.
  RenderedFrame render(const World& world, const TimelineFrame& f, uint32_t view) {
    RenderOptions o = test_options(kSize, kSize);
    o.view = view;
    o.readback_cells = true;
    RenderedFrame frame;
    auto r = make_renderer(ctx(), world, o);
    if (!r) return frame;
    View v = f.view;
    v.aspect = 1.0f;
    const Status s = r->render(v, f.start_cell, frame);
    EXPECT_TRUE(s.ok()) << s.message();
    return frame;
  }

  Counts render_hall(const World& world, uint32_t hall, const TimelineFrame& f) {
    Counts c;
    for (uint32_t view : {kViewAlbedo, kViewFinal}) {
      const RenderedFrame frame = render(world, f, view);
      if (std::getenv("LINTEL_TEXTURE_TEST_DUMP"))
        (void)write_png(std::string(std::getenv("LINTEL_TEXTURE_TEST_DUMP")) + "/" + std::to_string(view) + "_" +
                            std::to_string(world.textures.size()) + ".png",
                        {frame.width, frame.height, frame.rgba8});
      for (size_t p = 0; p < frame.cell_ids.size(); ++p) {
        if (frame.cell_ids[p] != hall) continue;
        const uint8_t red = frame.rgba8[p * 4];
        if (view == kViewAlbedo) {
          ++c.hall;
          c.dark += red < 30;
          c.light += red > 150;
        } else {
          c.mean_final += red;
        }
      }
    }
    if (c.hall) c.mean_final /= double(c.hall);
    return c;
  }
};

TEST_F(TextureTest, CheckerOnTheHallShellShowsInTheAlbedoPass) {
  HallView h;
  ASSERT_TRUE(hall_view(h));
  const World& world = h.world;
  const uint32_t hall = h.hall;
  const TimelineFrame& f = h.frame;

  const Counts plain = render_hall(world, hall, f);
  ASSERT_GT(plain.hall, kSize * kSize / 10);
  EXPECT_EQ(plain.dark, 0u) << "the untextured hall has no black";

  World textured = world;
  Mesh& shell = textured.meshes[size_t(textured.cells[hall].shell_mesh)];
  shell.uvs.clear();
  // World x, z (cell frames are scaled and turned): one checker period per 0.5 m.
  const glm::mat4& to_world = textured.cells[hall].cell_to_world;
  for (const glm::vec3& p : shell.positions) {
    const glm::vec3 w = glm::vec3(to_world * glm::vec4(p, 1.0f));
    shell.uvs.emplace_back(2.0f * w.x, 2.0f * w.z);
  }
  textured.textures.push_back(checker());
  shell.base_color_texture = int(textured.textures.size() - 1);
  const Counts tex = render_hall(textured, hall, f);
  ASSERT_EQ(tex.hall, plain.hall) << "a texture must not change what is drawn";
  EXPECT_GE(tex.dark, tex.hall * 15 / 100) << "black squares of the checker";
  EXPECT_GE(tex.light, tex.hall * 15 / 100) << "white squares of the checker";
  EXPECT_LT(tex.mean_final, plain.mean_final) << "half the hall's albedo is black: the lit image is darker";
}

// Property: vertex colours (COLOR_0) multiply the base colour in the g-buffer, interpolated over
// each triangle. The hall shell with every vertex coloured c draws, pixel for pixel, the albedo
// of the same shell with base colour times c and no vertex colours; and with the colour changing
// from red at the floor to blue at the ceiling, the shell's pixels spread over both. A missing or
// mis-bound vertex attribute draws white (the first half) or one colour (the second).
TEST_F(TextureTest, ColouredVerticesDrawAsTheirColour) {
  HallView h;
  ASSERT_TRUE(hall_view(h));
  const World& world = h.world;
  const uint32_t hall = h.hall;
  const TimelineFrame& f = h.frame;
  auto albedo = [&](const World& w) { return render(w, f, kViewAlbedo); };
  const size_t shell_mesh = size_t(world.cells[hall].shell_mesh);
  const glm::vec4 c(0.25f, 1.0f, 0.5f, 1.0f);
  World coloured = world, tinted = world;
  coloured.meshes[shell_mesh].colors.assign(coloured.meshes[shell_mesh].positions.size(), c);
  tinted.meshes[shell_mesh].base_color *= c;
  const RenderedFrame a = albedo(coloured), b = albedo(tinted), plain = albedo(world);
  ASSERT_EQ(a.rgba8.size(), size_t(kSize) * kSize * 4);
  // Interpolating a constant may round by an ulp: at most one step of the 8-bit image.
  int worst = 0;
  for (size_t i = 0; i < a.rgba8.size() && i < b.rgba8.size(); ++i)
    worst = std::max(worst, std::abs(int(a.rgba8[i]) - int(b.rgba8[i])));
  ASSERT_EQ(a.rgba8.size(), b.rgba8.size());
  EXPECT_LE(worst, 1) << "vertex colour c must draw as base colour times c";
  ASSERT_EQ(a.cell_ids, plain.cell_ids);
  size_t hall_pixels = 0, changed = 0;
  for (size_t p = 0; p < a.cell_ids.size(); ++p) {
    if (a.cell_ids[p] != hall) continue;
    ++hall_pixels;
    changed += a.rgba8[4 * p] != plain.rgba8[4 * p];
  }
  ASSERT_GT(hall_pixels, kSize * kSize / 10);
  EXPECT_GT(changed, hall_pixels / 2) << "the shell's red channel is a quarter of the plain one's";

  // Red at the shell's lowest vertices, blue at its highest, interpolated between: the shell's
  // pixels (green 0; the hall's instances keep theirs) run from red-leaning near the floor to
  // blue at the ceiling. One flat colour per triangle or per draw would not spread.
  World graded = world;
  Mesh& shell = graded.meshes[shell_mesh];
  const glm::mat4& to_world = graded.cells[hall].cell_to_world;
  float lo = 1e9f, hi = -1e9f;
  for (const glm::vec3& p : shell.positions) {
    const float y = (to_world * glm::vec4(p, 1.0f)).y;
    lo = std::min(lo, y), hi = std::max(hi, y);
  }
  for (const glm::vec3& p : shell.positions) {
    const float t = ((to_world * glm::vec4(p, 1.0f)).y - lo) / (hi - lo);
    shell.colors.emplace_back(1.0f - t, 0.0f, t, 1.0f);
  }
  shell.base_color = glm::vec4(1.0f);
  const RenderedFrame g = albedo(graded);
  int red_lo = 255, red_hi = 0, blue_lo = 255, blue_hi = 0;
  size_t shell_pixels = 0;
  for (size_t p = 0; p < g.cell_ids.size(); ++p) {
    if (g.cell_ids[p] != hall || g.rgba8[4 * p + 1] != 0) continue;
    ++shell_pixels;
    red_lo = std::min(red_lo, int(g.rgba8[4 * p])), red_hi = std::max(red_hi, int(g.rgba8[4 * p]));
    blue_lo = std::min(blue_lo, int(g.rgba8[4 * p + 2])), blue_hi = std::max(blue_hi, int(g.rgba8[4 * p + 2]));
  }
  std::printf("  graded hall: %zu shell pixels, red %d..%d, blue %d..%d\n", shell_pixels, red_lo, red_hi, blue_lo,
              blue_hi);
  EXPECT_GT(shell_pixels, hall_pixels / 4);
  EXPECT_GT(red_hi - red_lo, 100);
  EXPECT_GT(blue_hi, 240) << "the ceiling is blue";
  EXPECT_GT(blue_hi - blue_lo, 30);
}

}  // namespace
}  // namespace lintel::render::test
