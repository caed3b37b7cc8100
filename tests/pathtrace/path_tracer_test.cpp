// The path tracer as a reference must not leak light between sealed rooms, must give the same
// image on any number of threads, and its bounces must add the indirect light a closed form
// predicts (the interior of a sphere, where every bounce spreads light evenly).
#include <lintel/reference/path_tracer.h>
#include <lintel/scene_io.h>
#include <lintel/timeline.h>

#include "test_worlds.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <numeric>

namespace lintel {
namespace {

using pathtrace_test::add_cell;
using pathtrace_test::box_mesh;
using pathtrace_test::point_light;
using pathtrace_test::sphere_mesh;

constexpr float kPi = 3.14159265358979f;

PathTraceOptions options(uint32_t width, uint32_t height, uint32_t spp, uint32_t bounces) {
  PathTraceOptions o;
  o.width = width;
  o.height = height;
  o.samples_per_pixel = spp;
  o.max_bounces = bounces;
  return o;
}

View look(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up = {0, 1, 0}) {
  View v;
  v.eye_world = eye;
  v.target_world = target;
  v.up_world = up;
  return v;
}

glm::vec3 mean(const LinearImage& img) {
  return std::accumulate(img.rgb.begin(), img.rgb.end(), glm::vec3(0.0f)) / float(img.rgb.size());
}

// Room A [-4, 0] x [0, 3] x [-2, 2] holds the lights; room B, in its own cell frame, is the box
// [0, 4] x [0, 3] x [-2, 2] in world space: the two share the wall plane x = 0 (coplanar
// triangles). One light sits 1 cm from that wall, where a careless ray offset would leak.
World sealed_rooms() {
  World w;
  const glm::vec3 grey(0.8f);
  add_cell(w, box_mesh({-4, 0, -2}, {0, 3, 2}, grey));
  add_cell(w, box_mesh({-2, 0, -2}, {2, 3, 2}, grey), glm::translate(glm::mat4(1.0f), glm::vec3(2, 0, 0)));
  // A table in room B, so instances are part of the sealed geometry too.
  w.meshes.push_back(box_mesh({-0.5f, 0.0f, -0.5f}, {0.5f, 0.8f, 0.5f}, glm::vec3(0.6f, 0.3f, 0.2f)));
  Instance table;
  table.cell = 1;
  table.mesh = uint32_t(w.meshes.size() - 1);
  table.mesh_to_world = glm::translate(glm::mat4(1.0f), glm::vec3(2.5f, 0.0f, 0.5f));
  w.instances = {table};
  Light sun;  // above both roofs: sealed rooms get none of it
  sun.type = Light::Type::Directional;
  sun.intensity = 100.0f;
  sun.direction_world = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  w.lights = {point_light({-2.0f, 1.5f, 0.0f}, 50.0f), point_light({-0.01f, 1.5f, 0.3f}, 50.0f), sun};
  return w;
}

TEST(PathTracer, SealedRoomNextToALitOneIsExactlyBlack) {
  const World w = sealed_rooms();
  PathTracer pt;
  ASSERT_TRUE(pt.build(w).ok());
  LinearImage img;
  // From inside the dark room, towards the shared wall, the table and the corners.
  for (const bool connections : {true, false}) {
    for (const glm::vec3& target :
         {glm::vec3(-1.0f, 1.2f, 0.3f), glm::vec3(2.5f, 0.2f, 0.5f), glm::vec3(0.0f, 3.0f, 2.0f)}) {
      PathTraceOptions o = options(32, 18, 16, 4);
      o.light_connections = connections;
      pt.render(look({3.0f, 1.5f, -1.0f}, target), o, img);
      for (size_t i = 0; i < img.rgb.size(); ++i) ASSERT_EQ(img.rgb[i], glm::vec3(0.0f)) << "pixel " << i;
    }
  }
  // The lit room really is lit, on the same wall seen from its other side.
  pt.render(look({-3.0f, 1.5f, 0.0f}, {0.0f, 1.5f, 0.0f}), options(32, 18, 16, 4), img);
  EXPECT_GT(mean(img).x, 0.1f);
}

TEST(PathTracer, SameImageForAnyThreadCountAndProgressCountsRows) {
  World w;
  ASSERT_TRUE(load_world(LINTEL_SOURCE_DIR "/scenes/cottage.gltf", w).ok());
  ASSERT_FALSE(w.timelines.empty());
  const Timeline& walk = w.timelines[0];
  const View v = timeline_view(walk, 0.5 * (walk.keys.front().t + walk.keys.back().t));
  PathTracer pt;
  ASSERT_TRUE(pt.build(w).ok());
  PathTraceOptions o = options(32, 18, 4, 4);
  LinearImage reference;
  o.threads = 1;
  uint32_t calls = 0, last = 0;
  o.progress = [&](uint32_t done, uint32_t total) {
    EXPECT_EQ(total, 18u);
    EXPECT_EQ(done, last + 1);
    last = done;
    ++calls;
  };
  pt.render(v, o, reference);
  EXPECT_EQ(calls, 18u);
  EXPECT_GT(mean(reference).x + mean(reference).y + mean(reference).z, 0.0f);
  o.progress = nullptr;
  for (const unsigned threads : {2u, 3u, 7u}) {
    o.threads = threads;
    LinearImage img;
    pt.render(v, o, img);
    EXPECT_TRUE(img.rgb == reference.rgb) << threads << " threads";
  }
  o.seed = 2;  // and the seed really drives the samples
  LinearImage other;
  pt.render(v, o, other);
  EXPECT_FALSE(other.rgb == reference.rgb);
}

TEST(PathTracer, BouncesLightACeilingTheSpotCannotReach) {
  World w;
  add_cell(w, box_mesh({-2, 0, -2}, {2, 3, 2}, glm::vec3(0.7f)));
  Light spot = point_light({0.0f, 2.8f, 0.0f}, 40.0f);
  spot.type = Light::Type::Spot;
  spot.direction_world = {0.0f, -1.0f, 0.0f};
  spot.outer_cone_rad = 0.5f;
  w.lights = {spot};
  PathTracer pt;
  ASSERT_TRUE(pt.build(w).ok());
  // From the floor up: the view holds only ceiling, which the downward cone never lights.
  View up_view = look({0.0f, 0.5f, 0.0f}, {0.0f, 3.0f, 0.0f}, {0.0f, 0.0f, -1.0f});
  up_view.aspect = 1.0f;
  LinearImage direct;
  pt.render(up_view, options(16, 16, 64, 0), direct);
  for (const glm::vec3& px : direct.rgb) ASSERT_EQ(px, glm::vec3(0.0f));
  for (const bool connections : {true, false}) {
    PathTraceOptions o = options(16, 16, 64, 2);
    o.light_connections = connections;
    LinearImage indirect;
    pt.render(up_view, o, indirect);
    // With connections every path links the ceiling to the spot's lit floor. Without, about a
    // quarter of the paths reach that floor within two bounces, so a pixel whose 64 paths all
    // miss it has odds of about 4e-8.
    for (const glm::vec3& px : indirect.rgb) EXPECT_GT(px.x, 0.0f) << "connections " << connections;
  }
}

// Inside a sphere of radius R with a point light at its centre the direct irradiance is I / R^2
// everywhere, and a diffuse sphere's form factor to any patch is that patch's share of the area,
// so each bounce adds the same irradiance times a: L = a / pi * I / R^2 * (1 + a + ... + a^B).
// Both estimators (with and without light connections) must give it.
TEST(PathTracer, BouncesInsideASphereAddTheGeometricSeries) {
  constexpr float kRadius = 2.0f, kIntensity = 8.0f, kAlbedo = 0.5f;
  World w;
  add_cell(w, sphere_mesh(kRadius, 96, 48, glm::vec3(kAlbedo)));
  w.lights = {point_light({0.0f, 0.0f, 0.0f}, kIntensity)};
  PathTracer pt;
  ASSERT_TRUE(pt.build(w).ok());
  const View v = look({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f});
  for (const bool connections : {true, false}) {
    float previous = 0.0f;
    for (const uint32_t bounces : {0u, 1u, 2u, 4u}) {
      PathTraceOptions o = options(32, 18, 16, bounces);
      o.light_connections = connections;
      LinearImage img;
      pt.render(v, o, img);
      float series = 0.0f;
      for (uint32_t k = 0; k <= bounces; ++k) series += std::pow(kAlbedo, float(k));
      const float want = kAlbedo / kPi * kIntensity / (kRadius * kRadius) * series;
      // 1%: the tessellation's flat facets, slightly inside the sphere, put the image 0.1% above
      // the formula; the rest is room for the noise of 9k paths per image.
      EXPECT_NEAR(mean(img).x, want, 0.01f * want) << bounces << " bounces, connections " << connections;
      EXPECT_GT(mean(img).x, previous) << "more bounces must add light";
      previous = mean(img).x;
    }
  }
}

// A spot at the centre of a sphere, pointing down, lights only a cap directly. Its flux is
// Phi = 2 pi I ((1 - cos inner) + (cos inner - cos outer) / 3) (the squared ramp integrated over
// the cone), and after one bounce it is spread evenly: H = a Phi / (4 pi R^2). Looking up, where
// no direct light falls, L = a / pi * H * (1 + a + ... + a^(B-1)). This checks the spot's
// emission sampling and the weights of both strategies against a closed form. (Without
// connections the same view is 4x noisier; the point-light sphere above covers that estimator.)
TEST(PathTracer, SpotInsideASphereBouncesItsFluxEvenly) {
  constexpr float kRadius = 2.0f, kIntensity = 8.0f, kAlbedo = 0.5f, kInner = 0.3f, kOuter = 0.7f;
  World w;
  add_cell(w, sphere_mesh(kRadius, 96, 48, glm::vec3(kAlbedo)));
  Light spot = point_light({0.0f, 0.0f, 0.0f}, kIntensity);
  spot.type = Light::Type::Spot;
  spot.direction_world = {0.0f, -1.0f, 0.0f};
  spot.inner_cone_rad = kInner;
  spot.outer_cone_rad = kOuter;
  w.lights = {spot};
  PathTracer pt;
  ASSERT_TRUE(pt.build(w).ok());
  const float flux =
      2.0f * kPi * kIntensity * ((1.0f - std::cos(kInner)) + (std::cos(kInner) - std::cos(kOuter)) / 3.0f);
  const float h = kAlbedo * flux / (4.0f * kPi * kRadius * kRadius);
  View up_view = look({0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, -1.0f});
  up_view.fov_y_deg = 60.0f;  // the view stays in the upper hemisphere, far from the lit cap
  for (const uint32_t bounces : {1u, 3u}) {
    LinearImage img;
    pt.render(up_view, options(16, 9, 512, bounces), img);
    float series = 0.0f;
    for (uint32_t k = 0; k < bounces; ++k) series += std::pow(kAlbedo, float(k));
    const float want = kAlbedo / kPi * h * series;
    // 3%: about four standard deviations of this image's mean (measured over seeds).
    EXPECT_NEAR(mean(img).x, want, 0.03f * want) << bounces << " bounces";
  }
}

// A lamp 5 cm under the ceiling lights a bright patch that cosine bounces rarely hit: connecting
// to light vertices must cut the noise (measured as the difference of two seeds) by a large
// factor at the same sample count. (Means are not compared here: without connections the mean
// of a few samples is heavy-tailed; the sphere tests check both estimators' expectations.)
TEST(PathTracer, LightConnectionsCutTheNoiseOfALampUnderTheCeiling) {
  World w;
  add_cell(w, box_mesh({-2, 0, -2}, {2, 3, 2}, glm::vec3(0.7f)));
  w.lights = {point_light({0.0f, 2.95f, 0.0f}, 20.0f)};
  PathTracer pt;
  ASSERT_TRUE(pt.build(w).ok());
  const View v = look({0.0f, 1.0f, 1.8f}, {0.0f, 0.5f, -2.0f});
  const auto noise_of = [&](bool connections) {
    PathTraceOptions o = options(24, 14, 16, 2);
    o.light_connections = connections;
    LinearImage a, b;
    pt.render(v, o, a);
    o.seed = 99;
    pt.render(v, o, b);
    double sq = 0.0;
    for (size_t i = 0; i < a.rgb.size(); ++i) sq += double(glm::dot(a.rgb[i] - b.rgb[i], a.rgb[i] - b.rgb[i])) / 3.0;
    return std::sqrt(sq / double(a.rgb.size()) / 2.0);  // one image's noise
  };
  const double noise_on = noise_of(true), noise_off = noise_of(false);
  std::printf("lamp under the ceiling, 16 spp: noise %.4f with connections, %.4f without\n", noise_on, noise_off);
  EXPECT_LT(noise_on, 0.5 * noise_off);
}

}  // namespace
}  // namespace lintel
