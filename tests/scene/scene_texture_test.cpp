// Base colour textures in the scene layer: the textured fixture (tests/scene/fixtures/good/
// textured_table*, written by make_fixtures.py) loads with the same texture whether its image
// sits in a bufferView, a data: URI or a file beside the .gltf; a textured quad written by
// save_scene / scene_to_glb loads back with its pixels, uvs and texture index; images are
// decoded once however many meshes use them. Bad textures are in scene_bad_input_test.cpp.
#include "fixture_support.h"

#include <lintel/scene_desc.h>
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

namespace lintel {
namespace {

// make_fixtures.py's CHECKER (rows top to bottom) and TABLE_UVS.
const std::vector<uint8_t> kChecker = {255, 255, 255, 255, 0,   0,   0,   255,  //
                                       0,   0,   0,   255, 255, 255, 255, 255};
const std::vector<glm::vec2> kTableUvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};

void add_instance(SceneDesc& scene, int cell_node, int mesh, float height) {
  NodeDesc n;
  n.name = "Instance" + std::to_string(scene.nodes.size());
  n.parent = cell_node;
  n.mesh = mesh;
  n.translation = {0, height, 0};
  scene.nodes.push_back(n);
}

const Mesh* find_mesh(const World& w, const std::string& name) {
  for (const Mesh& m : w.meshes)
    if (m.name == name) return &m;
  return nullptr;
}

void expect_textured_table(const World& w, const std::string& texture_name) {
  ASSERT_EQ(w.textures.size(), 1u);
  EXPECT_EQ(w.textures[0].name, texture_name);
  EXPECT_EQ(w.textures[0].width, 2u);
  EXPECT_EQ(w.textures[0].height, 2u);
  EXPECT_EQ(w.textures[0].rgba8, kChecker);
  const Mesh* table = find_mesh(w, "Table");
  ASSERT_NE(table, nullptr);
  EXPECT_EQ(table->base_color_texture, 0);
  EXPECT_EQ(table->uvs, kTableUvs);
  EXPECT_EQ(table->base_color, glm::vec4(0.5f, 1.0f, 1.0f, 1.0f));
  for (const Mesh& m : w.meshes) {
    if (&m == table) continue;
    EXPECT_EQ(m.base_color_texture, -1) << m.name;
    EXPECT_TRUE(m.uvs.empty()) << m.name;  // the other fixture meshes have no TEXCOORD_0
  }
}

TEST(TexturedFixture, ImageInBufferViewDataUriOrFileGivesTheSameTexture) {
  World glb, data_uri, external;
  const Status a = load_world(test::fixture("good/textured_table.glb"), glb);
  ASSERT_TRUE(a.ok()) << a.message();
  expect_textured_table(glb, "checker");
  const Status b = load_world(test::fixture("good/textured_table_data_uri_image.gltf"), data_uri);
  ASSERT_TRUE(b.ok()) << b.message();
  expect_textured_table(data_uri, "images[0]");  // neither a name nor a file name
  const Status c = load_world(test::fixture("good/textured_table_external_image.gltf"), external);
  ASSERT_TRUE(c.ok()) << c.message();
  expect_textured_table(external, "checker");
}

// Quantized vertex attributes (core glTF's normalized 8/16-bit texture coordinates, and
// KHR_mesh_quantization's integer positions and normalized normals: what gltfpack writes) load as
// the float scene they were made from, within their quantization: the table's world-space corners
// within half a 1/1024 m step, its uvs within half a 1/65535 step, the chair's normals within one
// 1/127 step. Fixture good/textured_table_quantized.gltf (make_fixtures.py, quantized_scene).
TEST(TexturedFixture, QuantizedAttributesLoadAsTheFloatScene) {
  World plain, quantized;
  ASSERT_TRUE(load_world(test::fixture("good/textured_table.glb"), plain).ok());
  const Status s = load_world(test::fixture("good/textured_table_quantized.gltf"), quantized);
  ASSERT_TRUE(s.ok()) << s.message();
  expect_textured_table(quantized, "checker");  // the uvs 0 and 1 are exact in 16 bits
  ASSERT_EQ(quantized.instances.size(), plain.instances.size());
  for (size_t i = 0; i < plain.instances.size(); ++i) {
    const Instance& a = plain.instances[i];
    const Instance& b = quantized.instances[i];
    ASSERT_EQ(a.name, b.name);
    const Mesh& ma = plain.meshes[a.mesh];
    const Mesh& mb = quantized.meshes[b.mesh];
    ASSERT_EQ(ma.positions.size(), mb.positions.size()) << a.name;
    for (size_t v = 0; v < ma.positions.size(); ++v) {
      const glm::vec3 pa(a.mesh_to_world * glm::vec4(ma.positions[v], 1.0f));
      const glm::vec3 pb(b.mesh_to_world * glm::vec4(mb.positions[v], 1.0f));
      EXPECT_LE(glm::length(pa - pb), 0.5f / 1024.0f * std::sqrt(3.0f) + 1e-6f) << a.name << " vertex " << v;
      EXPECT_LE(glm::length(ma.normals[v] - mb.normals[v]), std::sqrt(3.0f) / 127.0f + 1e-6f)
          << a.name << " normal " << v;
    }
    EXPECT_EQ(ma.indices, mb.indices) << a.name;
  }
}

// KHR_texture_transform on the base colour texture (offset [0.5, 0.25], rotation pi/2, scale
// [2, 3], listed as required) is applied to the uvs on load as the extension defines it:
// uv' = translation * rotation * scale * uv, rotation = [cos sin; -sin cos].
TEST(TexturedFixture, TextureTransformIsAppliedToTheUvs) {
  World world;
  const Status s = load_world(test::fixture("good/textured_table_transform.gltf"), world);
  ASSERT_TRUE(s.ok()) << s.message();
  const Mesh* table = find_mesh(world, "Table");
  ASSERT_NE(table, nullptr);
  ASSERT_EQ(table->uvs.size(), kTableUvs.size());
  const double r = 1.5707963267948966, c = std::cos(r), sn = std::sin(r);
  for (size_t i = 0; i < kTableUvs.size(); ++i) {
    const double u = 2.0 * kTableUvs[i].x, v = 3.0 * kTableUvs[i].y;
    EXPECT_NEAR(table->uvs[i].x, c * u + sn * v + 0.5, 1e-6) << i;
    EXPECT_NEAR(table->uvs[i].y, -sn * u + c * v + 0.25, 1e-6) << i;
  }
  EXPECT_EQ(table->uvs[2], glm::vec2(3.5f, -1.75f));  // (1, 1): (3 + 0.5, -2 + 0.25)
}

// A base colour texture that names uv set 1 (texCoord 1) is mapped by TEXCOORD_1, not by the
// TEXCOORD_0 the mesh also has (which holds other coordinates in the fixture).
TEST(TexturedFixture, TextureReadsTheUvSetItNames) {
  World world;
  const Status s = load_world(test::fixture("good/textured_table_uv_set_1.gltf"), world);
  ASSERT_TRUE(s.ok()) << s.message();
  expect_textured_table(world, "checker");
}

TEST(TexturedFixture, ExternalImageNeedsABaseDirectory) {
  const std::string path = test::fixture("good/textured_table_external_image.gltf");
  std::ifstream in(path, std::ios::binary);
  const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  World world;
  const Status refused = load_world_from_memory(bytes.data(), bytes.size(), "memory.gltf", "", world);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(
      refused.message(),
      "memory.gltf: images[0] 'checker': external image 'checker.png' cannot be resolved without a base directory");
  const Status found = load_world_from_memory(bytes.data(), bytes.size(), "memory.gltf", test::fixture("good"), world);
  ASSERT_TRUE(found.ok()) << found.message();
  expect_textured_table(world, "checker");
}

// The two-room ring with one more instance in the first room: a textured quad named "Quad".
SceneDesc textured_rooms(const TextureDesc& texture, const std::vector<glm::vec2>& uvs) {
  SceneDesc scene = generate_ring({2, 1});
  scene.textures = {texture};
  MeshDesc quad;
  quad.name = "Quad";
  quad.positions = {{-0.5f, 0.5f, -0.5f}, {0.5f, 0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}, {-0.5f, 0.5f, 0.5f}};
  quad.indices = {0, 2, 1, 0, 3, 2};
  quad.uvs = uvs;
  quad.texture = 0;
  quad.base_color = {0.25f, 0.5f, 1.0f, 1.0f};
  scene.meshes.push_back(quad);
  int first_cell = 0;
  while (scene.nodes[size_t(first_cell)].kind != NodeDesc::Kind::Cell) ++first_cell;
  add_instance(scene, first_cell, int(scene.meshes.size() - 1), 0.0f);
  return scene;
}

TextureDesc gradient(uint32_t width, uint32_t height) {
  TextureDesc t;
  t.name = "gradient";
  t.width = width;
  t.height = height;
  t.rgba8.resize(size_t(width) * height * 4);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      uint8_t* texel = &t.rgba8[(size_t(y) * width + x) * 4];
      texel[0] = uint8_t(x * 255 / width);
      texel[1] = uint8_t(y * 255 / height);
      texel[2] = uint8_t(x ^ y);
      texel[3] = uint8_t(200 + x % 7);
    }
  return t;
}

