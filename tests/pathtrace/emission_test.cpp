// Emissive surfaces (Mesh::emissive, emissive_texture) in the path tracer: with no light and no
// sky, an emissive floor seen from above is its emission times its filtered texture (texels
// decoded to linear, as for base colour), and a large emissive ceiling lights the floor below it
// by ρ L, the reflected radiance of a Lambertian floor under a uniform hemisphere of radiance L
// (its irradiance is π L).
#include <lintel/reference/path_tracer.h>

#include "test_worlds.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace lintel {
namespace {

constexpr uint32_t kSize = 32;  // pixels each way

float linear(uint8_t srgb) {
  const double c = srgb / 255.0;
  return float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

View looking_down(float height) {
  View v;
  v.eye_world = {0.0f, height, 0.0f};
  v.target_world = {0.0f, 0.0f, 0.0f};
  v.up_world = {0.0f, 0.0f, -1.0f};
  v.fov_y_deg = 90.0f;
  v.aspect = 1.0f;
  return v;
}

LinearImage render(const World& world, const View& view, uint32_t spp, uint32_t bounces) {
  PathTracer pt;
  const Status s = pt.build(world);
  EXPECT_TRUE(s.ok()) << s.message();
  PathTraceOptions o;
  o.width = o.height = kSize;
  o.samples_per_pixel = spp;
  o.max_bounces = bounces;
  LinearImage img;
  if (s) pt.render(view, o, img);
  return img;
}

// Property: a camera ray that meets an emissive surface carries its emission times the emissive
// texture there; nothing else lights the scene, so the black-albedo floor seen from above is
// exactly that: a 2x2 texture of two greys, left half bright, right half dim.
TEST(PathTracerEmission, CameraSeesTheEmissionTimesItsTexture) {
  const glm::vec3 emissive(2.0f, 1.0f, 0.5f);
  constexpr uint8_t kBright = 255, kDim = 64;
  World w;
  Mesh floor = pathtrace_test::floor_mesh(1.0f, glm::vec3(0.0f));
  for (const glm::vec3& p : floor.positions) floor.uvs.push_back(glm::vec2((p.x + 1) / 2, (p.z + 1) / 2));
  floor.emissive = emissive;
  floor.emissive_texture = 0;
  floor.emissive_sampler.mag = TextureSampler::Filter::Nearest;  // no blend across the texel edge
  pathtrace_test::add_cell(w, floor);
  Texture t;
  t.width = t.height = 2;
  t.rgba8 = {kBright, kBright, kBright, 255, kDim, kDim, kDim, 255,
             kBright, kBright, kBright, 255, kDim, kDim, kDim, 255};
  w.textures = {t};
  const LinearImage img = render(w, looking_down(1.0f), 4, 2);
  ASSERT_EQ(img.rgb.size(), size_t(kSize) * kSize);
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) {
      if (x == kSize / 2 - 1 || x == kSize / 2) continue;  // pixels that straddle the texel edge
      const glm::vec3 want = emissive * linear(x < kSize / 2 ? kBright : kDim);
      const glm::vec3 got = img.rgb[size_t(y) * kSize + x];
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(got[c], want[c], 1e-4f * want[c]) << x << "," << y;
    }
}

// Property: emission travels along bounces like any radiance: a Lambertian floor of albedo ρ
// under a 100 x 100 m emissive ceiling of radiance L, 1 m up (it fills the floor's hemisphere
// but for under 0.05 % of its cosine-weighted solid angle), reflects ρ L; no light, no sky.
TEST(PathTracerEmission, EmissiveCeilingLightsTheFloorBelow) {
  const glm::vec3 albedo(0.5f, 0.25f, 0.75f);
  const float radiance = 3.0f;
  World w;
  pathtrace_test::add_cell(w, pathtrace_test::floor_mesh(1.0f, albedo));
  Mesh ceiling = pathtrace_test::floor_mesh(50.0f, glm::vec3(0.0f));
  ceiling.emissive = glm::vec3(radiance);
  pathtrace_test::add_cell(w, ceiling, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 1.0f, 0.0f)));
  const LinearImage img = render(w, looking_down(0.5f), 64, 1);
  ASSERT_EQ(img.rgb.size(), size_t(kSize) * kSize);
  // The cosine-weighted share of the hemisphere outside a disc of radius 49 m (inside the
  // ceiling from anywhere on the floor), 1 m up: h^2 / (r^2 + h^2).
  const float missing = 1.0f / (1.0f + 49.0f * 49.0f);
  glm::dvec3 mean(0.0);
  for (const glm::vec3& p : img.rgb) mean += glm::dvec3(p);
  mean /= double(img.rgb.size());
  std::printf("  floor under an emissive ceiling: %.4f %.4f %.4f (rho L = %.4f %.4f %.4f)\n", mean.x, mean.y, mean.z,
              albedo.x * radiance, albedo.y * radiance, albedo.z * radiance);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(mean[c], albedo[c] * radiance * (1.0f - missing), 0.02 * albedo[c] * radiance);
}

}  // namespace
}  // namespace lintel
