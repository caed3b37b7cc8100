// The CPU texture lookups that must read a texture as the g-buffer does (gbuffer.frag): the GI
// surfels' (render/src/base_color.h) and the path tracer's (lintel/reference/linear_texture.h). No GPU;
// render_texture_sampler_test holds the g-buffer itself to the first of them.
//  * Rule: on a 4x1 texture of linear values (1, 0, 0, L), hand-computed lookups for each wrap
//    mode (across the seams at u = 0 and 1), each filter and each mip mode, where mip level 1 is
//    (0.5, L / 2) and level 2 (1 + L) / 4. Both lookups give them (the renderer's levels are
//    rounded to 8-bit sRGB, hence its tolerance).
//  * Agreement: on small textures of random bytes (square, wide, tall, a single row), for every
//    sampler and a grid of uvs over [-2, 3] and levels of detail from -1 to 6, the two lookups
//    differ by no more than the renderer's 8-bit rounding of its levels (level 0: float noise).
//    The path tracer's copy is written from the Vulkan spec apart from the renderer's.
//  * Surfel footprint: a GI surfel's albedo is the texture over the area it stands for. A 1-texel
//    checker fine against a surfel (33 texels across) gives every floor surfel the checker's mean;
//    a coarse one (a texel 2.5 m across), read with nearest magnification, gives each surfel the
//    one texel under it, black or white.
//  * Surfel vertex colour: a surfel's albedo is the base colour times COLOR_0 interpolated at its
//    point, as the g-buffer's is.
#include "../scene/box_cells.h"
#include "base_color.h"
#include "gi_layout.h"
#include "render_scene.h"

#include <lintel/reference/linear_texture.h>
#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

