// Mirrored instances: a node scale with a negative component, or a matrix with a negative
// determinant, is valid glTF 2.0 (exporters write it for mirrored copies), and the loader used to
// refuse the whole scene for it. It now loads the instance with its mesh unchanged: as glTF 2.0
// says, a mirroring transform turns the front faces clockwise, the rule every reader of the World
// already applies (the renderer's kFaceMirrored, the GI surfels, the path tracer, the ray cast's
// Embree mesh); a mirrored cell is still refused (scene_bad_input_test). Fixtures:
// good/mirrored_table_{scale,matrix}.gltf, the three-room scene with its table mirrored
// (tests/scene/fixtures/make_fixtures.py).
#include "fixture_support.h"

#include <lintel/optimize.h>
#include <lintel/rooms_import.h>
#include <lintel/scene_io.h>

#include <glm/gtc/matrix_inverse.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace lintel {
namespace {

const Instance* instance_named(const World& world, const std::string& name) {
  for (const Instance& instance : world.instances)
    if (instance.name == name) return &instance;
  return nullptr;
}

// The triangles of `instance` whose front face points against the mesh's vertex normals mapped to
// world space by the inverse transpose: faces that back-face culling would drop where the normals
// say they face the viewer. The front face is counter-clockwise as seen, or clockwise when the
// transform mirrors (glTF's rule) unless `ignore_mirror_rule`.
size_t inside_out_triangles(const World& world, const Instance& instance, bool ignore_mirror_rule = false) {
  const Mesh& mesh = world.meshes[instance.mesh];
  const glm::mat4& m = instance.mesh_to_world;
  const glm::mat3 normal_to_world = glm::inverseTranspose(glm::mat3(m));
  const float front = !ignore_mirror_rule && glm::determinant(glm::mat3(m)) < 0.0f ? -1.0f : 1.0f;
  size_t bad = 0;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    glm::vec3 p[3], n(0.0f);
    for (int k = 0; k < 3; ++k) {
      p[k] = glm::vec3(m * glm::vec4(mesh.positions[mesh.indices[t + size_t(k)]], 1.0f));
      n += mesh.normals[mesh.indices[t + size_t(k)]];
    }
    const glm::vec3 winding = glm::cross(p[1] - p[0], p[2] - p[0]);
    if (glm::length(winding) < 1e-9f) continue;  // degenerate: no side to get wrong
    if (front * glm::dot(winding, normal_to_world * n) <= 0.0f) ++bad;
  }
  return bad;
}

