// The writer keeps what the loader reads of textures' glTF samplers (Mesh::base_color_sampler)
// and of the sky (World::environment), on a hand-built stair and hall whose shells and
// furniture sample two images with several samplers:
//  * SceneDesc -> file -> World: every textured mesh loads back with its sampler, field for field,
//    and the environment with the same floats; an untextured mesh's sampler is not written.
//  * The file holds each distinct non-default sampler once, no default sampler, and one glTF
//    texture per (image, sampler) pair; a scene with default samplers and no sky names neither.
//  * World -> optimize_world -> World, and `lintel optimize` from file to file: the same (the
//    merged stair shell samples as its first step did); a sky that is the loader's default for
//    the scene stays implicit, any other is written.
#include "box_cells.h"
#include "run_process.h"

#include <lintel/optimize.h>
#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace lintel {
namespace {

using Wrap = TextureSampler::Wrap;
using Filter = TextureSampler::Filter;
using MipMode = TextureSampler::MipMode;

TextureSampler sampler(Wrap s, Wrap t, Filter mag, Filter min, MipMode mip) { return {s, t, mag, min, mip}; }

// Every field, so that a mismatch names it.
void expect_same(const TextureSampler& got, const TextureSampler& want, const std::string& what) {
  EXPECT_EQ(got.wrap_s, want.wrap_s) << what;
  EXPECT_EQ(got.wrap_t, want.wrap_t) << what;
  EXPECT_EQ(got.mag, want.mag) << what;
  EXPECT_EQ(got.min, want.min) << what;
  EXPECT_EQ(got.mip, want.mip) << what;
}

Texture image(uint32_t size, uint8_t shade) {
  Texture t;
  t.name = "shade " + std::to_string(shade);
  t.width = t.height = size;
  t.rgba8.assign(size_t(size) * size * 4, 255);
  for (size_t i = 0; i < t.rgba8.size(); i += 4) t.rgba8[i] = uint8_t(shade + i / 4);
  return t;
}

// A box mesh with uvs (x + z, y) per corner, sampling `texture` (or none) through `s`.
MeshDesc box_mesh(const std::string& name, glm::vec3 lo, glm::vec3 hi, int texture = -1, const TextureSampler& s = {}) {
  MeshDesc mesh = test::box_mesh(name, lo, hi);
  for (const glm::vec3& p : mesh.positions) mesh.uvs.emplace_back(p.x + p.z, p.y);
  mesh.texture = texture;
  mesh.sampler = s;
  return mesh;
}

int add_cell(SceneDesc& scene, const std::string& name, glm::vec3 lo, glm::vec3 hi, int texture,
             const TextureSampler& s) {
  return test::add_box_cell(scene, name, lo, hi, box_mesh(name, lo, hi, texture, s));
}

using test::add_portal;

void add_instance(SceneDesc& scene, int cell, MeshDesc mesh) {
  NodeDesc node;
  node.name = mesh.name;
  node.parent = cell;
  node.mesh = int(scene.meshes.size());
  scene.meshes.push_back(std::move(mesh));
  scene.nodes.push_back(node);
}

const TextureSampler kClampNearest =
    sampler(Wrap::ClampToEdge, Wrap::ClampToEdge, Filter::Nearest, Filter::Nearest, MipMode::None);
const TextureSampler kMirrorS =
    sampler(Wrap::MirroredRepeat, Wrap::Repeat, Filter::Linear, Filter::Linear, MipMode::Linear);
const TextureSampler kMixed =
    sampler(Wrap::Repeat, Wrap::MirroredRepeat, Filter::Nearest, Filter::Linear, MipMode::Nearest);
const TextureSampler kNearestMipLinear =
    sampler(Wrap::Repeat, Wrap::Repeat, Filter::Linear, Filter::Nearest, MipMode::Linear);

// Three 0.2 m stair steps and a hall through a door, lit by a lamp. The first two steps sample
// image 0 alike and merge under optimize; the third samples it with another sampler, which keeps
// it apart. Image 0 is sampled with two samplers and the default, image 1 with two others; the
// untextured table's non-default sampler means nothing.
SceneDesc textured_scene(bool samplers, std::optional<glm::vec3> sky) {
  const TextureSampler def{};
  SceneDesc scene;
  scene.textures = {image(4, 10), image(8, 100)};
  add_cell(scene, "s0", {0, 0.0f, 0}, {1, 3, 2}, 0, samplers ? kClampNearest : def);
  add_cell(scene, "s1", {1, 0.2f, 0}, {2, 3, 2}, 0, samplers ? kClampNearest : def);
  add_cell(scene, "s2", {2, 0.4f, 0}, {3, 3, 2}, 0, samplers ? kMirrorS : def);
  const int hall = add_cell(scene, "hall", {3, 0.4f, -1}, {7, 3, 3}, 0, def);
  add_portal(scene, "p01", "s0", "s1", 1, 0, 2, 0.2f, 3);
  add_portal(scene, "p12", "s1", "s2", 2, 0, 2, 0.4f, 3);
  add_portal(scene, "door", "s2", "hall", 3, 0.5f, 1.5f, 0.4f, 2.4f);
  add_instance(scene, hall, box_mesh("chest", {4, 0.4f, 0}, {4.5f, 1, 0.5f}, 0, samplers ? kClampNearest : def));
  add_instance(scene, hall, box_mesh("shelf", {5, 0.4f, 0}, {5.5f, 2, 0.3f}, 1, samplers ? kNearestMipLinear : def));
  add_instance(scene, hall, box_mesh("crate", {6, 0.4f, 0}, {6.5f, 1, 0.5f}, 1, samplers ? kMixed : def));
  add_instance(scene, hall, box_mesh("table", {4, 0.4f, 2}, {5, 1, 2.5f}, -1, samplers ? kMixed : def));
  scene.lights.push_back({"lamp", Light::Type::Point, glm::vec3(1.0f), 20.0f});
  NodeDesc lamp;
  lamp.name = "lamp";
  lamp.parent = hall;
  lamp.translation = {5, 2.5f, 1};
  lamp.light = 0;
  scene.nodes.push_back(lamp);
  scene.environment = sky;
  return scene;
}

const Mesh* mesh_named(const World& w, const std::string& name) {
  for (const Mesh& m : w.meshes)
    if (m.name == name) return &m;
  return nullptr;
}

// The sampler each drawn mesh of textured_scene(true, ...) must load with.
const std::map<std::string, TextureSampler>& want_samplers() {
  static const std::map<std::string, TextureSampler> want = {
      {"s0", kClampNearest},    {"s1", kClampNearest},        {"s2", kMirrorS},  {"hall", TextureSampler{}},
      {"chest", kClampNearest}, {"shelf", kNearestMipLinear}, {"crate", kMixed}, {"table", TextureSampler{}}};
  return want;
}

nlohmann::json written_json(const SceneDesc& scene, const std::string& dir) {
  const std::string path = dir + "/scene.gltf";
  const Status s = save_scene(scene, path);
  EXPECT_TRUE(s.ok()) << s.message();
  std::ifstream in(path, std::ios::binary);
  return nlohmann::json::parse(std::string{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()});
}

TEST(SceneWriteSampler, SamplersAndSkyComeBackExactly) {
  const glm::vec3 sky(0.3f, 0.7f, 1.9f);
  World w;
  const Status s = build_world(textured_scene(true, sky), "textured", w);
  ASSERT_TRUE(s.ok()) << s.message();
  for (const auto& [name, want] : want_samplers()) {
    const Mesh* m = mesh_named(w, name);
    ASSERT_NE(m, nullptr) << name;
    expect_same(m->base_color_sampler, want, name);
  }
  EXPECT_EQ(mesh_named(w, "table")->base_color_texture, -1);
  EXPECT_EQ(w.environment, sky);  // the same floats: color x intensity 1
  ASSERT_EQ(w.textures.size(), 2u);
}

TEST(SceneWriteSampler, FileHoldsEachSamplerOnceAndNoDefault) {
  const std::string dir = test::make_temp_dir();
  const nlohmann::json j = written_json(textured_scene(true, glm::vec3(2.0f)), dir);
  // Four distinct non-default samplers are used by textured meshes (the table's is not).
  ASSERT_TRUE(j.contains("samplers"));
  ASSERT_EQ(j["samplers"].size(), 4u);
  std::set<std::string> distinct;
  for (const auto& s : j["samplers"]) distinct.insert(s.dump());
  EXPECT_EQ(distinct.size(), 4u);
  EXPECT_EQ(j["samplers"][0],
            (nlohmann::json{{"magFilter", 9728}, {"minFilter", 9728}, {"wrapS", 33071}, {"wrapT", 33071}}));
  EXPECT_EQ(j["samplers"][1], (nlohmann::json{{"wrapS", 33648}}));  // only what is not the default
  // (image, sampler) pairs: image 0 with clamp (its first user), mirror and the default; image 1
  // with nearest-mip-linear (its first user) and mixed: five textures, each pair once.
  ASSERT_EQ(j["textures"].size(), 5u);
  std::set<std::pair<int, int>> pairs;
  size_t without_sampler = 0;
  for (const auto& t : j["textures"]) {
    pairs.emplace(t["source"].get<int>(), t.value("sampler", -1));
    without_sampler += !t.contains("sampler");
  }
  EXPECT_EQ(pairs.size(), 5u);
  EXPECT_EQ(without_sampler, 1u);  // the hall's default
  EXPECT_EQ(j["scenes"][0]["extras"]["lintel"]["environment"], (nlohmann::json{{"color", {2.0, 2.0, 2.0}}}));

  // Defaults everywhere and no sky: neither is named, one texture per image as before.
  const nlohmann::json plain = written_json(textured_scene(false, std::nullopt), dir);
  EXPECT_FALSE(plain.contains("samplers"));
  EXPECT_EQ(plain["textures"], (nlohmann::json{{{"source", 0}}, {{"source", 1}}}));
  EXPECT_FALSE(plain["scenes"][0]["extras"]["lintel"].contains("environment"));
}

TEST(SceneWriteSampler, OptimizeKeepsSamplersAndSky) {
  for (const glm::vec3 sky : {glm::vec3(0.25f, 0.5f, 4.0f), glm::vec3(0.0f), glm::vec3(1.0f)}) {
    World source;
    ASSERT_TRUE(build_world(textured_scene(true, sky), "source", source).ok());
    SceneDesc merged;
    OptimizeReport report;
    const Status s = optimize_world(source, {}, merged, &report);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(report.merged_cell_of, (std::vector<uint32_t>{0, 0, 1, 2})) << "s2's other sampler keeps it apart";
    // The scene has a lamp: no sky is what the loader gives it anyway, so 0 is not written.
    EXPECT_EQ(merged.environment.has_value(), sky != glm::vec3(0.0f));
    World w;
    const Status loaded = build_world(merged, "merged", w);
    ASSERT_TRUE(loaded.ok()) << loaded.message();
    EXPECT_EQ(w.environment, sky);
    for (const auto& [name, want] : want_samplers()) {
      if (name == "s1") continue;  // merged into s0
      const Mesh* m = mesh_named(w, name == "s0" ? "s0 merged shell" : name);
      ASSERT_NE(m, nullptr) << name;
      expect_same(m->base_color_sampler, want, name);
    }
  }
}

// Control for the merge above: with one sampler on every step, all three merge.
TEST(SceneWriteSampler, StepsThatSampleAlikeMerge) {
  SceneDesc merged;
  OptimizeReport report;
  const Status s = optimize_scene(textured_scene(false, std::nullopt), "plain", {}, merged, &report);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(report.merged_cell_of, (std::vector<uint32_t>{0, 0, 0, 1}));
  EXPECT_FALSE(merged.environment.has_value());
}

TEST(SceneWriteSampler, OptimizeCommandKeepsSamplersAndSky) {
  const std::string dir = test::make_temp_dir();
  const glm::vec3 sky(0.125f, 3.0f, 0.5f);
  ASSERT_TRUE(save_scene(textured_scene(true, sky), dir + "/in.glb").ok());
  const test::ProcessResult r =
      test::run_process(test::lintel_bin() + " optimize " + dir + "/in.glb -o " + dir + "/out.gltf");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  World w;
  const Status s = load_world(dir + "/out.gltf", w);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(w.cells.size(), 3u);
  EXPECT_EQ(w.environment, sky);
  for (const auto& [name, want] : want_samplers()) {
    if (name == "s1") continue;
    const Mesh* m = mesh_named(w, name == "s0" ? "s0 merged shell" : name);
    ASSERT_NE(m, nullptr) << name;
    expect_same(m->base_color_sampler, want, name);
  }
}

TEST(SceneWriteSampler, BadSkyOrSamplerIsRefused) {
  SceneDesc scene = textured_scene(true, glm::vec3(-1.0f, 0.0f, 0.0f));
  std::vector<uint8_t> glb;
  Status s = scene_to_glb(scene, glb);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("environment"), std::string::npos) << s.message();
  scene.environment.reset();
  scene.meshes[0].sampler.wrap_s = Wrap(7);
  s = scene_to_glb(scene, glb);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("sampler"), std::string::npos) << s.message();
}

}  // namespace
}  // namespace lintel
