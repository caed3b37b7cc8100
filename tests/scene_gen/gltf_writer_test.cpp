// The writer: .gltf + .bin and .glb from one serialization, files that tinygltf reads without
// complaint, floats that survive the round trip exactly, clear errors for bad paths and bad
// scene descriptions, and nothing half-written.
#include "gen_test_support.h"
#include "run_process.h"

#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace lintel {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Two cells side by side with a door between them: the smallest scene with every node kind.
SceneDesc two_rooms() { return generate_ring({2, 1}); }

class Writer : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::make_temp_dir(); }
  void TearDown() override { fs::remove_all(dir_); }
  std::string dir_;
};

TEST_F(Writer, GltfAndBinReadByTinygltf) {
  const std::string path = dir_ + "/two rooms.gltf";
  const Status s = save_scene(two_rooms(), path);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_TRUE(fs::exists(dir_ + "/two rooms.bin"));
  EXPECT_NE(read_text(path).find("\"uri\":\"two%20rooms.bin\""), std::string::npos);
  for (const auto& f : fs::directory_iterator(dir_)) EXPECT_NE(f.path().extension(), ".tmp") << f.path();

  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  ASSERT_TRUE(loader.LoadASCIIFromFile(&model, &err, &warn, path)) << err;
  EXPECT_TRUE(err.empty()) << err;
  EXPECT_TRUE(warn.empty()) << warn;
  EXPECT_EQ(model.extensionsUsed, std::vector<std::string>{"KHR_lights_punctual"});
  for (const tinygltf::Accessor& a : model.accessors) {
    EXPECT_FALSE(a.minValues.empty());
    EXPECT_FALSE(a.maxValues.empty());
  }
}

TEST_F(Writer, GlbMatchesScenetoGlbAndTinygltf) {
  const SceneDesc scene = two_rooms();
  const std::string path = dir_ + "/rooms.GLB";  // the extension is case-insensitive
  ASSERT_TRUE(save_scene(scene, path).ok());
  std::vector<uint8_t> memory;
  ASSERT_TRUE(scene_to_glb(scene, memory).ok());
  const std::string file = read_text(path);
  ASSERT_EQ(file.size(), memory.size());
  EXPECT_TRUE(std::equal(memory.begin(), memory.end(), reinterpret_cast<const uint8_t*>(file.data())));
  ASSERT_GE(memory.size(), 20u);
  EXPECT_EQ(std::string(file.data(), 4), "glTF");
  EXPECT_EQ(memory.size() % 4, 0u);

  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string err, warn;
  ASSERT_TRUE(loader.LoadBinaryFromMemory(&model, &err, &warn, memory.data(), unsigned(memory.size()))) << err;
  EXPECT_TRUE(err.empty()) << err;
}

TEST_F(Writer, PositionsSurviveTheLoaderExactly) {
  SceneDesc scene = two_rooms();
  World world;
  ASSERT_TRUE(gen_test::load(scene, "two rooms", world));
  // The first cell's shell is written and read back bit for bit.
  const MeshDesc& written = scene.meshes[size_t(scene.nodes[0].mesh)];
  const Mesh& read = world.meshes[size_t(world.cells[0].shell_mesh)];
  ASSERT_EQ(written.positions.size(), read.positions.size());
  for (size_t i = 0; i < read.positions.size(); ++i) EXPECT_EQ(written.positions[i], read.positions[i]);
  EXPECT_EQ(written.indices, read.indices);
}

TEST_F(Writer, ShortestFloatText) {
  SceneDesc scene = two_rooms();
  scene.nodes[0].translation = {0.3f, -2.5f, 1e-7f};
  const std::string path = dir_ + "/f.gltf";
  ASSERT_TRUE(save_scene(scene, path).ok());
  EXPECT_NE(read_text(path).find("\"translation\":[0.3,-2.5,1e-07]"), std::string::npos);
}

TEST_F(Writer, BadPathsAreErrorsAndWriteNothing) {
  Status s = save_scene(two_rooms(), dir_ + "/scene.obj");
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("unsupported extension '.obj'"), std::string::npos) << s.message();
  s = save_scene(two_rooms(), dir_ + "/no/such/dir/scene.gltf");
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("does not exist"), std::string::npos) << s.message();
  fs::create_directory(dir_ + "/taken.gltf");  // a directory where the file should go
  s = save_scene(two_rooms(), dir_ + "/taken.gltf");
  EXPECT_FALSE(s.ok());
  EXPECT_FALSE(fs::exists(dir_ + "/taken.bin"));
  size_t files = 0;
  for (const auto& f : fs::directory_iterator(dir_)) files += !f.is_directory();
  EXPECT_EQ(files, 0u);
}

TEST_F(Writer, BadSceneDescIsAnError) {
  SceneDesc scene = two_rooms();
  scene.meshes[0].indices.push_back(999999);
  scene.meshes[0].indices.push_back(0);
  scene.meshes[0].indices.push_back(1);
  std::vector<uint8_t> out;
  Status s = scene_to_glb(scene, out);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("out of range"), std::string::npos) << s.message();

  scene = two_rooms();
  scene.nodes[1].parent = 5;
  EXPECT_FALSE(scene_to_glb(scene, out).ok());
  scene = two_rooms();
  scene.nodes[0].translation.x = NAN;
  EXPECT_FALSE(scene_to_glb(scene, out).ok());
  scene = two_rooms();
  scene.timelines[0].keys[1].t = scene.timelines[0].keys[0].t;
  s = save_scene(scene, dir_ + "/x.gltf");
  EXPECT_FALSE(s.ok());
  EXPECT_FALSE(fs::exists(dir_ + "/x.gltf"));
}

TEST_F(Writer, LargeMeshUses32BitIndices) {
  // A grid of 64 x 64 rooms has shells far below 65535 vertices, so build a big mesh by hand.
  SceneDesc scene = two_rooms();
  MeshDesc& m = scene.meshes[size_t(scene.nodes[0].mesh)];
  const size_t base = m.positions.size();
  for (int i = 0; i < 70000; ++i) m.positions.push_back(m.positions[0]);
  m.normals.resize(m.positions.size(), glm::vec3(0, 1, 0));
  m.indices.insert(m.indices.end(), {uint32_t(base + 69999), uint32_t(base + 69998), uint32_t(base + 69997)});
  World world;
  std::vector<std::string> warnings;
  const Status s = build_world(scene, "big", world, &warnings);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(world.meshes[size_t(world.cells[0].shell_mesh)].indices.back(), base + 69997);
}

}  // namespace
}  // namespace lintel
