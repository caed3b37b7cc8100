// Irradiance the path tracer must reproduce exactly: a floor under a directional light (every
// pixel a / pi * E, noise-free), under a point light (inverse square and cosine, with and without
// the range window) and under a spot light (the cone), each against the formulas of path_tracer.h.
#include <lintel/reference/path_tracer.h>

#include "test_worlds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace lintel {
namespace {

using pathtrace_test::add_cell;
using pathtrace_test::floor_mesh;
using pathtrace_test::point_light;

constexpr float kPi = 3.14159265358979f;
const glm::vec3 kAlbedo(0.5f, 0.25f, 0.75f);  // distinct channels catch a swapped or dropped one

// A camera `height` above the origin looking straight down; image x runs along +X, image rows
// along +Z (up is -Z).
View looking_down(float height, float fov_y_deg, float aspect) {
  View v;
  v.eye_world = {0.0f, height, 0.0f};
  v.target_world = {0.0f, 0.0f, 0.0f};
  v.up_world = {0.0f, 0.0f, -1.0f};
  v.fov_y_deg = fov_y_deg;
  v.aspect = aspect;
  return v;
}

// Where pixel (x, y)'s centre ray meets the floor y = 0, for a looking_down() view.
glm::vec3 floor_point(const View& v, uint32_t x, uint32_t y, uint32_t w, uint32_t h) {
  const float tan_half = std::tan(glm::radians(v.fov_y_deg) * 0.5f);
  const float ndc_x = (float(x) + 0.5f) / float(w) * 2.0f - 1.0f;
  const float ndc_y = 1.0f - (float(y) + 0.5f) / float(h) * 2.0f;
  return {ndc_x * tan_half * v.aspect * v.eye_world.y, 0.0f, -ndc_y * tan_half * v.eye_world.y};
}

LinearImage render(const World& w, const View& v, uint32_t width, uint32_t height, uint32_t spp, uint32_t bounces) {
  PathTracer pt;
  EXPECT_TRUE(pt.build(w).ok());
  PathTraceOptions o;
  o.width = width;
  o.height = height;
  o.samples_per_pixel = spp;
  o.max_bounces = bounces;
  LinearImage img;
  pt.render(v, o, img);
  EXPECT_EQ(img.rgb.size(), size_t{width} * height);
  return img;
}

void expect_rgb_near(const glm::vec3& got, const glm::vec3& want, float rel_tol, const char* where) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(got[c], want[c], rel_tol * std::max(want[c], 1e-6f)) << where << " channel " << c;
}

TEST(PathTracerAnalytic, FloorUnderDirectionalLightIsAlbedoOverPiTimesIrradiance) {
  for (const float tilt_deg : {0.0f, 60.0f}) {
    World w;
    add_cell(w, floor_mesh(1000.0f, kAlbedo));
    Light sun;
    sun.type = Light::Type::Directional;
    sun.color = {1.0f, 0.8f, 0.6f};
    sun.intensity = 3.0f;
    const float tilt = glm::radians(tilt_deg);
    sun.direction_world = {std::sin(tilt), -std::cos(tilt), 0.0f};
    w.lights = {sun};
    const glm::vec3 want = kAlbedo / kPi * sun.color * sun.intensity * std::cos(tilt);
    // Bounces change nothing: every bounce ray escapes to the black sky.
    for (const uint32_t bounces : {0u, 3u}) {
      const LinearImage img = render(w, looking_down(5.0f, 60.0f, 16.0f / 9.0f), 16, 9, 4, bounces);
      for (const glm::vec3& px : img.rgb) expect_rgb_near(px, want, 1e-5f, "directional");
    }
  }
}

// Irradiance of a point light `h` above the floor at horizontal distance r, range window included.
float point_irradiance(float intensity, float h, float r, float range) {
  const float d2 = h * h + r * r, d = std::sqrt(d2);
  float window = 1.0f;
  if (range > 0.0f) window = std::pow(std::clamp(1.0f - std::pow(d / range, 4.0f), 0.0f, 1.0f), 2.0f);
  return intensity * window / d2 * (h / d);
}

