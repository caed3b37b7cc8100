// Mirrored instances: a node scale with a negative component, or a matrix with a negative
// determinant, is valid glTF 2.0 (exporters write it for mirrored copies), and the loader used to
// refuse the whole scene for it. It now loads the instance with a mirror twin of its mesh (the same
// vertices, each triangle's winding reversed: Mesh::mirror_of), so that back-face culling and every
// reader of the mesh keep working unchanged; a mirrored cell is still refused
// (scene_bad_input_test). Fixtures: good/mirrored_table_{scale,matrix}.gltf, the three-room scene
// with its table mirrored (tests/scene/fixtures/make_fixtures.py).
#include "fixture_support.h"

#include <lintel/optimize.h>
#include <lintel/rooms_import.h>
#include <lintel/scene_io.h>

#include <glm/gtc/matrix_inverse.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace lintel {
namespace {

const Instance* instance_named(const World& world, const std::string& name) {
  for (const Instance& instance : world.instances)
    if (instance.name == name) return &instance;
  return nullptr;
}

// The triangles of `instance` in world space whose winding (right-hand rule, as the rasterizer
// sees it) points against the mesh's vertex normals mapped to world space by the inverse transpose:
// back faces that culling would drop where the normals say the surface faces the viewer.
size_t inside_out_triangles(const World& world, const Instance& instance) {
  const Mesh& mesh = world.meshes[instance.mesh];
  const glm::mat4& m = instance.mesh_to_world;
  const glm::mat3 normal_to_world = glm::inverseTranspose(glm::mat3(m));
  size_t bad = 0;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    glm::vec3 p[3], n(0.0f);
    for (int k = 0; k < 3; ++k) {
      p[k] = glm::vec3(m * glm::vec4(mesh.positions[mesh.indices[t + size_t(k)]], 1.0f));
      n += mesh.normals[mesh.indices[t + size_t(k)]];
    }
    const glm::vec3 winding = glm::cross(p[1] - p[0], p[2] - p[0]);
    if (glm::length(winding) < 1e-9f) continue;  // degenerate: no side to get wrong
    if (glm::dot(winding, normal_to_world * n) <= 0.0f) ++bad;
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

// Property, on both fixtures (scale and matrix): the mirrored table loads; its mesh is a twin of the
// file's table mesh (same vertices and normals, same triangle count, windings reversed), in a draw
// group of its own; and no triangle of any instance is inside out (winding against its normals),
// so culling back faces never removes a face turned to the camera. The unmirrored scene passes the
// same check, which makes it a check of the fixture as well.
TEST(MirroredInstance, LoadsWithATwinMeshWhoseFrontFacesFaceOut) {
  World plain;
  ASSERT_TRUE(load_world(test::fixture("good/three_rooms.gltf"), plain).ok());
  for (const Instance& instance : plain.instances)
    EXPECT_EQ(inside_out_triangles(plain, instance), 0u) << instance.name;
  for (const char* file : {"good/mirrored_table_scale.gltf", "good/mirrored_table_matrix.gltf"}) {
    SCOPED_TRACE(file);
    World world;
    const Status s = load_world(test::fixture(file), world);
    ASSERT_TRUE(s.ok()) << s.message();
    const Instance* table = instance_named(world, "HallTable");
    ASSERT_NE(table, nullptr);
    const Mesh& twin = world.meshes[table->mesh];
    ASSERT_GE(twin.mirror_of, 0);
    const Mesh& original = world.meshes[size_t(twin.mirror_of)];
    EXPECT_EQ(original.mirror_of, -1);
    EXPECT_EQ(twin.positions, original.positions);
    EXPECT_EQ(twin.normals, original.normals);
    ASSERT_EQ(twin.indices.size(), original.indices.size());
    EXPECT_NE(twin.indices, original.indices);
    EXPECT_EQ(world.groups[table->group].mesh, table->mesh);
    EXPECT_EQ(world.groups[table->group].instances.size(), 1u);
    EXPECT_EQ(world.meshes.size(), plain.meshes.size() + 1);  // one twin, nothing else new
    for (const Instance& instance : world.instances)
      EXPECT_EQ(inside_out_triangles(world, instance), 0u) << instance.name;
    // Without the twin (the file's mesh under the mirroring transform) every face would be inside out.
    Instance untwinned = *table;
    untwinned.mesh = uint32_t(twin.mirror_of);
    EXPECT_EQ(inside_out_triangles(world, untwinned), original.indices.size() / 3);
  }
}

// Property: the World's writers (optimize, export rooms) write a mirrored instance as the file's
// mesh under its mirroring transform, never the twin, so loading what they wrote gives the same
// world-space triangles with the same windings (not mirrored twice), and no extra mesh.
TEST(MirroredInstance, WritersKeepTheFilesMeshAndTheMirror) {
  World world;
  ASSERT_TRUE(load_world(test::fixture("good/mirrored_table_scale.gltf"), world).ok());
  const Instance* table = instance_named(world, "HallTable");
  ASSERT_NE(table, nullptr);
  const size_t file_meshes =
      size_t(std::count_if(world.meshes.begin(), world.meshes.end(), [](const Mesh& m) { return m.mirror_of < 0; }));
  SceneDesc optimized, exported, imported;
  ASSERT_TRUE(optimize_world(world, {}, optimized).ok());
  ASSERT_TRUE(export_rooms(world, exported).ok());
  // The rooms convention becomes a Lintel scene again through import rooms.
  std::vector<uint8_t> glb;
  ASSERT_TRUE(scene_to_glb(exported, glb).ok());
  const Status rooms = import_rooms_from_memory(glb.data(), glb.size(), "exported", "", imported);
  ASSERT_TRUE(rooms.ok()) << rooms.message();
  for (const SceneDesc* written : {&optimized, &imported}) {
    EXPECT_LE(written->meshes.size(), file_meshes + world.cells.size() + world.portals.size());
    World back;
    const Status s = build_world(*written, "written", back);
    ASSERT_TRUE(s.ok()) << s.message();
    const Instance* again = instance_named(back, "HallTable");
    ASSERT_NE(again, nullptr) << (written == &optimized ? "optimize" : "export rooms, import rooms") << ": "
                              << back.instances.size() << " instances";
    ASSERT_GE(back.meshes[again->mesh].mirror_of, 0);
    EXPECT_EQ(world_triangles(back, *again), world_triangles(world, *table));
    EXPECT_EQ(inside_out_triangles(back, *again), 0u);
    EXPECT_EQ(std::count_if(back.meshes.begin(), back.meshes.end(), [](const Mesh& m) { return m.mirror_of >= 0; }), 1);
  }
}

}  // namespace
}  // namespace lintel
