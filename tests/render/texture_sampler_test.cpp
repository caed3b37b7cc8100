// Base-colour textures: mipmaps and the glTF sampler in the g-buffer, on one cell whose shell is
// a textured floor (albedo view, so lighting plays no part).
//  * Grazing angle: a checker of 1-texel squares seen along a 100 m floor. Where a pixel covers
//    many texels (the floor 10-40 m away), the mip chain averages them: the albedo there is the
//    checker's mean grey with a small spread. Control: the same floor with glTF minFilter LINEAR
//    (no mipmapping) aliases there, a spread several times larger, so the measure can fail.
//  * Wrap: a floor with u from -1 to 2 under a 4-texel strip (red, green, blue, white) seen from
//    above, nearest magnification. Every pixel away from texel borders shows the column its
//    wrapped u names (REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT); REPEAT and CLAMP differ exactly
//    where u lies outside [0, 1].
//  * The CPU lookup the GI surfels use (base_color.h, sample_texture) reads as the g-buffer does:
//    on random 4x4 and 16x16 textures, every wrap mode (on u, and another on v) and filter,
//    magnified (u and v from -1 to 2, linear filters across the seams included) and minified at a
//    known level of detail (a floor seen straight down: lod log2(3.5) everywhere; each mip mode),
//    the albedo pass matches the CPU lookup at each pixel's uv on >= 99 % of the pixels.
// About 25 s on the 2-core lavapipe machine (the lookup comparison renders 10 frames).
#include "../scene/box_cells.h"
#include "base_color.h"
#include "render_test_support.h"

#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>