void expect_round_trip(const World& w, const TextureDesc& texture, const std::vector<glm::vec2>& uvs) {
  ASSERT_EQ(w.textures.size(), 1u);
  EXPECT_EQ(w.textures[0].name, texture.name);
  EXPECT_EQ(w.textures[0].width, texture.width);
  EXPECT_EQ(w.textures[0].height, texture.height);
  EXPECT_EQ(w.textures[0].rgba8, texture.rgba8);  // PNG is lossless, row order kept
  const Mesh* quad = find_mesh(w, "Quad");
  ASSERT_NE(quad, nullptr);
  EXPECT_EQ(quad->base_color_texture, 0);
  EXPECT_EQ(quad->uvs, uvs);  // floats written and read as raw bytes: exact
  EXPECT_EQ(quad->base_color, glm::vec4(0.25f, 0.5f, 1.0f, 1.0f));
  for (const Mesh& m : w.meshes) {
    if (&m != quad) {
      EXPECT_EQ(m.base_color_texture, -1) << m.name;
    }
  }
}

TEST(TexturedRoundTrip, GlbGltfAndBuildWorldKeepPixelsUvsAndTextureIndex) {
  const TextureDesc texture = gradient(7, 5);  // odd sizes: rows are not 4-byte aligned in the PNG
  const std::vector<glm::vec2> uvs = {{-0.25f, 0.1f}, {3.5f, 0.1f}, {3.5f, 2.75f}, {-0.25f, 2.75f}};
  const SceneDesc scene = textured_rooms(texture, uvs);

  World built;
  const Status b = build_world(scene, "memory", built);
  ASSERT_TRUE(b.ok()) << b.message();
  expect_round_trip(built, texture, uvs);

  const std::string dir = test::scratch_dir("textured_round_trip");
  for (const char* name : {"/rooms.glb", "/rooms.gltf"}) {
    const std::string path = dir + name;
    const Status saved = save_scene(scene, path);
    ASSERT_TRUE(saved.ok()) << saved.message();
    World loaded;
    const Status s = load_world(path, loaded);
    ASSERT_TRUE(s.ok()) << s.message();
    expect_round_trip(loaded, texture, uvs);
  }
}

