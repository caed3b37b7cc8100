// The base colour texture in the path tracer: a floor quad textured with a 2x2 image under a
// directional light straight down, seen from straight above with no bounces, so that every pixel
// is factor / pi * E * (the filtered texture over the pixel). The four texels differ, so a flipped
// or transposed lookup fails; the pixel on the boundary between a white and a black texel is 0.5
// only when texels are decoded to linear before filtering (0.21 if filtered first). The glTF
// sampler and the ray cone's mip level: a nearest magnification filter keeps a texel edge sharp,
// and a checker finer than the pixels reads as its mean grey at one sample per pixel. Vertex
// colours (COLOR_0) multiply the factor, interpolated over the triangle. Cut-outs (alphaMode
// MASK) let every ray through where their coverage is below the cutoff.
#include <lintel/reference/path_tracer.h>

#include "test_worlds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lintel {
namespace {

constexpr float kPi = 3.14159265358979f;
constexpr uint32_t kSize = 64;  // pixels each way; the floor [-1, 1]^2 fills the image
const glm::vec3 kFactor(0.5f, 0.25f, 0.75f);
constexpr float kIrradiance = 3.0f;

// sRGB values of the texels (grey, all channels equal), rows top to bottom.
constexpr uint8_t kTexels[2][2] = {{255, 0}, {188, 128}};

float linear(uint8_t srgb) {
  const double c = srgb / 255.0;
  return float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

// The 2x2 texture of kTexels.
Texture four_texels() {
  Texture t;
  t.name = "test";
  t.width = t.height = 2;
  // Indexed writes: GCC 12 warns falsely (-Wstringop-overflow) on vector::insert of a braced list.
  t.rgba8.assign(16, 255);
  for (size_t i = 0; i < 4; ++i)
    for (size_t c = 0; c < 3; ++c) t.rgba8[4 * i + c] = kTexels[i / 2][i % 2];
  return t;
}

// uv = (x + 1) / 2 + offset.x, (z + 1) / 2 + offset.y over the floor's corners.
World textured_floor(glm::vec2 uv_offset, const Texture& texture = four_texels(), const TextureSampler& sampler = {}) {
  World w;
  Mesh floor = pathtrace_test::floor_mesh(1.0f, kFactor);
  for (const glm::vec3& p : floor.positions) floor.uvs.push_back(glm::vec2((p.x + 1) / 2, (p.z + 1) / 2) + uv_offset);
  floor.base_color_texture = 0;
  floor.base_color_sampler = sampler;
  pathtrace_test::add_cell(w, floor);
  w.textures = {texture};
  Light sun;
  sun.type = Light::Type::Directional;
  sun.intensity = kIrradiance;
  sun.direction_world = {0.0f, -1.0f, 0.0f};
  w.lights = {sun};
  return w;
}

// Image x along +X, rows along +Z (u right, v down on the screen too); the floor fills the view.
View looking_down() {
  View v;
  v.eye_world = {0.0f, 1.0f, 0.0f};
  v.target_world = {0.0f, 0.0f, 0.0f};
  v.up_world = {0.0f, 0.0f, -1.0f};
  v.fov_y_deg = 90.0f;
  v.aspect = 1.0f;
  return v;
}

// The built tracer's image from above, direct light only.
LinearImage render_built_from_above(const PathTracer& pt, uint32_t spp) {
  PathTraceOptions o;
  o.width = o.height = kSize;
  o.samples_per_pixel = spp;
  o.max_bounces = 0;
  LinearImage img;
  pt.render(looking_down(), o, img);
  return img;
}

LinearImage render_from_above(const World& world, uint32_t spp) {
  PathTracer pt;
  const Status s = pt.build(world);
  EXPECT_TRUE(s.ok()) << s.message();
  return s ? render_built_from_above(pt, spp) : LinearImage{};
}

TEST(PathTracerTexture, PixelsFollowTheTexelsDecodedBeforeFiltering) {
  // REPEAT: shifting every uv by whole numbers changes nothing.
  for (const glm::vec2 offset : {glm::vec2(0.0f), glm::vec2(3.0f, -2.0f)}) {
    const LinearImage img = render_from_above(textured_floor(offset), 16);
    ASSERT_EQ(img.rgb.size(), size_t(kSize) * kSize);
    const auto pixel = [&img](uint32_t x, uint32_t y) { return img.rgb[size_t(y) * kSize + x]; };
    const glm::vec3 white = kFactor / kPi * kIrradiance;  // a texel of linear value 1

    // Pixel 15 spans x in [-0.531, -0.5]: at most 1/32 texel from the centre of texel column 0,
    // so the bilinear blend moves the mean by about 3% (hence the tolerance).
    const uint32_t near_left = 15, near_right = 48;  // just beside the texel centres -0.5 and +0.5
    const struct {
      uint32_t x, y;
      uint8_t texel;
    } centres[] = {{near_left, near_left, kTexels[0][0]},
                   {near_right, near_left, kTexels[0][1]},
                   {near_left, near_right, kTexels[1][0]},
                   {near_right, near_right, kTexels[1][1]}};
    for (const auto& c : centres) {
      const glm::vec3 want = white * linear(c.texel);
      for (int ch = 0; ch < 3; ++ch)
        EXPECT_NEAR(pixel(c.x, c.y)[ch], want[ch], 0.04f * white[ch])
            << "pixel " << c.x << "," << c.y << " texel " << int(c.texel) << " offset " << offset.x;
    }
    // Over the black texel (top right): close to nothing.
    EXPECT_LT(pixel(near_right, near_left).x, 0.04f * white.x);

    // Pixel 31 ends at x = 0, the boundary between the white (0, 0) and black (1, 0) texels, in
    // row 15 (beside the top row's centre): half of white in linear light, a little more on the
    // white side; filtering the sRGB values first would give srgb_to_linear(0.5) = 0.21.
    const glm::vec3 boundary = pixel(31, near_left);
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(boundary[ch], 0.5f * white[ch], 0.04f * white[ch]) << "boundary";
  }
}

// A nearest magnification filter (glTF magFilter NEAREST) keeps the texel edge sharp: the pixel
// beside the white/black boundary, which the linear filter makes half white, is all white.
TEST(PathTracerTexture, NearestMagnificationKeepsTexelsWhole) {
  TextureSampler nearest;
  nearest.mag = TextureSampler::Filter::Nearest;
  const LinearImage img = render_from_above(textured_floor(glm::vec2(0.0f), four_texels(), nearest), 16);
  ASSERT_EQ(img.rgb.size(), size_t(kSize) * kSize);
  const glm::vec3 white = kFactor / kPi * kIrradiance;
  const glm::vec3 boundary = img.rgb[15 * kSize + 31];
  for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(boundary[ch], white[ch], 0.01f * white[ch]) << "nearest";
  EXPECT_LT(img.rgb[15 * kSize + 32].x, 0.01f * white.x) << "just across the edge: the black texel";
}

// Ray cones pick the mip level: a checker of single texels, 4 of them across a pixel at the
// image centre (lod 2; up to 3.6 towards the corners), reads as its mean grey in every pixel with
// one sample per pixel. Level 0 at one point per pixel would show black or white.
TEST(PathTracerTexture, RayConesReadAFineCheckerAsItsMean) {
  constexpr uint32_t kSide = 256;
  Texture checker;
  checker.name = "checker";
  checker.width = checker.height = kSide;
  checker.rgba8.assign(size_t(kSide) * kSide * 4, 255);
  for (uint32_t j = 0; j < kSide; ++j)
    for (uint32_t i = 0; i < kSide; ++i)
      for (size_t c = 0; c < 3; ++c) checker.rgba8[(size_t(j) * kSide + i) * 4 + c] = (i + j) % 2 ? 255 : 0;
  const LinearImage img = render_from_above(textured_floor(glm::vec2(0.0f), checker), 1);
  ASSERT_EQ(img.rgb.size(), size_t(kSize) * kSize);
  const glm::vec3 grey = 0.5f * kFactor / kPi * kIrradiance;
  float lo = 1e9f, hi = 0.0f;
  for (const glm::vec3& p : img.rgb) lo = std::min(lo, p.x / grey.x), hi = std::max(hi, p.x / grey.x);
  std::printf("  fine checker at 1 spp: pixels from %.4f to %.4f of the mean\n", lo, hi);
  EXPECT_GT(lo, 0.99f);
  EXPECT_LT(hi, 1.01f);
}

TEST(PathTracerTexture, TexturedMeshWithoutUvsIsABuildError) {
  World w = textured_floor(glm::vec2(0.0f));
  w.meshes[0].uvs.clear();
  PathTracer pt;
  const Status s = pt.build(w);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("mesh 'floor'"), std::string::npos) << s.message();
}

// A floor red at x = -1 and green at x = +1 (blue 0.5 throughout), untextured: each pixel is
// factor / pi * E * the colour interpolated at its centre's column, a linear ramp.
TEST(PathTracerVertexColor, PixelsFollowTheInterpolatedVertexColours) {
  World w = textured_floor(glm::vec2(0.0f));
  Mesh& floor = w.meshes[0];
  floor.base_color_texture = -1;
  floor.uvs.clear();
  for (const glm::vec3& p : floor.positions) {
    const float t = (p.x + 1.0f) / 2.0f;
    floor.colors.emplace_back(1.0f - t, t, 0.5f, 1.0f);
  }
  const LinearImage img = render_from_above(w, 16);
  ASSERT_EQ(img.rgb.size(), size_t(kSize) * kSize);
  const glm::vec3 white = kFactor / kPi * kIrradiance;
  for (const uint32_t x : {2u, 16u, 31u, 47u, 61u}) {
    const float t = (float(x) + 0.5f) / float(kSize);  // the pixel centre's (x + 1) / 2
    const glm::vec3 want = white * glm::vec3(1.0f - t, t, 0.5f);
    const glm::vec3 got = img.rgb[size_t(kSize / 2) * kSize + x];
    for (int ch = 0; ch < 3; ++ch)
      EXPECT_NEAR(got[ch], want[ch], 0.02f * white[ch] + 1e-6f) << "pixel " << x << " channel " << ch;
  }
}

// Cut-outs (alphaMode MASK): the textured floor, white, its left texel column covered (alpha
// 255) and its right one not (alpha 0), over a second floor 0.5 m below, under the sun. Seen from
// above, the left half shows the cut-out; the right half shows the floor below, lit: the camera
// ray passes the uncovered texels, and so does the sun's shadow ray. With the base colour's alpha
// below the cutoff (untextured), the cut-out is gone everywhere; with COLOR_0's alpha falling
// from 1 to 0 across it, it is there where that alpha is at least the cutoff.
TEST(PathTracerCutOut, RaysPassWhereCoverageIsBelowTheCutoff) {
  const glm::vec3 below(0.2f, 0.6f, 0.3f);
  auto scene = [&](bool textured, float base_alpha) {
    Texture half;
    half.name = "left half covered";
    half.width = half.height = 2;
    half.rgba8.assign(16, 255);
    for (size_t i : {1u, 3u}) half.rgba8[4 * i + 3] = 0;  // texel column 1: alpha 0
    World w = textured_floor(glm::vec2(0.0f), half);
    Mesh& cut = w.meshes[0];
    cut.alpha_mode = Mesh::AlphaMode::Mask;
    cut.alpha_cutoff = 0.5f;
    cut.base_color.a = base_alpha;
    if (!textured) cut.base_color_texture = -1, cut.uvs.clear();
    Mesh lower = pathtrace_test::floor_mesh(2.0f, below);
    for (glm::vec3& p : lower.positions) p.y = -0.5f;
    pathtrace_test::add_cell(w, lower);
    return w;
  };
  const glm::vec3 white = kFactor / kPi * kIrradiance, floor_below = below / kPi * kIrradiance;
  const uint32_t left = 15, right = 48, row = kSize / 2;
  {
    // Built from a World that is gone before the render (build() says it need not outlive the
    // tracer: what the cut-out reads must be the tracer's copies; clean under valgrind).
    PathTracer pt;
    ASSERT_TRUE(pt.build(scene(true, 1.0f)).ok());
    const LinearImage img = render_built_from_above(pt, 4);
    ASSERT_EQ(img.rgb.size(), size_t(kSize) * kSize);
    for (int ch = 0; ch < 3; ++ch) {
      EXPECT_NEAR(img.rgb[row * kSize + left][ch], white[ch], 0.01f * white[ch]) << "the covered half";
      EXPECT_NEAR(img.rgb[row * kSize + right][ch], floor_below[ch], 0.01f * floor_below[ch])
          << "through the uncovered half, the lit floor below";
    }
  }
  {
    const LinearImage img = render_from_above(scene(false, 0.4f), 4);
    ASSERT_EQ(img.rgb.size(), size_t(kSize) * kSize);
    for (const uint32_t x : {left, right})
      for (int ch = 0; ch < 3; ++ch)
        EXPECT_NEAR(img.rgb[row * kSize + x][ch], floor_below[ch], 0.01f * floor_below[ch])
            << "base alpha 0.4 < cutoff 0.5: nothing of the cut-out, pixel " << x;
  }
  {
    // COLOR_0's alpha multiplies the coverage: untextured, alpha 1 at x = -1 falling to 0 at
    // x = +1, so covered where x < 0 (rgb white: the albedo is unchanged).
    World w = scene(false, 1.0f);
    Mesh& cut = w.meshes[0];
    for (const glm::vec3& p : cut.positions) cut.colors.emplace_back(1.0f, 1.0f, 1.0f, (1.0f - p.x) / 2.0f);
    const LinearImage img = render_from_above(w, 4);
    ASSERT_EQ(img.rgb.size(), size_t(kSize) * kSize);
    for (int ch = 0; ch < 3; ++ch) {
      EXPECT_NEAR(img.rgb[row * kSize + left][ch], white[ch], 0.01f * white[ch]) << "vertex alpha about 0.76";
      EXPECT_NEAR(img.rgb[row * kSize + right][ch], floor_below[ch], 0.01f * floor_below[ch]) << "vertex alpha 0.24";
    }
  }
}

// See-through surfaces (alphaMode BLEND: glass): a ray passes a point with probability 1 -
// coverage, the renderer's screen-door transparency in expectation. White glass of alpha 0.3
// over the floor 0.5 m below, under the sun: a camera ray sees the glass with probability 0.3
// (lit: white); otherwise the floor below, whose shadow ray passes the glass with probability
// 0.7. So the mean over the middle of the image, where the floor seen below has the glass above
// it (image x and z within 2/3 of the centre: the floor below is 1.5 times as far), is 0.3 white
// + 0.49 of the lit floor (rays from below meet the glass's back face, which a single-sided
// surface does not have: no light between the two).
TEST(PathTracerGlass, RaysPassWithProbabilityOneMinusCoverage) {
  const glm::vec3 below(0.2f, 0.6f, 0.3f);
  World w = textured_floor(glm::vec2(0.0f));
  Mesh& glass = w.meshes[0];
  glass.alpha_mode = Mesh::AlphaMode::Blend;
  glass.base_color = glm::vec4(1.0f, 1.0f, 1.0f, 0.3f);
  glass.base_color_texture = -1;
  glass.uvs.clear();
  Mesh lower = pathtrace_test::floor_mesh(2.0f, below);
  for (glm::vec3& p : lower.positions) p.y = -0.5f;
  pathtrace_test::add_cell(w, lower);
  const LinearImage img = render_from_above(w, 64);
  ASSERT_EQ(img.rgb.size(), size_t(kSize) * kSize);
  const glm::vec3 white(1.0f / kPi * kIrradiance), floor_below = below / kPi * kIrradiance;
  const glm::vec3 want = 0.3f * white + 0.49f * floor_below;
  glm::dvec3 sum(0.0);
  size_t n = 0;
  for (uint32_t y = 13; y < kSize - 13; ++y)  // |pixel centre| < 0.6 of the half image
    for (uint32_t x = 13; x < kSize - 13; ++x, ++n) sum += glm::dvec3(img.rgb[size_t(y) * kSize + x]);
  const glm::vec3 mean = glm::vec3(sum / double(n));
  std::printf("  glass alpha 0.3: mean %.4f %.4f %.4f, expected %.4f %.4f %.4f\n", mean.x, mean.y, mean.z, want.x,
              want.y, want.z);
  for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(mean[ch], want[ch], 0.02f * want[ch]) << "channel " << ch;
  // Opaque, the same glass hides the floor: every pixel is white (add_cell moved the meshes).
  w.meshes[0].alpha_mode = Mesh::AlphaMode::Opaque;
  const LinearImage solid = render_from_above(w, 4);
  for (int ch = 0; ch < 3; ++ch)
    EXPECT_NEAR(solid.rgb[size_t(kSize / 2) * kSize + kSize / 2][ch], white[ch], 0.01f * white[ch]);
}

}  // namespace
}  // namespace lintel
