// The loader's glTF samplers (Mesh::base_color_sampler) and scene environment
// (extras.lintel.environment -> World::environment), on the textured fixture's JSON edited in
// memory: every wrap and filter code maps to its mode, a texture without a sampler keeps the
// defaults, a bad code or environment is an error naming the element, and the environment is
// colour x intensity (the fixture has lights, so without the key there is no sky).
#include "fixture_support.h"

#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <iterator>

namespace lintel {
namespace {

nlohmann::json fixture_json() {
  std::ifstream in(test::fixture("good/textured_table_data_uri_image.gltf"), std::ios::binary);
  return nlohmann::json::parse(std::string{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()});
}

Status load(const nlohmann::json& j, World& out) {
  const std::string text = j.dump();
  return load_world_from_memory(reinterpret_cast<const uint8_t*>(text.data()), text.size(), "memory.gltf", "", out);
}

const Mesh& table(const World& w) {
  for (const Mesh& m : w.meshes)
    if (m.name == "Table") return m;
  ADD_FAILURE() << "no Table mesh";
  return w.meshes.front();
}

TEST(SceneSampler, CodesMapToModes) {
  using S = TextureSampler;
  struct Case {
    int wrap_s, wrap_t, mag, min;
    S::Wrap ws, wt;
    S::Filter fmag, fmin;
    S::MipMode mip;
  };
  const Case cases[] = {
      {10497, 33071, 9728, 9984, S::Wrap::Repeat, S::Wrap::ClampToEdge, S::Filter::Nearest, S::Filter::Nearest,
       S::MipMode::Nearest},
      {33648, 10497, 9729, 9987, S::Wrap::MirroredRepeat, S::Wrap::Repeat, S::Filter::Linear, S::Filter::Linear,
       S::MipMode::Linear},
      {33071, 33648, 9729, 9729, S::Wrap::ClampToEdge, S::Wrap::MirroredRepeat, S::Filter::Linear, S::Filter::Linear,
       S::MipMode::None},
      {10497, 10497, 9728, 9986, S::Wrap::Repeat, S::Wrap::Repeat, S::Filter::Nearest, S::Filter::Nearest,
       S::MipMode::Linear},
      {10497, 10497, 9728, 9985, S::Wrap::Repeat, S::Wrap::Repeat, S::Filter::Nearest, S::Filter::Linear,
       S::MipMode::Nearest},
      {10497, 10497, 9728, 9728, S::Wrap::Repeat, S::Wrap::Repeat, S::Filter::Nearest, S::Filter::Nearest,
       S::MipMode::None},
  };
  for (const Case& c : cases) {
    nlohmann::json j = fixture_json();
    j["samplers"] = {{{"wrapS", c.wrap_s}, {"wrapT", c.wrap_t}, {"magFilter", c.mag}, {"minFilter", c.min}}};
    j["textures"][0]["sampler"] = 0;
    World w;
    const Status s = load(j, w);
    ASSERT_TRUE(s.ok()) << s.message();
    const S& got = table(w).base_color_sampler;
    EXPECT_EQ(got.wrap_s, c.ws) << c.wrap_s;
    EXPECT_EQ(got.wrap_t, c.wt) << c.wrap_t;
    EXPECT_EQ(got.mag, c.fmag) << c.mag;
    EXPECT_EQ(got.min, c.fmin) << c.min;
    EXPECT_EQ(got.mip, c.mip) << c.min;
  }
  // No sampler (the fixture as written), and a sampler with no keys: the defaults.
  for (const bool empty_sampler : {false, true}) {
    nlohmann::json j = fixture_json();
    if (empty_sampler) {
      j["samplers"] = nlohmann::json::array({nlohmann::json::object()});
      j["textures"][0]["sampler"] = 0;
    }
    World w;
    ASSERT_TRUE(load(j, w).ok());
    const S& got = table(w).base_color_sampler;
    EXPECT_EQ(got.wrap_s, S::Wrap::Repeat);
    EXPECT_EQ(got.mag, S::Filter::Linear);
    EXPECT_EQ(got.mip, S::MipMode::Linear);
  }
}

TEST(SceneSampler, BadCodeIsAnErrorNamingTheSampler) {
  nlohmann::json j = fixture_json();
  j["samplers"] = {{{"wrapS", 7}}};
  j["textures"][0]["sampler"] = 0;
  World w;
  const Status s = load(j, w);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("samplers[0]"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("wrapS 7"), std::string::npos) << s.message();
}

TEST(SceneEnvironment, ColourTimesIntensityAndErrors) {
  World w;
  ASSERT_TRUE(load(fixture_json(), w).ok());
  ASSERT_FALSE(w.lights.empty());
  EXPECT_EQ(w.environment, glm::vec3(0.0f));  // lights and no key: no sky

  nlohmann::json j = fixture_json();
  j["scenes"][0]["extras"]["lintel"]["environment"] = {{"color", {0.5, 0.25, 1.0}}, {"intensity", 2.0}};
  const Status s = load(j, w);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(w.environment, glm::vec3(1.0f, 0.5f, 2.0f));

  j["scenes"][0]["extras"]["lintel"]["environment"] = {{"intensity", -1.0}};
  const Status bad = load(j, w);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message().find("extras.lintel.environment.intensity"), std::string::npos) << bad.message();
}

}  // namespace
}  // namespace lintel