TEST(TexturedRoundTrip, UntexturedUvsSurviveToo) {
  SceneDesc scene = textured_rooms(gradient(2, 2), {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  scene.meshes.back().texture = -1;
  scene.textures.clear();
  World w;
  const Status s = build_world(scene, "memory", w);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_TRUE(w.textures.empty());
  const Mesh* quad = find_mesh(w, "Quad");
  ASSERT_NE(quad, nullptr);
  EXPECT_EQ(quad->base_color_texture, -1);
  EXPECT_EQ(quad->uvs, (std::vector<glm::vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
}

TEST(TexturedRoundTrip, OneWorldTexturePerImageHoweverManyMeshesUseIt) {
  const std::vector<glm::vec2> uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  SceneDesc scene = textured_rooms(gradient(3, 3), uvs);
  scene.textures.push_back(gradient(4, 2));
  // Two more quads: one with the same texture (another colour: another material), one with the
  // second texture, each drawn by an instance in the same room as the first.
  MeshDesc same = scene.meshes.back();
  same.name = "Rug";
  same.base_color = {1, 1, 1, 1};
  MeshDesc other = scene.meshes.back();
  other.name = "Mat";
  other.texture = 1;
  const int cell_node = scene.nodes.back().parent;
  scene.meshes.push_back(same);
  add_instance(scene, cell_node, int(scene.meshes.size() - 1), 0.1f);
  scene.meshes.push_back(other);
  add_instance(scene, cell_node, int(scene.meshes.size() - 1), 0.2f);
  World w;
  const Status s = build_world(scene, "memory", w);
  ASSERT_TRUE(s.ok()) << s.message();
  ASSERT_EQ(w.textures.size(), 2u);
  ASSERT_NE(find_mesh(w, "Rug"), nullptr);
  ASSERT_NE(find_mesh(w, "Mat"), nullptr);
  EXPECT_EQ(find_mesh(w, "Quad")->base_color_texture, 0);
  EXPECT_EQ(find_mesh(w, "Rug")->base_color_texture, 0);
  EXPECT_EQ(find_mesh(w, "Mat")->base_color_texture, 1);
  EXPECT_EQ(w.textures[0].width, 3u);
  EXPECT_EQ(w.textures[1].width, 4u);
}

TEST(TexturedRoundTrip, WriterRefusesWhatTheLoaderWould) {
  const std::vector<glm::vec2> uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::vector<uint8_t> glb;
  {
    SceneDesc scene = textured_rooms(gradient(2, 2), uvs);
    scene.meshes.back().uvs.clear();
    const Status s = scene_to_glb(scene, glb);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.message(),
              "scene: mesh " + std::to_string(scene.meshes.size() - 1) + " 'Quad': has a texture but no uvs");
  }
  {
    SceneDesc scene = textured_rooms(gradient(2, 2), uvs);
    scene.meshes.back().texture = 1;
    EXPECT_EQ(scene_to_glb(scene, glb).message(),
              "scene: mesh " + std::to_string(scene.meshes.size() - 1) + " 'Quad': texture 1 is out of range");
  }
  {
    SceneDesc scene = textured_rooms(gradient(2, 2), uvs);
    scene.textures[0].rgba8.pop_back();
    EXPECT_EQ(scene_to_glb(scene, glb).message(),
              "scene: texture 0 'gradient': has 15 bytes, width * height * 4 is 16");
  }
  {
    SceneDesc scene = textured_rooms(gradient(2, 2), uvs);
    scene.textures[0].width = 8193;
    EXPECT_EQ(scene_to_glb(scene, glb).message(), "scene: texture 0 'gradient': size 8193x2 is outside 1..8192");
  }
  {
    SceneDesc scene = textured_rooms(gradient(2, 2), uvs);
    scene.meshes.back().uvs.pop_back();
    EXPECT_EQ(scene_to_glb(scene, glb).message(),
              "scene: mesh " + std::to_string(scene.meshes.size() - 1) + " 'Quad': has 3 uvs for 4 positions");
  }
}

}  // namespace
}  // namespace lintel
