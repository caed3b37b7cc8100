// Meshes of several materials: a glTF mesh's primitives may each name a material (a chair of wood
// with a painted backrest, a room with a rug), and the loader used to draw the whole mesh with the
// first primitive's (a silent wrong picture). It now loads such a mesh as one Mesh per material,
// drawn as one instance per part placed by the node (a shell's other parts are instances of its
// cell), and a timeline key naming the node moves every part. Fixture good/multi_material.gltf:
// the three-room scene with a red backrest on the chair and a red rug in the room shell
// (tests/scene/fixtures/make_fixtures.py).
#include "fixture_support.h"

#include <lintel/optimize.h>
#include <lintel/rooms_import.h>
#include <lintel/scene_io.h>
#include <lintel/timeline.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace lintel {
namespace {

const glm::vec4 kOak(0.6f, 0.3f, 0.1f, 1.0f), kPaint(0.9f, 0.1f, 0.1f, 1.0f), kWhite(1.0f);

std::vector<const Instance*> instances_named(const World& world, const std::string& name) {
  std::vector<const Instance*> out;
  for (const Instance& instance : world.instances)
    if (instance.name == name) out.push_back(&instance);
  return out;
}

// World-space triangles of `instance`, corners as written, sorted: a multiset to compare. With
// `grid` > 0 each coordinate is rounded to a multiple of it first (a writer's transform may differ
// from the loaded one by a few ulps).
std::vector<std::vector<float>> world_triangles(const World& world, const Instance& instance, float grid = 0.0f) {
  const Mesh& mesh = world.meshes[instance.mesh];
  std::vector<std::vector<float>> out;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    std::vector<float> row;
    for (size_t k = 0; k < 3; ++k) {
      const glm::vec3 p(instance.mesh_to_world * glm::vec4(mesh.positions[mesh.indices[t + k]], 1.0f));
      for (int c = 0; c < 3; ++c) row.push_back(grid > 0.0f ? std::round(p[c] / grid) * grid : p[c]);
    }
    out.push_back(row);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Property: each material of a mesh is drawn with its own looks. The chair's two primitives load as
// two instances of one node (same name, same transform), one with the oak of the first primitive
// and its triangles exactly (those of the single-material scene's chair), the other with the paint
// and the backrest's 12 triangles; the room shell keeps its first primitive (no material: white)
// as the cell's shell and draws its rug as an instance of each cell that uses it. Meshes of one
// material load as before.
TEST(MultiMaterial, EachMaterialIsItsOwnMeshDrawnByTheNode) {
  World plain, world;
  ASSERT_TRUE(load_world(test::fixture("good/three_rooms.gltf"), plain).ok());
  const Status s = load_world(test::fixture("good/multi_material.gltf"), world);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(world.meshes.size(), plain.meshes.size() + 2);  // the chair's and the shell's second parts

  const auto plain_chair = instances_named(plain, "HallChair");
  const auto chair = instances_named(world, "HallChair");
  ASSERT_EQ(plain_chair.size(), 1u);
  ASSERT_EQ(chair.size(), 2u);
  EXPECT_EQ(chair[0]->mesh_to_world, chair[1]->mesh_to_world);
  EXPECT_EQ(chair[0]->node, chair[1]->node);
  EXPECT_NE(chair[0]->group, chair[1]->group);
  EXPECT_EQ(world.meshes[chair[0]->mesh].base_color, kOak);
  EXPECT_EQ(world.meshes[chair[1]->mesh].base_color, kPaint);
  EXPECT_EQ(world_triangles(world, *chair[0]), world_triangles(plain, *plain_chair[0]));
  EXPECT_EQ(world.meshes[chair[1]->mesh].indices.size(), 36u);
  EXPECT_EQ(instances_named(world, "KitchenChair").size(), 2u);

  for (const char* name : {"Hall", "Cellar"}) {
    SCOPED_TRACE(name);
    const int c = world.find_cell(name), p = plain.find_cell(name);
    ASSERT_GE(c, 0);
    const Cell& cell = world.cells[size_t(c)];
    EXPECT_EQ(world.meshes[size_t(cell.shell_mesh)].base_color, kWhite);
    EXPECT_EQ(world.meshes[size_t(cell.shell_mesh)].indices,
              plain.meshes[size_t(plain.cells[size_t(p)].shell_mesh)].indices);
    const auto rug = instances_named(world, name);
    ASSERT_EQ(rug.size(), 1u);
    EXPECT_EQ(rug[0]->cell, uint32_t(c));
    EXPECT_EQ(rug[0]->mesh_to_world, cell.cell_to_world);
    EXPECT_EQ(world.meshes[rug[0]->mesh].base_color, kPaint);
    EXPECT_EQ(world.meshes[rug[0]->mesh].indices.size(), 6u);
    EXPECT_TRUE(std::find(cell.instances.begin(), cell.instances.end(), uint32_t(rug[0] - world.instances.data())) !=
                cell.instances.end());
  }
}

// Property: a timeline key naming a node of several materials moves all its parts, keeping them
// together at every time; instances of one name placed apart are still ambiguous (an error).
TEST(MultiMaterial, TimelineMovesEveryPartOfTheNode) {
  World world;
  ASSERT_TRUE(load_world(test::fixture("good/multi_material.gltf"), world).ok());
  ASSERT_FALSE(world.timelines.empty());
  Timeline timeline = world.timelines.front();
  std::vector<InstanceTrack> tracks;
  const Status s = resolve_timeline_instances(world, timeline, tracks);
  ASSERT_TRUE(s.ok()) << s.message();
  ASSERT_EQ(tracks.size(), 2u);
  EXPECT_NE(tracks[0].instance, tracks[1].instance);
  for (const InstanceTrack& track : tracks) {
    EXPECT_EQ(world.instances[track.instance].name, "HallChair");
    EXPECT_EQ(track.keys.size(), 2u);
  }
  for (const double t : {0.0, 0.7, 2.0}) {
    glm::mat4 a, b;
    ASSERT_TRUE(sample_instance_track(timeline, tracks[0], t, a));
    ASSERT_TRUE(sample_instance_track(timeline, tracks[1], t, b));
    EXPECT_EQ(a, b) << "t = " << t;
  }
  world.instances[tracks[1].instance].mesh_to_world[3].x += 1.0f;
  const Status apart = resolve_timeline_instances(world, timeline, tracks);
  EXPECT_NE(apart.message().find("more than one instance is named 'HallChair'"), std::string::npos) << apart.message();
}

// Property: optimize writes the parts back (each as a node of the name, under the same transform),
// so the world it writes draws the same triangles with the same colours and its timeline still
// moves the whole chair.
TEST(MultiMaterial, OptimizeKeepsEveryPart) {
  World world;
  ASSERT_TRUE(load_world(test::fixture("good/multi_material.gltf"), world).ok());
  SceneDesc written;
  ASSERT_TRUE(optimize_world(world, {}, written).ok());
  World back;
  const Status s = build_world(written, "written", back);
  ASSERT_TRUE(s.ok()) << s.message();
  for (const char* name : {"HallChair", "KitchenChair"}) {
    SCOPED_TRACE(name);
    const auto before = instances_named(world, name), after = instances_named(back, name);
    ASSERT_EQ(after.size(), before.size());
    for (size_t i = 0; i < before.size(); ++i) {
      EXPECT_EQ(back.meshes[after[i]->mesh].base_color, world.meshes[before[i]->mesh].base_color);
      EXPECT_EQ(world_triangles(back, *after[i], 1e-4f), world_triangles(world, *before[i], 1e-4f));
    }
  }
  ASSERT_FALSE(back.timelines.empty());
  Timeline timeline = back.timelines.front();
  std::vector<InstanceTrack> tracks;
  const Status resolved = resolve_timeline_instances(back, timeline, tracks);
  ASSERT_TRUE(resolved.ok()) << resolved.message();
  EXPECT_EQ(tracks.size(), 2u);
}

// Property: the looks come from the triangles: a chair whose first primitive is a line (skipped,
// with a warning) of another material draws as one part with the oak of its triangles.
TEST(MultiMaterial, LooksComeFromTheFirstTrianglePrimitive) {
  std::ifstream in(test::fixture("good/multi_material.gltf"), std::ios::binary);
  nlohmann::json doc = nlohmann::json::parse(in);
  for (nlohmann::json& mesh : doc["meshes"]) {
    if (mesh["name"] != "Chair") continue;
    nlohmann::json line = mesh["primitives"][1];  // the backrest's positions, drawn as lines
    line.erase("indices");
    line["mode"] = 1;
    mesh["primitives"] = nlohmann::json::array({line, mesh["primitives"][0]});
  }
  const std::string text = doc.dump();
  World world;
  std::vector<std::string> warnings;
  const Status s = load_world_from_memory(reinterpret_cast<const uint8_t*>(text.data()), text.size(), "line.gltf",
                                          test::fixture("good"), world, &warnings);
  ASSERT_TRUE(s.ok()) << s.message();
  const auto chair = instances_named(world, "HallChair");
  ASSERT_EQ(chair.size(), 1u);
  EXPECT_EQ(world.meshes[chair[0]->mesh].base_color, kOak);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("primitive 0: has mode 1 (lines)"), std::string::npos) << warnings[0];
}

// The rooms example as a GLB whose JSON `edit` changed (the BIN chunk kept).
std::vector<uint8_t> edited_rooms_example(const std::function<void(nlohmann::json&)>& edit) {
  std::vector<uint8_t> glb;
  EXPECT_TRUE(scene_to_glb(generate_rooms_example(), glb).ok());
  uint32_t json_length = 0;
  std::memcpy(&json_length, glb.data() + 12, 4);
  nlohmann::json doc = nlohmann::json::parse(glb.begin() + 20, glb.begin() + 20 + json_length);
  edit(doc);
  std::string text = doc.dump();
  while (text.size() % 4 != 0) text += ' ';
  std::vector<uint8_t> out(glb.begin(), glb.begin() + 12);
  const uint32_t length = uint32_t(text.size()), type = 0x4E4F534A;  // "JSON"
  out.resize(20);
  std::memcpy(out.data() + 12, &length, 4);
  std::memcpy(out.data() + 16, &type, 4);
  out.insert(out.end(), text.begin(), text.end());
  out.insert(out.end(), glb.begin() + 20 + json_length, glb.end());
  const uint32_t total = uint32_t(out.size());
  std::memcpy(out.data() + 8, &total, 4);
  return out;
}

// Property: `import rooms` (the Blender path, where meshes of several materials are the rule) keeps
// every material too: a room's mesh of two materials is its shell and an instance of the second
// part, and an instance's mesh of two is two instances of its name, each with its colour and
// triangles.
TEST(MultiMaterial, ImportRoomsKeepsEveryPart) {
  const SceneDesc example = generate_rooms_example();
  const std::vector<uint8_t> glb = edited_rooms_example([](nlohmann::json& doc) {
    auto mesh_of = [&](const std::string& node) -> nlohmann::json& {
      for (const nlohmann::json& n : doc["nodes"])
        if (n["name"] == node) return doc["meshes"][n["mesh"].get<size_t>()];
      throw std::runtime_error("no node " + node);
    };
    const nlohmann::json table = mesh_of("KitchenTable")["primitives"][0];
    const nlohmann::json chair = mesh_of("KitchenChair")["primitives"][0];
    mesh_of("Hall-room")["primitives"].push_back(table);
    mesh_of("KitchenTable")["primitives"].push_back(chair);
  });
  SceneDesc imported;
  const Status s = import_rooms_from_memory(glb.data(), glb.size(), "rooms.glb", "", imported);
  ASSERT_TRUE(s.ok()) << s.message();
  World world;
  ASSERT_TRUE(build_world(imported, "imported", world).ok());
  auto colour_of = [&](const std::string& mesh_name) {
    for (const MeshDesc& m : example.meshes)
      if (m.name == mesh_name) return m.base_color;
    ADD_FAILURE() << "no mesh " << mesh_name;
    return glm::vec4(0.0f);
  };
  const glm::vec4 walls = colour_of("Hall walls"), table = colour_of("table"), chair = colour_of("chair");
  ASSERT_NE(walls, table);
  ASSERT_NE(table, chair);
  const int hall = world.find_cell("Hall");
  ASSERT_GE(hall, 0);
  EXPECT_EQ(world.meshes[size_t(world.cells[size_t(hall)].shell_mesh)].base_color, walls);
  const auto rug = instances_named(world, "Hall");
  ASSERT_EQ(rug.size(), 1u);
  EXPECT_EQ(world.meshes[rug[0]->mesh].base_color, table);
  EXPECT_EQ(rug[0]->cell, uint32_t(hall));
  const auto parts = instances_named(world, "KitchenTable");
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(world.meshes[parts[0]->mesh].base_color, table);
  EXPECT_EQ(world.meshes[parts[1]->mesh].base_color, chair);
  EXPECT_EQ(parts[0]->mesh_to_world, parts[1]->mesh_to_world);
  const auto chairs = instances_named(world, "KitchenChair");
  ASSERT_FALSE(chairs.empty());
  EXPECT_EQ(world.meshes[parts[1]->mesh].indices.size(), world.meshes[chairs[0]->mesh].indices.size());
}

}  // namespace
}  // namespace lintel
