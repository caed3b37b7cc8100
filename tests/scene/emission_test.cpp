// Emissive materials (glTF emissiveFactor, emissiveTexture, KHR_materials_emissive_strength):
// lamp shades, screens and signs that give off light. The loader used to drop them, so a file's
// lamps rendered unlit; now they load into Mesh::emissive / emissive_texture, the writer keeps
// them, optimize never merges shells that emit differently, and a scene whose only light sources
// are emissive surfaces gets no default sky. What the renderers do with them is tested in
// tests/render (emission_test) and tests/pathtrace.
#include "box_cells.h"
#include "fixture_support.h"
#include "written_meshes.h"

#include <lintel/optimize.h>
#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace lintel {
namespace {

using test::mesh_named;

// Property: an emissive material as another tool writes it (good/emissive_table.gltf, by
// make_fixtures.py) loads with its factor times its strength, and its emissive texture is the
// image the base colour uses (decoded once); a material without the extension keeps its factor,
// and every other mesh emits nothing. Nothing warns.
TEST(Emission, FileFromAnotherWriterLoadsItsEmission) {
  World world;
  std::vector<std::string> warnings;
  const Status s = load_world(test::fixture("good/emissive_table.gltf"), world, &warnings);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_TRUE(warnings.empty()) << test::joined(warnings);
  const Mesh& table = mesh_named(world, "Table");
  EXPECT_EQ(table.emissive, glm::vec3(4.0f, 2.0f, 1.0f));
  ASSERT_EQ(world.textures.size(), 1u);
  EXPECT_EQ(table.emissive_texture, 0);
  EXPECT_EQ(table.base_color_texture, 0);
  size_t emitting = 0;
  for (const Mesh& m : world.meshes) {
    if (&m == &table || m.emissive == glm::vec3(0.0f)) continue;
    ++emitting;
    EXPECT_EQ(m.emissive, glm::vec3(0.125f, 0.0f, 0.0f)) << m.name;
    EXPECT_EQ(m.emissive_texture, -1) << m.name;
  }
  EXPECT_GT(emitting, 0u) << "the first material's plain factor";
  EXPECT_EQ(world.environment, glm::vec3(0.0f)) << "the file has lights: no sky";
}

// Property: emission survives the writer and the loader: a factor at most 1 is written as it is,
// a brighter one as a factor times KHR_materials_emissive_strength (listed in extensionsUsed),
// and an emissive texture keeps its image and sampler; what loads back is the same.
TEST(Emission, EmissionRoundTrips) {
  World world;
  ASSERT_TRUE(load_world(test::fixture("good/emissive_table.gltf"), world).ok());
  SceneDesc written;
  ASSERT_TRUE(optimize_world(world, test::nothing_merges(), written).ok());
  const glm::vec3 dim(0.25f, 0.5f, 0.0f);
  bool found = false;
  for (MeshDesc& m : written.meshes)
    if (m.name == "Chair") {
      m.emissive = dim;
      m.emissive_sampler.wrap_s = TextureSampler::Wrap::ClampToEdge;  // ignored: no emissive texture
      found = true;
    }
  ASSERT_TRUE(found);
  std::vector<uint8_t> glb;
  ASSERT_TRUE(scene_to_glb(written, glb).ok());
  const std::string text(glb.begin(), glb.end());
  EXPECT_NE(text.find("\"KHR_materials_emissive_strength\""), std::string::npos);
  EXPECT_NE(text.find("\"emissiveTexture\""), std::string::npos);
  World back;
  const Status s = load_world_from_memory(glb.data(), glb.size(), "written.glb", "", back);
  ASSERT_TRUE(s.ok()) << s.message();
  const Mesh& table = mesh_named(back, "Table");
  EXPECT_EQ(table.emissive, glm::vec3(4.0f, 2.0f, 1.0f));
  ASSERT_GE(table.emissive_texture, 0);
  EXPECT_EQ(back.textures[size_t(table.emissive_texture)].rgba8,
            world.textures[size_t(mesh_named(world, "Table").emissive_texture)].rgba8);
  EXPECT_EQ(mesh_named(back, "Chair").emissive, dim);
  EXPECT_EQ(mesh_named(back, "Chair").emissive_texture, -1);
}

// Property: a scene whose only light sources are emissive surfaces is lit by them, not by the
// white default sky a scene without light sources gets: two box cells without lights get the sky
// when nothing emits, none when a shell emits, and the sky they get is not written back as a
// named environment either way.
TEST(Emission, EmissiveSurfacesCountAsLightSourcesForTheDefaultSky) {
  for (const bool emits : {false, true}) {
    SCOPED_TRACE(emits ? "a shell emits" : "nothing emits");
    SceneDesc scene;
    MeshDesc a = test::box_mesh("a", {0, 0, 0}, {2, 3, 2});
    if (emits) a.emissive = {1.0f, 0.9f, 0.8f};
    test::add_box_cell(scene, "a", {0, 0, 0}, {2, 3, 2}, a);
    test::add_box_cell(scene, "b", {2, 0, 0}, {4, 3, 2}, test::box_mesh("b", {2, 0, 0}, {4, 3, 2}));
    test::add_portal(scene, "ab", "a", "b", 2, 0, 2, 0.0f, 3);
    World world;
    ASSERT_TRUE(build_world(scene, "two boxes", world).ok());
    EXPECT_TRUE(world.lights.empty());
    EXPECT_EQ(world.has_light_sources(), emits);
    EXPECT_EQ(world.environment, emits ? glm::vec3(0.0f) : glm::vec3(kDefaultEnvironmentRadiance));
    SceneDesc again;
    ASSERT_TRUE(optimize_world(world, test::nothing_merges(), again).ok());
    EXPECT_FALSE(again.environment.has_value()) << "the implied sky is not written";
  }
}

// Property: optimize merges two open-walled cells only when their shells emit alike: three cells
// in a row, the middle shell emissive, stay three; all emitting the same, they merge into one
// whose shell emits that.
TEST(Emission, OptimizeMergesOnlyShellsThatEmitAlike) {
  const glm::vec3 glow(0.5f, 0.25f, 2.0f);
  for (const bool alike : {false, true}) {
    SCOPED_TRACE(alike ? "all emit" : "middle emits");
    const SceneDesc scene = test::row_of_three_cells([&](int k, MeshDesc& shell) {
      if (alike || k == 1) shell.emissive = glow;
    });
    World before;
    ASSERT_TRUE(build_world(scene, "row", before).ok());
    SceneDesc merged;
    OptimizeReport report;
    ASSERT_TRUE(optimize_world(before, {}, merged, &report).ok());
    EXPECT_EQ(report.cells_after, alike ? 1u : 3u);
    World after;
    ASSERT_TRUE(build_world(merged, "merged", after).ok());
    size_t emitting = 0;
    for (const Cell& c : after.cells) {
      const glm::vec3 e = after.meshes[size_t(c.shell_mesh)].emissive;
      if (e == glm::vec3(0.0f)) continue;
      ++emitting;
      EXPECT_EQ(e, glow);
    }
    EXPECT_EQ(emitting, 1u);
  }
}

}  // namespace
}  // namespace lintel