// World-space corners of an instance's triangles, each triangle rotated to start at its smallest
// corner (lexicographic) so that the same triangle compares equal whatever corner came first.
std::vector<std::array<float, 9>> world_triangles(const World& world, const Instance& instance) {
  const Mesh& mesh = world.meshes[instance.mesh];
  std::vector<std::array<float, 9>> out;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    std::array<glm::vec3, 3> p;
    for (int k = 0; k < 3; ++k)
      p[size_t(k)] = glm::vec3(instance.mesh_to_world * glm::vec4(mesh.positions[mesh.indices[t + size_t(k)]], 1.0f));
    auto less = [](const glm::vec3& a, const glm::vec3& b) {
      return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
    };
    const size_t first = size_t(std::min_element(p.begin(), p.end(), less) - p.begin());
    std::array<float, 9> row{};
    for (size_t k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) row[k * 3 + size_t(c)] = p[(first + k) % 3][c];
    out.push_back(row);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Property, on both fixtures (scale and matrix): the mirrored table loads with the file's mesh (the
// same triangles in the same order) under a transform that mirrors; by glTF's rule no triangle of
// any instance is inside out, and the unmirrored scene passes the same check (a check of the
// fixture as well). The rule matters: read counter-clockwise, every face of the mirrored table
// would be inside out.
TEST(MirroredInstance, LoadsWithItsMeshAndFrontFacesFaceOutByGltfsRule) {
  World plain;
  ASSERT_TRUE(load_world(test::fixture("good/three_rooms.gltf"), plain).ok());
  for (const Instance& instance : plain.instances)
    EXPECT_EQ(inside_out_triangles(plain, instance), 0u) << instance.name;
  const Instance* plain_table = instance_named(plain, "HallTable");
  ASSERT_NE(plain_table, nullptr);
  for (const char* file : {"good/mirrored_table_scale.gltf", "good/mirrored_table_matrix.gltf"}) {
    SCOPED_TRACE(file);
    World world;
    const Status s = load_world(test::fixture(file), world);
    ASSERT_TRUE(s.ok()) << s.message();
    const Instance* table = instance_named(world, "HallTable");
    ASSERT_NE(table, nullptr);
    EXPECT_LT(glm::determinant(glm::mat3(table->mesh_to_world)), 0.0f);
    EXPECT_EQ(world.meshes.size(), plain.meshes.size());
    EXPECT_EQ(world.meshes[table->mesh].indices, plain.meshes[plain_table->mesh].indices);
    for (const Instance& instance : world.instances)
      EXPECT_EQ(inside_out_triangles(world, instance), 0u) << instance.name;
    const size_t faces = world.meshes[table->mesh].indices.size() / 3;
    EXPECT_EQ(inside_out_triangles(world, *table, /*ignore_mirror_rule=*/true), faces);
  }
}

// Property: the World's writers (optimize; export rooms, then import rooms) write a mirrored
// instance as the file's mesh under its mirroring transform (a negative x scale), so loading what
// they wrote gives the same world-space triangles, corner order included: mirrored once, not twice
// and not lost.
TEST(MirroredInstance, WritersKeepTheMirror) {
  World world;
  ASSERT_TRUE(load_world(test::fixture("good/mirrored_table_scale.gltf"), world).ok());
  const Instance* table = instance_named(world, "HallTable");
  ASSERT_NE(table, nullptr);
  SceneDesc optimized, exported, imported;
  ASSERT_TRUE(optimize_world(world, {}, optimized).ok());
  ASSERT_TRUE(export_rooms(world, exported).ok());
  std::vector<uint8_t> glb;
  ASSERT_TRUE(scene_to_glb(exported, glb).ok());
  const Status rooms = import_rooms_from_memory(glb.data(), glb.size(), "exported", "", imported);
  ASSERT_TRUE(rooms.ok()) << rooms.message();
  for (const SceneDesc* written : {&optimized, &imported}) {
    SCOPED_TRACE(written == &optimized ? "optimize" : "export rooms, import rooms");
    World back;
    const Status s = build_world(*written, "written", back);
    ASSERT_TRUE(s.ok()) << s.message();
    const Instance* again = instance_named(back, "HallTable");
    ASSERT_NE(again, nullptr);
    EXPECT_LT(glm::determinant(glm::mat3(again->mesh_to_world)), 0.0f);
    EXPECT_EQ(world_triangles(back, *again), world_triangles(world, *table));
    EXPECT_EQ(inside_out_triangles(back, *again), 0u);
  }
}

// Six times the signed volume a closed triangle list encloses (positive when its faces point out).
double six_signed_volume(const std::vector<glm::vec3>& triangles) {
  double sum = 0.0;
  for (size_t t = 0; t + 2 < triangles.size(); t += 3)
    sum += glm::dot(glm::dvec3(triangles[t]), glm::cross(glm::dvec3(triangles[t + 1]), glm::dvec3(triangles[t + 2])));
  return sum;
}

// Property: a volume node whose transform mirrors (the Kitchen's, scale x -1 about its own centre,
// so the volume covers the same space) gives the cell a volume whose faces still point out: the
// loader reverses each triangle, and the signed volume is the unmirrored one's.
TEST(MirroredInstance, MirroredVolumeNodeKeepsItsFacesOutward) {
  const std::string path = test::fixture("good/three_rooms.gltf");
  std::ifstream in(path, std::ios::binary);
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::string node = "\"name\": \"KitchenVolume\",";
  const size_t at = text.find(node);
  ASSERT_NE(at, std::string::npos);
  text.insert(at + node.size(), " \"scale\": [-1, 1, 1],");
  World plain, mirrored;
  ASSERT_TRUE(load_world(path, plain).ok());
  const Status s = load_world_from_memory(reinterpret_cast<const uint8_t*>(text.data()), text.size(), "mirrored.gltf",
                                          test::fixture("good"), mirrored);
  ASSERT_TRUE(s.ok()) << s.message();
  const int kitchen = mirrored.find_cell("Kitchen");
  ASSERT_GE(kitchen, 0);
  const double before = six_signed_volume(plain.cells[size_t(kitchen)].volume_triangles_cell);
  const double after = six_signed_volume(mirrored.cells[size_t(kitchen)].volume_triangles_cell);
  EXPECT_GT(before, 0.0);
  EXPECT_NEAR(after, before, 1e-4 * before);
}

}  // namespace
}  // namespace lintel
