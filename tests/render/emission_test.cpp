// Emissive surfaces (Mesh::emissive) in the renderer: the g-buffer's emission target carries
// what a surface gives off, the lighting adds it where the surface is seen, and the GI surfels
// emit it, so an emissive crate lights the room it stands in. Two rooms with a door
// (two_rooms.h); the crate of room A glows.
#include "render_test_support.h"
#include "two_rooms.h"

#include <lintel/reference/path_tracer.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

namespace lintel::render::test {
namespace {

constexpr uint32_t kWidth = 96, kHeight = 54;

// two_rooms(door open) with room A's crate emitting `emission`, with or without the lamp.
World rooms_with_glowing_crate(const glm::vec3& emission, bool lamp) {
  SceneDesc desc = two_rooms(true);
  if (!lamp) {
    desc.lights.clear();
    for (NodeDesc& n : desc.nodes) n.light = -1;
  }
  crate_a(desc).emissive = emission;
  return built_world(desc);
}

View towards_crate() { return towards_crate_a(float(kWidth) / float(kHeight)); }

RenderedFrame render(gpu::Context& ctx, const World& world, bool gi) {
  RenderOptions o = test_options(kWidth, kHeight);
  o.readback_hdr = true;
  o.readback_cells = true;
  o.gi = gi;
  RenderedFrame f;
  std::unique_ptr<Renderer> r = make_renderer(ctx, world, o);
  if (!r) return f;
  const Status s = r->render(towards_crate(), uint32_t(world.find_cell("A")), f);
  EXPECT_TRUE(s.ok()) << s.message();
  return f;
}

class EmissionTest : public ValidatedGpu {};

// Property: emission is added where the emissive surface is seen and nowhere else: with the
// lamp lit and GI off (so nothing else depends on the crate's emission), the frame with the
// crate glowing differs from the plain one by exactly the emission on the crate's pixels (float
// rounding of the sum aside) and not at all on every other pixel.
TEST_F(EmissionTest, EmissionIsAddedWhereTheSurfaceIsSeen) {
  const glm::vec3 glow(3.0f, 1.5f, 0.5f);  // exact in the half-float emission target
  const RenderedFrame plain = render(ctx(), rooms_with_glowing_crate(glm::vec3(0.0f), true), false);
  const RenderedFrame lit = render(ctx(), rooms_with_glowing_crate(glow, true), false);
  ASSERT_EQ(plain.hdr.size(), size_t(kWidth) * kHeight);
  ASSERT_EQ(lit.hdr.size(), plain.hdr.size());
  size_t glowing = 0, unchanged = 0, other = 0;
  for (size_t p = 0; p < plain.hdr.size(); ++p) {
    const glm::vec3 a(plain.hdr[p]), b(lit.hdr[p]);
    if (a == b) {
      ++unchanged;
      continue;
    }
    const glm::vec3 d = b - a;
    bool exact = true;
    for (int c = 0; c < 3; ++c) exact = exact && std::fabs(d[c] - glow[c]) <= 1e-5f * (1.0f + std::fabs(b[c]));
    (exact ? glowing : other)++;
  }
  std::printf("  crate glowing: %zu pixels + emission, %zu unchanged, %zu otherwise\n", glowing, unchanged, other);
  EXPECT_EQ(other, 0u);
  EXPECT_GT(glowing, plain.hdr.size() / 50) << "the crate is in the middle of the frame";
  EXPECT_GT(unchanged, plain.hdr.size() / 2);
}

// Property: the emissive texture multiplies the emission, read like a base colour texture (sRGB
// decoded, its glTF sampler): the crate's emissive texture is a checker of two greys read
// nearest, so each of its pixels changes by the factor times one of the two decoded greys
// (within 1 %), and both occur.
TEST_F(EmissionTest, EmissiveTextureMultipliesTheEmission) {
  const glm::vec3 glow(3.0f, 1.5f, 0.5f);
  constexpr uint8_t kBright = 255, kDim = 64;
  auto world_with = [&](bool emits) {
    SceneDesc desc = two_rooms(true);
    desc.textures.push_back(block_checker(8, 4, {kBright, kBright, kBright, 255}, {kDim, kDim, kDim, 255}));
    MeshDesc& m = crate_a(desc);
    for (const glm::vec3& p : m.positions) m.uvs.emplace_back(1.25f * (p.x + p.z), 1.25f * p.y);
    if (emits) {
      m.emissive = glow;
      m.emissive_texture = 0;
      m.emissive_sampler.mag = m.emissive_sampler.min = TextureSampler::Filter::Nearest;
      m.emissive_sampler.mip = TextureSampler::MipMode::None;
    }
    return built_world(desc);
  };
  const RenderedFrame plain = render(ctx(), world_with(false), false);
  const RenderedFrame lit = render(ctx(), world_with(true), false);
  ASSERT_EQ(plain.hdr.size(), size_t(kWidth) * kHeight);
  ASSERT_EQ(lit.hdr.size(), plain.hdr.size());
  const auto decode = [](uint8_t srgb) {
    const double c = srgb / 255.0;
    return float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
  };
  std::array<size_t, 2> seen{};
  size_t other = 0;
  for (size_t p = 0; p < plain.hdr.size(); ++p) {
    const glm::vec3 d = glm::vec3(lit.hdr[p]) - glm::vec3(plain.hdr[p]);
    if (d == glm::vec3(0.0f)) continue;
    bool matched = false;
    for (int k = 0; k < 2 && !matched; ++k) {
      const glm::vec3 want = glow * decode(k == 0 ? kBright : kDim);
      bool close = true;
      // 1 %: lavapipe's sRGB decode of 64 is 0.4 % above the exact curve's.
      for (int c = 0; c < 3; ++c) close = close && std::fabs(d[c] - want[c]) <= 1e-2f * want[c];
      if (close) ++seen[size_t(k)], matched = true;
    }
    other += !matched;
  }
  std::printf("  emissive checker: %zu bright, %zu dim, %zu otherwise\n", seen[0], seen[1], other);
  EXPECT_EQ(other, 0u);
  EXPECT_GT(seen[0], 10u);
  EXPECT_GT(seen[1], 10u);
}

// Property: an emissive surface lights its room through the GI as the path tracer says it does:
// with no lamp (and so no sky: the glowing crate is the scene's light source), room A's other
// surfaces are black without GI and lit with it, each pixel, and their mean radiance is within a
// factor of 1.5 of the path-traced mean over the same pixels.
TEST_F(EmissionTest, EmissiveSurfaceLightsItsRoomThroughTheGi) {
  const glm::vec3 glow(8.0f);
  const World world = rooms_with_glowing_crate(glow, false);
  ASSERT_EQ(world.environment, glm::vec3(0.0f)) << "emission counts as a light source: no default sky";
  const RenderedFrame direct = render(ctx(), world, false);
  const RenderedFrame gi = render(ctx(), world, true);
  ASSERT_EQ(direct.hdr.size(), size_t(kWidth) * kHeight);
  ASSERT_EQ(gi.hdr.size(), direct.hdr.size());

  PathTracer pt;
  const Status built = pt.build(world);
  ASSERT_TRUE(built.ok()) << built.message();
  PathTraceOptions po;
  po.width = kWidth;
  po.height = kHeight;
  po.samples_per_pixel = 32;
  LinearImage reference;
  pt.render(towards_crate(), po, reference);
  ASSERT_EQ(reference.rgb.size(), direct.hdr.size());

  const uint32_t room_a = uint32_t(world.find_cell("A"));
  size_t crate = 0, surfaces = 0, lit = 0;
  double rendered = 0.0, traced = 0.0;
  for (size_t p = 0; p < direct.hdr.size(); ++p) {
    if ((direct.cell_ids[p] & kCellIdMask) != room_a || direct.cell_ids[p] == kNoCell) continue;
    const glm::vec3 d(direct.hdr[p]);
    if (d == glow) {  // the crate itself: its emission, nothing else lights it without GI
      ++crate;
      continue;
    }
    EXPECT_EQ(d, glm::vec3(0.0f)) << "pixel " << p << ": no light but the crate's, and no GI";
    ++surfaces;
    const glm::vec3 g(gi.hdr[p]);
    lit += g.x > 0.0f && g.y > 0.0f && g.z > 0.0f;
    rendered += (g.x + g.y + g.z) / 3.0;
    const glm::vec3 r = reference.rgb[p];
    traced += (r.x + r.y + r.z) / 3.0;
  }
  ASSERT_GT(crate, 0u);
  ASSERT_GT(surfaces, direct.hdr.size() / 4);
  rendered /= double(surfaces);
  traced /= double(surfaces);
  std::printf("  room A lit by the crate alone: %zu of %zu pixels lit, mean radiance %.3f (path traced %.3f)\n", lit,
              surfaces, rendered, traced);
  EXPECT_EQ(lit, surfaces);
  EXPECT_GT(traced, 0.0);
  EXPECT_LT(rendered, 1.5 * traced);
  EXPECT_GT(rendered, traced / 1.5);
}

}  // namespace
}  // namespace lintel::render::test