namespace lintel::render {
namespace {

using Wrap = TextureSampler::Wrap;
using Filter = TextureSampler::Filter;
using MipMode = TextureSampler::MipMode;

float decode(uint8_t v) {
  const double c = v / 255.0;
  return float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

Texture grey_texture(uint32_t w, uint32_t h, const std::vector<uint8_t>& values) {
  Texture t;
  t.name = "test";
  t.width = w;
  t.height = h;
  t.rgba8.assign(size_t(w) * h * 4, 255);
  for (size_t i = 0; i < values.size(); ++i) t.rgba8[4 * i] = t.rgba8[4 * i + 1] = t.rgba8[4 * i + 2] = values[i];
  return t;
}

TextureSampler sampler(Wrap wrap, Filter mag, Filter min, MipMode mip) { return {wrap, wrap, mag, min, mip}; }

TEST(TextureLookup, HandComputedLookupsOfTheGBufferRule) {
  const Texture strip = grey_texture(4, 1, {255, 0, 0, 188});
  const float l = decode(188);  // about 0.503
  const TextureMips mips = texture_mips(strip);
  const reference::LinearTexture linear = reference::to_linear(strip);
  ASSERT_EQ(mips.sizes.size(), 3u);
  ASSERT_EQ(linear.levels.size(), 3u);
  const float level1 = 0.5f, level2 = (1.0f + l) / 4.0f;  // texel 0 of each level
  constexpr float kMagnify = -1.0f;
  struct Case {
    TextureSampler s;
    float u, lod, want;
    const char* what;
  };
  const Case cases[] = {
      // Linear magnification across the seams: u = 0 sits between texel 3 (or its mirror or
      // clamp) and texel 0.
      {sampler(Wrap::Repeat, Filter::Linear, Filter::Linear, MipMode::Linear), 0.0f, kMagnify, (1.0f + l) / 2.0f,
       "repeat u=0: texels 3 and 0"},
      {sampler(Wrap::ClampToEdge, Filter::Linear, Filter::Linear, MipMode::Linear), 0.0f, kMagnify, 1.0f, "clamp u=0"},
      {sampler(Wrap::MirroredRepeat, Filter::Linear, Filter::Linear, MipMode::Linear), 0.0f, kMagnify, 1.0f,
       "mirror u=0: texel 0 and its mirror image"},
      {sampler(Wrap::MirroredRepeat, Filter::Linear, Filter::Linear, MipMode::Linear), -0.25f, kMagnify, 0.5f,
       "mirror u=-0.25: texels 1 and 0 mirrored"},
      {sampler(Wrap::Repeat, Filter::Linear, Filter::Linear, MipMode::Linear), 1.0f, kMagnify, (l + 1.0f) / 2.0f,
       "repeat u=1"},
      {sampler(Wrap::ClampToEdge, Filter::Linear, Filter::Linear, MipMode::Linear), 1.0f, kMagnify, l, "clamp u=1"},
      {sampler(Wrap::MirroredRepeat, Filter::Linear, Filter::Linear, MipMode::Linear), 1.0f, kMagnify, l,
       "mirror u=1: texel 3 and its mirror image"},
      {sampler(Wrap::ClampToEdge, Filter::Linear, Filter::Linear, MipMode::Linear), 7.5f, kMagnify, l, "clamp far"},
      {sampler(Wrap::Repeat, Filter::Linear, Filter::Linear, MipMode::Linear), 0.3f, kMagnify, 0.3f,
       "repeat u=0.3: 0.7 of the way from texel 0 to 1"},
      // Nearest magnification: the texel u lies in (u = -0.1 is texel -1).
      {sampler(Wrap::Repeat, Filter::Nearest, Filter::Linear, MipMode::Linear), -0.1f, kMagnify, l, "nearest repeat"},
      {sampler(Wrap::ClampToEdge, Filter::Nearest, Filter::Linear, MipMode::Linear), -0.1f, kMagnify, 1.0f,
       "nearest clamp"},
      {sampler(Wrap::MirroredRepeat, Filter::Nearest, Filter::Linear, MipMode::Linear), -0.1f, kMagnify, 1.0f,
       "nearest mirror"},
      {sampler(Wrap::MirroredRepeat, Filter::Nearest, Filter::Linear, MipMode::Linear), 1.9f, kMagnify, 1.0f,
       "nearest mirror u=1.9: texel 7 of the mirrored pair is texel 0"},
      // lod <= 0 is magnification (the mag filter), lod > 0 minification (the min filter).
      {sampler(Wrap::Repeat, Filter::Nearest, Filter::Linear, MipMode::None), 0.3f, 0.0f, 0.0f, "lod 0: nearest mag"},
      {sampler(Wrap::Repeat, Filter::Nearest, Filter::Linear, MipMode::None), 0.3f, 0.01f, 0.3f,
       "lod 0.01: linear min at level 0"},
      {sampler(Wrap::Repeat, Filter::Linear, Filter::Nearest, MipMode::None), 0.3f, 3.0f, 0.0f,
       "no mipmaps: nearest min at level 0"},
      // Mip modes at u = 0.25 (texel 0's centre on level 1).
      {sampler(Wrap::Repeat, Filter::Linear, Filter::Linear, MipMode::Nearest), 0.25f, 1.4f, level1, "mip nearest 1.4"},
      {sampler(Wrap::Repeat, Filter::Linear, Filter::Linear, MipMode::Nearest), 0.25f, 1.6f, level2, "mip nearest 1.6"},
      {sampler(Wrap::Repeat, Filter::Linear, Filter::Linear, MipMode::Linear), 0.25f, 1.5f, (level1 + level2) / 2.0f,
       "mip linear 1.5"},
      {sampler(Wrap::Repeat, Filter::Linear, Filter::Linear, MipMode::Linear), 0.25f, 9.0f, level2,
       "lod past the last level"},
      {sampler(Wrap::Repeat, Filter::Linear, Filter::Nearest, MipMode::Linear), 0.1f, 1.0f, level1,
       "nearest min on level 1"},
  };
  for (const Case& c : cases) {
    const glm::vec2 uv(c.u, 0.5f);
    const float surfel = sample_texture(mips, c.s, uv, c.lod).g;
    const float traced = reference::sample_texture(linear, c.s, uv, c.lod).g;
    // The renderer stores levels 1.. as sRGB bytes: about half a step of rounding.
    EXPECT_NEAR(surfel, c.want, c.lod > 0.5f ? 5e-3f : 1e-5f) << c.what;
    EXPECT_NEAR(traced, c.want, 1e-5f) << c.what;
  }
}

TEST(TextureLookup, SurfelAndPathTracerLookupsAgree) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> byte(0, 255);
  size_t compared = 0;
  for (const glm::uvec2 size : {glm::uvec2(5, 5), glm::uvec2(8, 3), glm::uvec2(2, 7), glm::uvec2(6, 1)}) {
    Texture t;
    t.name = "random";
    t.width = size.x;
    t.height = size.y;
    t.rgba8.resize(size_t(size.x) * size.y * 4);
    for (uint8_t& b : t.rgba8) b = uint8_t(byte(rng));
    const TextureMips mips = texture_mips(t);
    const reference::LinearTexture linear = reference::to_linear(t);
    ASSERT_EQ(mips.sizes.size(), linear.levels.size());
    for (int ws = 0; ws < 3; ++ws)
      for (int wt = 0; wt < 3; ++wt)
        for (int filters = 0; filters < 4; ++filters)
          for (int mip = 0; mip < 3; ++mip) {
            const TextureSampler s{Wrap(ws), Wrap(wt), Filter(filters & 1), Filter(filters >> 1), MipMode(mip)};
            for (float u = -2.0f; u <= 3.0f; u += 0.137f)
              for (float v = -2.0f; v <= 3.0f; v += 0.193f)
                for (float lod = -1.0f; lod <= 6.0f; lod += 0.55f) {
                  const glm::vec3 a = sample_texture(mips, s, {u, v}, lod);
                  const glm::vec3 b = reference::sample_texture(linear, s, {u, v}, lod);
                  // Nearest filters jump at texel borders; both compute the same float u * width.
                  // The renderer rounds each level to 8-bit sRGB from the rounded level above.
                  const float tolerance = lod > 0.0f && mip != 0 ? 0.012f : 1e-5f;
                  for (int c = 0; c < 3; ++c) {
                    ASSERT_NEAR(a[c], b[c], tolerance)
                        << size.x << "x" << size.y << " wrap " << ws << "," << wt << " filters " << filters << " mip "
                        << mip << " uv " << u << "," << v << " lod " << lod;
                  }
                  ++compared;
                }
          }
  }
  std::printf("  %zu lookups agree\n", compared);
  EXPECT_GT(compared, size_t(1000000));
}

// One cell whose shell is a 10 x 10 m floor at y = 0, uv = (x, z) * uv_per_m, textured.
World textured_floor(float uv_per_m, const Texture& texture, const TextureSampler& s) {
  SceneDesc scene;
  MeshDesc floor;
  floor.name = "floor";
  floor.positions = {{-5, 0, -5}, {5, 0, -5}, {5, 0, 5}, {-5, 0, 5}};
  floor.indices = {0, 2, 1, 0, 3, 2};
  for (const glm::vec3& p : floor.positions) floor.uvs.push_back(glm::vec2(p.x, p.z) * uv_per_m + 0.5f);
  floor.base_color = glm::vec4(1.0f);
  floor.texture = 0;
  floor.sampler = s;
  floor.double_sided = true;
  scene.textures.push_back(texture);
  lintel::test::add_box_cell(scene, "room", {-5, 0, -5}, {5, 3, 5}, floor);
  World w;
  const Status st = build_world(scene, "textured floor", w);
  EXPECT_TRUE(st.ok()) << st.message();
  return w;
}

std::vector<float> floor_surfel_albedos(const World& world) {
  RenderScene scene;
  const Status s = build_render_scene(world, scene);
  EXPECT_TRUE(s.ok()) << s.message();
  const GiLayout layout = build_gi_layout(scene, GiOptions{});
  std::vector<float> out;
  for (const GpuSurfel& surfel : layout.surfels)
    if (surfel.albedo.w == 1.0f) out.push_back(surfel.albedo.g);
  return out;
}

TEST(TextureLookup, SurfelReadsTheTextureOverItsFootprint) {
  // 384 surfels on 100 m^2: 0.26 m^2 each, 33 texels across at 64 texels per metre (lod 5).
  std::vector<uint8_t> fine(64 * 64), coarse(4 * 4);
  for (size_t i = 0; i < fine.size(); ++i) fine[i] = ((i % 64) + (i / 64)) % 2 ? 255 : 0;
  for (size_t i = 0; i < coarse.size(); ++i) coarse[i] = ((i % 4) + (i / 4)) % 2 ? 255 : 0;
  const std::vector<float> averaged = floor_surfel_albedos(textured_floor(1.0f, grey_texture(64, 64, fine), {}));
  ASSERT_EQ(averaged.size(), GiOptions{}.surfels_per_cell);
  float lo = 1.0f, hi = 0.0f;
  for (float a : averaged) lo = std::min(lo, a), hi = std::max(hi, a);
  std::printf("  fine checker: floor surfel albedo in [%.4f, %.4f]\n", lo, hi);
  EXPECT_GT(lo, 0.49f);  // the 2x2 level holds 0.5 exactly; its 8-bit sRGB is 188 (0.5029)
  EXPECT_LT(hi, 0.51f);

  // 0.4 texels per metre: a texel is 2.5 m, a surfel 0.5 m: magnified, the texel under it.
  TextureSampler nearest;
  nearest.mag = Filter::Nearest;
  const std::vector<float> point = floor_surfel_albedos(textured_floor(0.1f, grey_texture(4, 4, coarse), nearest));
  size_t black = 0, white = 0;
  for (float a : point) black += a<1e-3f, white += a> 0.999f;
  std::printf("  coarse checker: %zu black and %zu white of %zu surfels\n", black, white, point.size());
  EXPECT_EQ(black + white, point.size());
  EXPECT_GT(black, point.size() / 4);
  EXPECT_GT(white, point.size() / 4);
}

TEST(TextureLookup, SurfelTakesTheVertexColourAtItsPoint) {
  // An untextured 10 x 10 m floor, red at x = -5 and green at x = +5 (and blue 0.5 throughout).
  World world = textured_floor(1.0f, grey_texture(1, 1, {255}), {});
  Mesh& floor = world.meshes[size_t(world.cells[0].shell_mesh)];
  floor.base_color_texture = -1;
  floor.base_color = glm::vec4(0.5f, 1.0f, 1.0f, 1.0f);
  for (const glm::vec3& p : floor.positions) {
    const float t = (p.x + 5.0f) / 10.0f;
    floor.colors.emplace_back(1.0f - t, t, 0.5f, 1.0f);
  }
  RenderScene scene;
  ASSERT_TRUE(build_render_scene(world, scene).ok());
  const GiLayout layout = build_gi_layout(scene, GiOptions{});
  size_t checked = 0;
  for (const GpuSurfel& surfel : layout.surfels) {
    if (surfel.albedo.w != 1.0f || std::abs(surfel.position_cell.y) > 1e-4f) continue;  // floor surfels only
    const float t = (surfel.position_cell.x + 5.0f) / 10.0f;
    EXPECT_NEAR(surfel.albedo.r, 0.5f * (1.0f - t), 1e-5f) << "x " << surfel.position_cell.x;
    EXPECT_NEAR(surfel.albedo.g, t, 1e-5f) << "x " << surfel.position_cell.x;
    EXPECT_NEAR(surfel.albedo.b, 0.5f, 1e-6f);
    ++checked;
  }
  EXPECT_GT(checked, size_t(100));
}

// Property: a surfel gives off the emissive factor times the emissive texture at its point, read
// like the base colour (sRGB decoded, its own sampler); surfels of a mesh without emission give
// off nothing. The floor's emissive texture is two texels, 255 (x < 0) and 64 (x > 0), read
// nearest at 0.1 uv per metre, so every floor surfel's emission is the factor times one of them.
TEST(TextureLookup, SurfelEmitsTheEmissiveTextureAtItsPoint) {
  const TextureSampler nearest = sampler(Wrap::ClampToEdge, Filter::Nearest, Filter::Nearest, MipMode::None);
  World world = textured_floor(0.1f, grey_texture(2, 1, {255, 64}), nearest);
  Mesh& floor = world.meshes[size_t(world.cells[0].shell_mesh)];
  const glm::vec3 factor(2.0f, 1.0f, 0.5f);
  floor.emissive = factor;
  floor.emissive_texture = 0;
  floor.emissive_sampler = nearest;
  floor.base_color_texture = -1;  // the emission does not depend on the base colour
  RenderScene scene;
  ASSERT_TRUE(build_render_scene(world, scene).ok());
  const GiLayout layout = build_gi_layout(scene, GiOptions{});
  std::array<size_t, 2> sides{};
  for (const GpuSurfel& surfel : layout.surfels) {
    if (surfel.albedo.w != 1.0f) continue;
    if (std::abs(surfel.position_cell.y) > 1e-4f) {  // the box's other faces: another mesh, no emission
      EXPECT_EQ(glm::vec3(surfel.emission), glm::vec3(0.0f));
      continue;
    }
    const bool right = surfel.position_cell.x > 0.0f;
    const glm::vec3 want = factor * decode(right ? 64 : 255);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(surfel.emission[c], want[c], 1e-5f) << "x " << surfel.position_cell.x;
    ++sides[right];
  }
  EXPECT_GT(sides[0], size_t(20));
  EXPECT_GT(sides[1], size_t(20));
}

// Property: a cut-out has no surfels where it has no surface. The floor's texture is two texels,
// alpha 255 (x < 0) and 0 (x > 0), read nearest; as a cut-out (alphaMode MASK) its surfels all
// lie on the covered half, and still more than a few do; drawn opaque, both halves get surfels.
TEST(TextureLookup, CutOutHasNoSurfelsWhereItIsUncovered) {
  Texture half = grey_texture(2, 1, {200, 200});
  half.rgba8[7] = 0;  // texel 1: alpha 0
  const TextureSampler nearest = sampler(Wrap::ClampToEdge, Filter::Nearest, Filter::Nearest, MipMode::None);
  World world = textured_floor(0.1f, half, nearest);
  auto floor_surfels_by_side = [](const World& w) {
    RenderScene scene;
    EXPECT_TRUE(build_render_scene(w, scene).ok());
    const GiLayout layout = build_gi_layout(scene, GiOptions{});
    std::array<size_t, 2> sides{};
    for (const GpuSurfel& surfel : layout.surfels)
      if (surfel.albedo.w == 1.0f && std::abs(surfel.position_cell.y) < 1e-4f) ++sides[surfel.position_cell.x > 0.0f];
    return sides;
  };
  const std::array<size_t, 2> opaque = floor_surfels_by_side(world);
  EXPECT_GT(opaque[0], size_t(20));
  EXPECT_GT(opaque[1], size_t(20));
  world.meshes[size_t(world.cells[0].shell_mesh)].alpha_mode = Mesh::AlphaMode::Mask;
  const std::array<size_t, 2> cut = floor_surfels_by_side(world);
  EXPECT_GT(cut[0], size_t(20));
  EXPECT_EQ(cut[1], 0u) << "surfels on the uncovered half";
}

}  // namespace
}  // namespace lintel::render