TEST(PathTracerAnalytic, FloorUnderPointLightFollowsInverseSquareCosineAndWindow) {
  constexpr uint32_t kSize = 33;  // odd: the centre pixel's centre lies right under the light
  constexpr float kHeight = 1.5f, kIntensity = 10.0f;
  for (const float range : {0.0f, 2.0f}) {
    World w;
    add_cell(w, floor_mesh(100.0f, kAlbedo));
    w.lights = {point_light({0.0f, kHeight, 0.0f}, kIntensity, range)};
    const View v = looking_down(4.0f, 40.0f, 1.0f);
    const LinearImage img = render(w, v, kSize, kSize, 64, 0);
    // (b) of the issue: the pixel under the light is a / pi * I / h^2 (times the window); the
    // falloff's curvature over the jittered pixel keeps it about 0.1% below that.
    const glm::vec3 centre = img.rgb[(kSize / 2) * kSize + kSize / 2];
    expect_rgb_near(centre, kAlbedo / kPi * point_irradiance(kIntensity, kHeight, 0.0f, range), 5e-3f,
                    "under the light");
    // Along the centre row the falloff is I * h / d^3. Jitter averages over the pixel, so the
    // tolerance covers the curvature of that falloff across one pixel (about 0.1 m here).
    for (uint32_t x = 0; x < kSize; ++x) {
      const glm::vec3 p = floor_point(v, x, kSize / 2, kSize, kSize);
      const float e = point_irradiance(kIntensity, kHeight, glm::length(p), range);
      const glm::vec3 got = img.rgb[(kSize / 2) * kSize + x];
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(got[c], kAlbedo[c] / kPi * e, 0.01f * kAlbedo[c] / kPi * kIntensity / (kHeight * kHeight))
            << "x " << x << " range " << range;
    }
  }
}

TEST(PathTracerAnalytic, SpotLightConeFollowsTheSmoothFalloffAndIsZeroOutside) {
  constexpr uint32_t kSize = 33;
  constexpr float kHeight = 1.5f, kIntensity = 10.0f, kInner = 0.2f, kOuter = 0.4f;
  World w;
  add_cell(w, floor_mesh(100.0f, kAlbedo));
  Light spot = point_light({0.0f, kHeight, 0.0f}, kIntensity);
  spot.type = Light::Type::Spot;
  spot.direction_world = {0.0f, -1.0f, 0.0f};
  spot.inner_cone_rad = kInner;
  spot.outer_cone_rad = kOuter;
  w.lights = {spot};
  const View v = looking_down(4.0f, 40.0f, 1.0f);  // sees 1.46 m each way; the cone ends at 0.63 m
  const LinearImage img = render(w, v, kSize, kSize, 256, 0);
  const float scale = 1.0f / (std::cos(kInner) - std::cos(kOuter)), offset = -std::cos(kOuter) * scale;
  const float pixel_m = 2.0f * 4.0f * std::tan(glm::radians(20.0f)) / kSize;
  for (uint32_t x = 0; x < kSize; ++x) {
    const glm::vec3 p = floor_point(v, x, kSize / 2, kSize, kSize);
    const float r = glm::length(p);
    const float cd = kHeight / std::sqrt(kHeight * kHeight + r * r);  // cos of the angle off the axis
    const float cone = std::pow(std::clamp(cd * scale + offset, 0.0f, 1.0f), 2.0f);
    const float e = point_irradiance(kIntensity, kHeight, r, 0.0f) * cone;
    const glm::vec3 got = img.rgb[(kSize / 2) * kSize + x];
    if (r > kHeight * std::tan(kOuter) + pixel_m) {
      EXPECT_EQ(got, glm::vec3(0.0f)) << "outside the outer cone, x " << x;  // exactly: no light at all
      continue;
    }
    // The cone's edges are steep (full to zero over ~0.3 m, three pixels): allow 3% of the peak.
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(got[c], kAlbedo[c] / kPi * e, 0.03f * kAlbedo[c] / kPi * kIntensity / (kHeight * kHeight))
          << "x " << x;
  }
}

}  // namespace
}  // namespace lintel