namespace lintel::render::test {
namespace {

// One cell: a floor [-half, half]^2 at y = 0 with uv = (x, z) * uv_per_m + uv_offset, textured
// with `texture`; its volume reaches `height` up (above the eye).
World floor_world(float half, float uv_per_m, glm::vec2 uv_offset, const Texture& texture, float height = 10.0f) {
  SceneDesc s;
  MeshDesc floor;
  floor.name = "floor";
  floor.positions = {{-half, 0, -half}, {half, 0, -half}, {half, 0, half}, {-half, 0, half}};
  floor.normals.assign(4, glm::vec3(0, 1, 0));
  floor.indices = {0, 2, 1, 0, 3, 2};
  for (const glm::vec3& p : floor.positions) floor.uvs.push_back(glm::vec2(p.x, p.z) * uv_per_m + uv_offset);
  floor.base_color = glm::vec4(1.0f);
  floor.texture = 0;
  floor.double_sided = true;
  s.textures.push_back(texture);
  lintel::test::add_box_cell(s, "room", {-half, 0, -half}, {half, height, half}, floor);
  World w;
  const Status st = build_world(s, "textured floor", w);
  EXPECT_TRUE(st.ok()) << st.message();
  return w;
}

Texture image(uint32_t w, uint32_t h, const std::function<glm::u8vec3(uint32_t, uint32_t)>& texel) {
  Texture t;
  t.name = "test";
  t.width = w;
  t.height = h;
  t.rgba8.resize(size_t(w) * h * 4);
  for (uint32_t j = 0; j < h; ++j)
    for (uint32_t i = 0; i < w; ++i) {
      const glm::u8vec3 c = texel(i, j);
      uint8_t* p = &t.rgba8[(size_t(j) * w + i) * 4];
      p[0] = c.r;
      p[1] = c.g;
      p[2] = c.b;
      p[3] = 255;
    }
  return t;
}

// Where the ray through pixel (x, y)'s centre meets the plane y = 0 (false: it does not, ahead).
bool floor_hit(const View& v, uint32_t width, uint32_t height, uint32_t x, uint32_t y, glm::dvec3& hit) {
  const glm::dmat4 inv = glm::inverse(view_projection_d(v));
  const glm::dvec2 ndc((x + 0.5) / width * 2.0 - 1.0, 1.0 - (y + 0.5) / height * 2.0);
  const glm::dvec4 p = inv * glm::dvec4(ndc, 0.5, 1.0);
  const glm::dvec3 eye(v.eye_world), dir = glm::dvec3(p) / p.w - eye;
  if (dir.y >= 0.0) return false;
  hit = eye + dir * (-eye.y / dir.y);
  return true;
}

class TextureSamplerTest : public ValidatedGpu {
 protected:
  RenderedFrame albedo(const World& world, const View& view, uint32_t w, uint32_t h) {
    RenderOptions o = test_options(w, h);
    o.view = kViewAlbedo;
    o.gi = false;
    RenderedFrame f;
    std::unique_ptr<Renderer> r = make_renderer(ctx(), world, o);
    if (!r) return f;
    const Status s = r->render(view, 0, f);
    EXPECT_TRUE(s.ok()) << s.message();
    return f;
  }
};

struct Spread {
  double mean = 0.0, stddev = 0.0;
  size_t pixels = 0;
};

TEST_F(TextureSamplerTest, MipmapsAverageAGrazingCheckerToGrey) {
  constexpr uint32_t kW = 160, kH = 90;
  const Texture checker = image(64, 64, [](uint32_t i, uint32_t j) {
    const uint8_t v = (i + j) % 2 ? 255 : 0;
    return glm::u8vec3(v);
  });
  View v;
  v.eye_world = {0.0f, 1.0f, 45.0f};
  v.target_world = {0.0f, 0.6f, 35.0f};
  v.aspect = float(kW) / float(kH);
  auto far_spread = [&](const TextureSampler& sampler) {
    World world = floor_world(50.0f, 1.0f, glm::vec2(0.0f), checker);  // 64 texels per metre
    world.meshes[size_t(world.cells.at(0).shell_mesh)].base_color_sampler = sampler;
    const RenderedFrame f = albedo(world, v, kW, kH);
    Spread s;
    double sum = 0.0, sq = 0.0;
    for (uint32_t y = 0; y < kH && !f.rgba8.empty(); ++y)
      for (uint32_t x = 0; x < kW; ++x) {
        glm::dvec3 hit;
        if (!floor_hit(v, kW, kH, x, y, hit)) continue;
        const double d = glm::length(hit - glm::dvec3(v.eye_world));
        if (d < 10.0 || d > 40.0 || std::abs(hit.x) > 45.0 || std::abs(hit.z) > 45.0) continue;
        const double g = f.rgba8[(size_t(y) * kW + x) * 4 + 1];
        sum += g;
        sq += g * g;
        ++s.pixels;
      }
    if (s.pixels) {
      s.mean = sum / double(s.pixels);
      s.stddev = std::sqrt(std::max(0.0, sq / double(s.pixels) - s.mean * s.mean));
    }
    return s;
  };
  const Spread mipmapped = far_spread(TextureSampler{});
  TextureSampler no_mips;
  no_mips.mip = TextureSampler::MipMode::None;  // glTF minFilter 9729 (LINEAR)
  const Spread aliased = far_spread(no_mips);
  std::printf("  far floor (10-40 m): mipmapped mean %.1f sd %.1f, no mipmaps mean %.1f sd %.1f (%zu pixels)\n",
              mipmapped.mean, mipmapped.stddev, aliased.mean, aliased.stddev, mipmapped.pixels);
  ASSERT_GT(mipmapped.pixels, size_t(kW * 4));
  // The checker's mean is linear 0.5: sRGB 188 in the albedo view.
  EXPECT_NEAR(mipmapped.mean, 188.0, 12.0);
  EXPECT_LT(mipmapped.stddev, 16.0);
  // Measured on lavapipe: 0.0 with mipmaps, 24.5 without.
  EXPECT_GT(aliased.stddev, std::max(10.0, 3.0 * mipmapped.stddev));
}

TEST_F(TextureSamplerTest, WrapModesShowTheExpectedColumns) {
  constexpr uint32_t kSize = 128;
  const glm::u8vec3 kColumns[4] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};
  const Texture strip = image(4, 4, [&](uint32_t i, uint32_t) { return kColumns[i]; });
  View v;
  v.eye_world = {0.0f, 5.0f, 0.0f};
  v.target_world = {0.0f, 0.0f, 0.0f};
  v.up_world = {0.0f, 0.0f, -1.0f};  // screen right = +x
  v.fov_y_deg = 70.0f;
  v.aspect = 1.0f;
  using Wrap = TextureSampler::Wrap;
  auto wrapped = [](double u, Wrap mode) {
    if (mode == Wrap::ClampToEdge) return std::clamp(u, 0.0, 0.999999);
    if (mode == Wrap::MirroredRepeat) return 1.0 - std::abs(std::fmod(std::fmod(u, 2.0) + 2.0, 2.0) - 1.0);
    return u - std::floor(u);
  };
  std::vector<RenderedFrame> frames;
  std::vector<double> u_of_pixel(size_t(kSize) * kSize, std::nan(""));
  for (const Wrap mode : {Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat}) {
    // u = x / 2 + 0.5 over x in [-3, 3]: -1 .. 2.
    World world = floor_world(3.0f, 0.5f, glm::vec2(0.5f, 0.5f), strip);
    TextureSampler s;
    s.wrap_s = mode;
    s.mag = TextureSampler::Filter::Nearest;
    world.meshes[size_t(world.cells.at(0).shell_mesh)].base_color_sampler = s;
    frames.push_back(albedo(world, v, kSize, kSize));
    ASSERT_EQ(frames.back().rgba8.size(), size_t(kSize) * kSize * 4);
    size_t checked = 0, right = 0;
    for (uint32_t y = 0; y < kSize; ++y)
      for (uint32_t x = 0; x < kSize; ++x) {
        glm::dvec3 hit;
        if (!floor_hit(v, kSize, kSize, x, y, hit) || std::abs(hit.x) > 2.95 || std::abs(hit.z) > 2.95) continue;
        const double u = hit.x / 2.0 + 0.5;
        u_of_pixel[size_t(y) * kSize + x] = u;
        const double t = wrapped(u, mode) * 4.0;
        // Away from texel borders inside the strip (a clamped u sits on its edge, 0 or 4, on
        // purpose) and from u's own integer steps, where a wrap changes column.
        if ((t > 0.05 && t < 3.95 && std::abs(t - std::round(t)) < 0.1) || std::abs(u - std::round(u)) < 0.03) continue;
        const glm::u8vec3 want = kColumns[std::min(3, int(std::floor(t)))];
        const uint8_t* p = &frames.back().rgba8[(size_t(y) * kSize + x) * 4];
        ++checked;
        right += std::abs(p[0] - want.r) <= 2 && std::abs(p[1] - want.g) <= 2 && std::abs(p[2] - want.b) <= 2;
      }
    std::printf("  wrap mode %d: %zu of %zu pixels show the expected column\n", int(mode), right, checked);
    EXPECT_GT(checked, size_t(kSize * kSize / 4));
    EXPECT_GE(double(right), 0.995 * double(checked)) << "wrap mode " << int(mode);
  }
  // REPEAT against CLAMP: same inside u in [0, 1], different outside (where the columns differ).
  size_t inside = 0, inside_same = 0, outside = 0, outside_diff = 0;
  for (size_t p = 0; p < u_of_pixel.size(); ++p) {
    const double u = u_of_pixel[p];
    if (std::isnan(u) || std::abs(u * 4.0 - std::round(u * 4.0)) < 0.1) continue;
    const bool same = std::equal(&frames[0].rgba8[p * 4], &frames[0].rgba8[p * 4 + 3], &frames[1].rgba8[p * 4]);
    if (u > 0.0 && u < 1.0) {
      ++inside;
      inside_same += same;
    } else if (std::floor(wrapped(u, Wrap::Repeat) * 4.0) != std::floor(wrapped(u, Wrap::ClampToEdge) * 4.0)) {
      ++outside;
      outside_diff += !same;
    }
  }
  std::printf("  REPEAT vs CLAMP: %zu of %zu inside equal, %zu of %zu outside differ\n", inside_same, inside,
              outside_diff, outside);
  EXPECT_EQ(inside_same, inside);
  EXPECT_EQ(outside_diff, outside);
  EXPECT_GT(outside, size_t(1000));
}

Texture random_texture(uint32_t size, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> byte(0, 255);
  return image(size, size, [&](uint32_t, uint32_t) {
    return glm::u8vec3(uint8_t(byte(rng)), uint8_t(byte(rng)), uint8_t(byte(rng)));
  });
}

double decode_srgb(uint8_t v) {
  const double c = v / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

struct Agreement {
  size_t checked = 0, agree = 0;
  double worst = 0.0;
};

TEST_F(TextureSamplerTest, GBufferReadsAsTheCpuLookup) {
  constexpr uint32_t kSize = 128;
  using Wrap = TextureSampler::Wrap;
  using Filter = TextureSampler::Filter;
  using MipMode = TextureSampler::MipMode;
  View v;
  v.target_world = {0.0f, 0.0f, 0.0f};
  v.up_world = {0.0f, 0.0f, -1.0f};  // screen right = +x (u), down = +z (v)
  v.fov_y_deg = 70.0f;
  v.aspect = 1.0f;
  // Per pixel of the floor (away from its edge), the albedo pass against sample_texture at the
  // uv of the ray through the pixel's centre, for a level of detail within 0.05 of `lod` (the
  // device derives its own from uv derivatives: lavapipe's is about 0.03 below the exact value,
  // measured by shifting `lod`). The albedo is stored as linear 8-bit, then shown as sRGB:
  // compared in linear light, within 0.012 (about 3 steps of the first, 1 of the second at white)
  // of the values between those at lod - 0.05 and lod + 0.05. `nearest`: pixels within 0.05 texel
  // of a texel border are left out (sub-pixel uv differences pick the neighbour there).
  auto compare = [&](const World& world, float half, float uv_per_m, const TextureSampler& s, float lod, bool nearest) {
    Agreement a;
    const RenderedFrame f = albedo(world, v, kSize, kSize);
    if (f.rgba8.size() != size_t(kSize) * kSize * 4) return a;
    const Texture& t = world.textures.at(0);
    const TextureMips mips = texture_mips(t);
    for (uint32_t y = 0; y < kSize; ++y)
      for (uint32_t x = 0; x < kSize; ++x) {
        glm::dvec3 hit;
        if (!floor_hit(v, kSize, kSize, x, y, hit) || std::abs(hit.x) > half - 0.05 || std::abs(hit.z) > half - 0.05)
          continue;
        const glm::dvec2 uv = glm::dvec2(hit.x, hit.z) * double(uv_per_m) + 0.5;
        if (nearest) {
          const glm::dvec2 texel = uv * double(t.width);
          if (std::abs(texel.x - std::round(texel.x)) < 0.05 || std::abs(texel.y - std::round(texel.y)) < 0.05)
            continue;
        }
        const glm::vec3 below = sample_texture(mips, s, glm::vec2(uv), lod - 0.05f);
        const glm::vec3 above = sample_texture(mips, s, glm::vec2(uv), lod + 0.05f);
        const uint8_t* p = &f.rgba8[(size_t(y) * kSize + x) * 4];
        double err = 0.0;
        for (int c = 0; c < 3; ++c) {
          const double got = decode_srgb(p[c]);
          const double lo = std::min(below[c], above[c]), hi = std::max(below[c], above[c]);
          err = std::max({err, lo - got, got - hi});
        }
        ++a.checked;
        a.agree += err <= 0.012;
        a.worst = std::max(a.worst, err);
      }
    return a;
  };
  const Wrap wraps[] = {Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat};

  // Magnified: a 4x4 texture over u, v in [-1, 2] (2 texels per metre, 0.1 texel per pixel).
  v.eye_world = {0.0f, 5.0f, 0.0f};
  const Texture small = random_texture(4, 3);
  for (int w = 0; w < 3; ++w)
    for (const Filter mag : {Filter::Linear, Filter::Nearest}) {
      const TextureSampler s{wraps[w], wraps[(w + 1) % 3], mag, Filter::Linear, MipMode::Linear};
      World world = floor_world(3.0f, 0.5f, glm::vec2(0.5f), small);
      world.meshes[size_t(world.cells.at(0).shell_mesh)].base_color_sampler = s;
      const Agreement a = compare(world, 3.0f, 0.5f, s, -4.0f, mag == Filter::Nearest);
      std::printf("  magnified, wrap %d/%d, mag %s: %zu of %zu pixels agree (worst %.4f)\n", int(s.wrap_s),
                  int(s.wrap_t), mag == Filter::Nearest ? "nearest" : "linear", a.agree, a.checked, a.worst);
      EXPECT_GT(a.checked, size_t(kSize * kSize / 3));
      EXPECT_GE(double(a.agree), 0.99 * double(a.checked)) << "wrap " << w << " mag " << int(mag);
    }

  // Minified: a 16x16 texture, 8 texels per metre, seen straight down from 40 m: a pixel is
  // 40 * 2 tan(35 deg) / 128 = 0.4376 m, 3.5 texels, everywhere on the floor (lod 1.807).
  v.eye_world = {0.0f, 40.0f, 0.0f};
  const float lod = float(std::log2(40.0 * 2.0 * std::tan(glm::radians(35.0)) / kSize * 8.0));
  const Texture large = random_texture(16, 5);
  const TextureSampler minified[] = {
      TextureSampler{},  // the default: the hardware's own trilinear path
      {Wrap::Repeat, Wrap::MirroredRepeat, Filter::Linear, Filter::Linear, MipMode::Nearest},
      {Wrap::MirroredRepeat, Wrap::Repeat, Filter::Linear, Filter::Nearest, MipMode::Linear},
      {Wrap::Repeat, Wrap::Repeat, Filter::Linear, Filter::Nearest, MipMode::Nearest},
  };
  for (const TextureSampler& s : minified) {
    World world = floor_world(35.0f, 0.5f, glm::vec2(0.5f), large, 50.0f);
    world.meshes[size_t(world.cells.at(0).shell_mesh)].base_color_sampler = s;
    const Agreement a = compare(world, 35.0f, 0.5f, s, lod, s.min == Filter::Nearest);
    std::printf("  minified (lod %.3f), wrap %d/%d, min %d, mip %d: %zu of %zu pixels agree (worst %.4f)\n", lod,
                int(s.wrap_s), int(s.wrap_t), int(s.min), int(s.mip), a.agree, a.checked, a.worst);
    EXPECT_GT(a.checked, size_t(kSize * kSize / 2));
    EXPECT_GE(double(a.agree), 0.99 * double(a.checked)) << "mip " << int(s.mip) << " min " << int(s.min);
  }
}

}  // namespace
}  // namespace lintel::render::test
