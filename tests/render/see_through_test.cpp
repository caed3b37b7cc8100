// See-through surfaces (glTF alphaMode BLEND: glass) in the renderer: screen-door transparency.
// A point of glass with coverage c (base alpha x texture alpha x COLOR_0 alpha) shows on the
// pixels of a 4 x 4 ordered dither whose threshold is below c, and what lies behind it on the
// others; the shadow maps use the same dither, so the glass lets about 1 - c of the light through.
// Two rooms with a door (two_rooms.h); room A's crate is the glass.
#include "render_test_support.h"
#include "two_rooms.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace lintel::render::test {
namespace {

constexpr uint32_t kWidth = 96, kHeight = 54;

// two_rooms(door open) with room A's crate red glass of base alpha `alpha` (opaque when < 0).
World rooms_with_glass_crate(float alpha) {
  SceneDesc desc = two_rooms(true);
  MeshDesc& crate = crate_a(desc);
  crate.base_color = glm::vec4(1.0f, 0.0f, 0.0f, alpha < 0.0f ? 1.0f : alpha);
  if (alpha >= 0.0f) crate.alpha_mode = Mesh::AlphaMode::Blend;
  return built_world(desc);
}

View towards_crate() { return towards_crate_a(float(kWidth) / float(kHeight)); }

// From high in the corner behind the crate down at it, over the floor where the lamp (kLightA)
// casts its shadow.
View towards_crate_shadow() {
  View v;
  v.eye_world = {0.15f, 2.3f, 0.15f};
  v.target_world = {1.0f, 0.0f, 1.0f};
  v.aspect = float(kWidth) / float(kHeight);
  return v;
}

RenderedFrame render(gpu::Context& ctx, const World& world, uint32_t view, const View& camera = towards_crate()) {
  RenderOptions o = test_options(kWidth, kHeight);
  o.view = view;
  o.readback_hdr = true;
  o.gi = false;
  RenderedFrame f;
  std::unique_ptr<Renderer> r = make_renderer(ctx, world, o);
  if (!r) return f;
  const Status s = r->render(camera, uint32_t(world.find_cell("A")), f);
  EXPECT_TRUE(s.ok()) << s.message();
  return f;
}

bool same_pixel(const RenderedFrame& a, const RenderedFrame& b, size_t p) {
  for (size_t c = 0; c < 3; ++c)
    if (a.rgba8[4 * p + c] != b.rgba8[4 * p + c]) return false;
  return true;
}

class SeeThroughTest : public ValidatedGpu {};

// Property: the screen door shows, on each pixel, either the glass (as the opaque crate's frame
// has it) or what lies behind (as the frame with the glass at alpha 0, which draws nothing, has
// it), never anything else; and the glass on a fraction of its pixels close to its alpha (exactly
// 4 of 16 in every whole dither tile at alpha 0.25; whole and partial tiles together within 0.05).
TEST_F(SeeThroughTest, ScreenDoorShowsTheGlassOnItsCoverage) {
  const RenderedFrame opaque = render(ctx(), rooms_with_glass_crate(-1.0f), kViewAlbedo);
  const RenderedFrame gone = render(ctx(), rooms_with_glass_crate(0.0f), kViewAlbedo);
  ASSERT_EQ(opaque.rgba8.size(), size_t(kWidth) * kHeight * 4);
  ASSERT_EQ(gone.rgba8.size(), opaque.rgba8.size());
  size_t crate = 0, red_left = 0;
  for (size_t p = 0; p < size_t(kWidth) * kHeight; ++p) {
    crate += !same_pixel(opaque, gone, p);
    red_left += gone.rgba8[4 * p] == 255 && gone.rgba8[4 * p + 1] == 0 && gone.rgba8[4 * p + 2] == 0;
  }
  EXPECT_GT(crate, size_t(kWidth) * kHeight / 50) << "the crate is in the middle of the frame";
  EXPECT_EQ(red_left, 0u) << "glass of alpha 0 draws nothing";
  for (const float alpha : {0.25f, 0.5f, 0.75f}) {
    const RenderedFrame glass = render(ctx(), rooms_with_glass_crate(alpha), kViewAlbedo);
    ASSERT_EQ(glass.rgba8.size(), opaque.rgba8.size());
    size_t shown = 0, neither = 0;
    for (size_t p = 0; p < size_t(kWidth) * kHeight; ++p) {
      if (same_pixel(opaque, gone, p)) {
        neither += !same_pixel(glass, gone, p);
        continue;
      }
      if (same_pixel(glass, opaque, p))
        ++shown;
      else if (!same_pixel(glass, gone, p))
        ++neither;
    }
    const double fraction = double(shown) / double(crate);
    std::printf("  alpha %.2f: glass on %zu of %zu pixels (%.3f), %zu otherwise\n", alpha, shown, crate, fraction,
                neither);
    EXPECT_EQ(neither, 0u);
    EXPECT_NEAR(fraction, alpha, 0.05);
  }
}

// Property: glass casts a partial shadow, through the same dither in the shadow maps: on the
// floor where the opaque crate's shadow falls (lit with the crate gone, darker with it opaque),
// the glass crate of alpha 0.25 lets through on average about 0.75 of the light the opaque one
// stops (within 0.15: the shadow filter and the shadow maps' texels blur the dither).
TEST_F(SeeThroughTest, GlassCastsAPartialShadow) {
  const World opaque_world = rooms_with_glass_crate(-1.0f), gone_world = rooms_with_glass_crate(0.0f),
              glass_world = rooms_with_glass_crate(0.25f);
  const RenderedFrame crate_mask_a = render(ctx(), opaque_world, kViewAlbedo, towards_crate_shadow());
  const RenderedFrame crate_mask_b = render(ctx(), gone_world, kViewAlbedo, towards_crate_shadow());
  const RenderedFrame opaque = render(ctx(), opaque_world, kViewFinal, towards_crate_shadow());
  const RenderedFrame gone = render(ctx(), gone_world, kViewFinal, towards_crate_shadow());
  const RenderedFrame glass = render(ctx(), glass_world, kViewFinal, towards_crate_shadow());
  ASSERT_EQ(opaque.hdr.size(), size_t(kWidth) * kHeight);
  ASSERT_EQ(gone.hdr.size(), opaque.hdr.size());
  ASSERT_EQ(glass.hdr.size(), opaque.hdr.size());
  ASSERT_EQ(crate_mask_a.rgba8.size(), 4 * opaque.hdr.size());
  const auto luminance = [](const glm::vec4& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; };
  double passed = 0.0;
  size_t shadowed = 0;
  for (size_t p = 0; p < opaque.hdr.size(); ++p) {
    if (!same_pixel(crate_mask_a, crate_mask_b, p)) continue;  // the crate itself
    const double lit = luminance(gone.hdr[p]), dark = luminance(opaque.hdr[p]);
    if (!(lit > 0.0) || lit - dark < 0.2 * lit) continue;  // not in the crate's shadow
    passed += (luminance(glass.hdr[p]) - dark) / (lit - dark);
    ++shadowed;
  }
  const double mean = shadowed ? passed / double(shadowed) : 0.0;
  std::printf("  the crate's shadow: %zu pixels, the glass lets through %.3f of the light\n", shadowed, mean);
  EXPECT_GT(shadowed, 20u) << "the lamp casts the crate's shadow on the floor in view";
  EXPECT_NEAR(mean, 0.75, 0.15);
}

}  // namespace
}  // namespace lintel::render::test
