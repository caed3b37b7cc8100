// The sky in the path tracer (World::environment): a ray that leaves the scene sees its radiance.
// A double-sided floor seen from above with no lights, one bounce: every bounce ray escapes
// upward, so each sample is exactly albedo x L (cosine sampling cancels the 1/pi), and so is
// every pixel; with no bounce (direct light only) the floor is black. Also the loader's rule:
// a scene without lights gets kDefaultEnvironmentRadiance, one with lights none.
#include <lintel/reference/path_tracer.h>
#include <lintel/scene_io.h>

#include "test_worlds.h"

#include <gtest/gtest.h>

namespace lintel {
namespace {

TEST(PathTracerEnvironment, FloorUnderASkyIsAlbedoTimesSky) {
  const glm::vec3 albedo(0.5f, 0.25f, 0.75f), sky(2.0f, 1.0f, 0.5f);
  World w;
  pathtrace_test::add_cell(w, pathtrace_test::floor_mesh(1.0f, albedo));
  w.environment = sky;
  PathTracer tracer;
  ASSERT_TRUE(tracer.build(w).ok());
  View v;
  v.eye_world = {0.0f, 3.0f, 0.0f};
  v.target_world = {0.0f, 0.0f, 0.0f};
  v.up_world = {0.0f, 0.0f, -1.0f};
  v.fov_y_deg = 20.0f;  // the floor fills the image
  v.aspect = 1.0f;
  PathTraceOptions o;
  o.width = o.height = 16;
  o.samples_per_pixel = 4;
  o.max_bounces = 1;
  LinearImage img;
  tracer.render(v, o, img);
  for (const glm::vec3& c : img.rgb) {
    ASSERT_NEAR(c.r, albedo.r * sky.r, 1e-5f);
    ASSERT_NEAR(c.g, albedo.g * sky.g, 1e-5f);
    ASSERT_NEAR(c.b, albedo.b * sky.b, 1e-5f);
  }
  o.max_bounces = 0;
  tracer.render(v, o, img);
  for (const glm::vec3& c : img.rgb) ASSERT_EQ(c, glm::vec3(0.0f));
}

TEST(PathTracerEnvironment, LoaderGivesTheDefaultSkyOnlyWithoutLights) {
  SceneDesc s;
  MeshDesc floor;
  floor.name = "floor";
  floor.positions = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
  floor.indices = {0, 2, 1, 0, 3, 2};
  s.meshes.push_back(floor);
  NodeDesc cell;
  cell.name = "room";
  cell.kind = NodeDesc::Kind::Cell;
  cell.cell_name = "room";
  cell.mesh = 0;
  s.nodes.push_back(cell);
  World w;
  ASSERT_TRUE(build_world(s, "floor", w).ok());
  EXPECT_EQ(w.environment, glm::vec3(kDefaultEnvironmentRadiance));
  s.lights.push_back(LightDesc{});
  NodeDesc lamp;
  lamp.name = "lamp";
  lamp.parent = 0;
  lamp.translation = {0, 1, 0};
  lamp.light = 0;
  s.nodes.push_back(lamp);
  ASSERT_TRUE(build_world(s, "floor with a lamp", w).ok());
  EXPECT_EQ(w.environment, glm::vec3(0.0f));
}

}  // namespace
}  // namespace lintel
