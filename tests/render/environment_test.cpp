// The default environment: a scene without lights is seen in the uniform white sky the loader
// gives it (World::environment, kDefaultEnvironmentRadiance), not black. Two rooms with a door,
// their lamp removed: no lit pixel of the final image is black, their mean is well above it, and
// any background pixel holds the sky's radiance.
// The sealed-room zero with a lamp is render_leak_test's (a scene with lights has no sky).
#include "render_test_support.h"
#include "two_rooms.h"

#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <cstdio>

namespace lintel::render::test {
namespace {

constexpr uint32_t kWidth = 96, kHeight = 54;

class EnvironmentTest : public ValidatedGpu {};

TEST_F(EnvironmentTest, SceneWithoutLightsIsNotBlack) {
  SceneDesc desc = two_rooms(true);
  desc.lights.clear();
  for (NodeDesc& n : desc.nodes) n.light = -1;
  World world;
  const Status loaded = build_world(desc, "two rooms (no lamp)", world);
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  ASSERT_TRUE(world.lights.empty());
  EXPECT_EQ(world.environment, glm::vec3(kDefaultEnvironmentRadiance));

  RenderOptions o = test_options(kWidth, kHeight);
  o.readback_hdr = true;
  o.readback_cells = true;
  std::unique_ptr<Renderer> r = make_renderer(ctx(), world, o);
  ASSERT_TRUE(r);
  View v;
  v.eye_world = {1.0f, 1.6f, 3.5f};
  v.target_world = {6.0f, 1.0f, 1.0f};  // through the door into room B
  v.aspect = float(kWidth) / float(kHeight);
  RenderedFrame f;
  const Status s = r->render(v, uint32_t(world.find_cell("A")), f);
  ASSERT_TRUE(s.ok()) << s.message();
  size_t lit = 0, black = 0;
  double mean = 0.0;
  for (size_t p = 0; p < f.cell_ids.size(); ++p) {
    if (f.cell_ids[p] == kNoCell) {
      EXPECT_EQ(glm::vec3(f.hdr[p]), world.environment) << "background pixel " << p;
      continue;
    }
    ++lit;
    const uint8_t* c = &f.rgba8[p * 4];
    black += c[0] == 0 && c[1] == 0 && c[2] == 0;
    mean += (c[0] + c[1] + c[2]) / 3.0;
  }
  ASSERT_GT(lit, size_t(kWidth * kHeight / 2));
  mean /= double(lit);
  std::printf("  no lamp: %zu lit pixels, mean final value %.1f / 255, %zu black\n", lit, mean, black);
  EXPECT_EQ(black, 0u);
  EXPECT_GT(mean, 40.0);
}

}  // namespace
}  // namespace lintel::render::test
