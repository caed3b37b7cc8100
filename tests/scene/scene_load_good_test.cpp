// The valid fixture (tests/scene/fixtures/good/three_rooms.*) loaded and checked field by field
// against values worked out by hand from make_fixtures.py: cell transforms, shells and volumes,
// portal orientation and cell-space polygons, draw groups, lights and the timeline. The same
// scene as .gltf (data URI), .gltf + .bin and .glb must give the same World.
#include "fixture_support.h"

#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iterator>

namespace lintel {
namespace {

constexpr float kEps = 1e-5f;

void expect_near(const glm::vec3& actual, const glm::vec3& expected, float eps = kEps) {
  EXPECT_NEAR(actual.x, expected.x, eps) << "x";
  EXPECT_NEAR(actual.y, expected.y, eps) << "y";
  EXPECT_NEAR(actual.z, expected.z, eps) << "z";
}

glm::vec3 apply(const glm::mat4& m, const glm::vec3& p) { return glm::vec3(m * glm::vec4(p, 1.0f)); }

// True when `actual` holds the same points as `expected`, in any order.
bool same_point_set(const std::vector<glm::vec3>& actual, const std::vector<glm::vec3>& expected) {
  if (actual.size() != expected.size()) return false;
  return std::all_of(expected.begin(), expected.end(), [&](const glm::vec3& e) {
    return std::any_of(actual.begin(), actual.end(), [&](const glm::vec3& a) { return glm::length(a - e) < 1e-4f; });
  });
}

// Newell's normal: the right-hand-rule normal of the vertex order.
glm::vec3 winding_normal(const std::vector<glm::vec3>& poly) {
  glm::vec3 n(0.0f);
  for (size_t i = 0; i < poly.size(); ++i) n += glm::cross(poly[i], poly[(i + 1) % poly.size()]);
  return glm::normalize(n);
}

class ThreeRooms : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = test::fixture("good/three_rooms.gltf");
    const Status s = load_world(path_, world_, &warnings_);
    ASSERT_TRUE(s.ok()) << s.message();
  }
  std::string path_;
  World world_;
  std::vector<std::string> warnings_;
};

TEST_F(ThreeRooms, LoadsWithoutWarningsAndRecordsSourceAndVersion) {
  EXPECT_TRUE(warnings_.empty()) << warnings_.front();
  EXPECT_EQ(world_.source, path_);
  EXPECT_EQ(world_.version, 1);
}

TEST_F(ThreeRooms, CellsFollowNodeOrderWithTheirNodeTransforms) {
  ASSERT_EQ(world_.cells.size(), 3u);
  EXPECT_EQ(world_.cells[0].name, "Hall");
  EXPECT_EQ(world_.cells[1].name, "Kitchen");
  EXPECT_EQ(world_.cells[2].name, "Cellar");
  EXPECT_EQ(world_.cells[0].node, 0);
  EXPECT_EQ(world_.cells[1].node, 1);
  EXPECT_EQ(world_.cells[2].node, 10);
  EXPECT_EQ(world_.find_cell("Kitchen"), 1);
  // Hall: translate (2,0,2) after a +90 degree turn about Y, which sends +X to -Z.
  expect_near(apply(world_.cells[0].cell_to_world, {1, 0, 0}), {2, 0, 1});
  expect_near(apply(world_.cells[0].world_to_cell, {2, 0, 1}), {1, 0, 0});
  // Kitchen: translate (6,0,2), turn 180 degrees, scale 2.
  expect_near(apply(world_.cells[1].cell_to_world, {1, 0.5f, 0}), {4, 1, 2});
  expect_near(apply(world_.cells[1].world_to_cell, {4, 1, 2}), {1, 0.5f, 0});
  expect_near(apply(world_.cells[2].cell_to_world, {0, 0, 0}), {2, -3, 2});
}

TEST_F(ThreeRooms, ShellsShareTheirMeshAndVolumesComeFromShellOrVolumeNode) {
  const Cell& hall = world_.cells[0];
  const Cell& kitchen = world_.cells[1];
  const Cell& cellar = world_.cells[2];
  ASSERT_GE(hall.shell_mesh, 0);
  EXPECT_EQ(hall.shell_mesh, cellar.shell_mesh);  // both use glTF mesh 0
  EXPECT_EQ(world_.meshes[size_t(hall.shell_mesh)].name, "RoomShell");
  EXPECT_EQ(world_.meshes[size_t(kitchen.shell_mesh)].name, "KitchenShell");

  EXPECT_TRUE(hall.volume_triangles_cell.empty());
  expect_near(hall.volume_box_cell.min, {-2, 0, -2});
  expect_near(hall.volume_box_cell.max, {2, 3, 2});

  // The Kitchen's volume node sits 0.75 above the cell origin; its box is narrower in z than the shell.
  ASSERT_EQ(kitchen.volume_triangles_cell.size(), 36u);
  expect_near(kitchen.volume_box_cell.min, {-1, 0, -0.9f});
  expect_near(kitchen.volume_box_cell.max, {1, 1.5f, 0.9f});
  for (const glm::vec3& p : kitchen.volume_triangles_cell) {
    const bool on_face = std::fabs(std::fabs(p.x) - 1) < kEps || std::fabs(p.y) < kEps ||
                         std::fabs(p.y - 1.5f) < kEps || std::fabs(std::fabs(p.z) - 0.9f) < kEps;
    EXPECT_TRUE(on_face) << p.x << " " << p.y << " " << p.z;
  }
}

TEST_F(ThreeRooms, MeshesHoldOnlyDrawnMeshesInGltfOrderWithNormalsAndColours) {
  ASSERT_EQ(world_.meshes.size(), 4u);  // portal and volume meshes are not drawn
  const int expected_index[] = {0, 1, 5, 6};
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(world_.meshes[i].gltf_index, expected_index[i]);

  const Mesh& chair = world_.meshes[2];
  EXPECT_EQ(chair.name, "Chair");
  EXPECT_EQ(chair.indices.size(), 36u);
  expect_near(chair.bounds_mesh.min, {-0.25f, 0, -0.25f});
  expect_near(chair.bounds_mesh.max, {0.25f, 0.5f, 0.25f});
  EXPECT_NEAR(chair.base_color.r, 0.6f, kEps);
  EXPECT_NEAR(chair.base_color.g, 0.3f, kEps);
  EXPECT_NEAR(chair.base_color.b, 0.1f, kEps);
  ASSERT_EQ(chair.normals.size(), chair.positions.size());
  for (size_t i = 0; i < chair.positions.size(); ++i)  // the file's NORMAL: away from (0, 0.25, 0)
    expect_near(chair.normals[i], glm::normalize(chair.positions[i] - glm::vec3(0, 0.25f, 0)));

  const Mesh& table = world_.meshes[3];
  EXPECT_EQ(table.name, "Table");
  EXPECT_EQ(table.indices, (std::vector<uint32_t>{0, 2, 1, 0, 3, 2}));
  EXPECT_EQ(table.base_color, glm::vec4(1.0f));
  ASSERT_EQ(table.normals.size(), 4u);
  for (const glm::vec3& n : table.normals) expect_near(n, {0, 1, 0});  // computed: no NORMAL in the file
}

TEST_F(ThreeRooms, InstancesAndDrawGroupsFollowNodeAndMeshOrder) {
  ASSERT_EQ(world_.instances.size(), 3u);
  const Instance& hall_chair = world_.instances[0];
  const Instance& table = world_.instances[1];
  const Instance& kitchen_chair = world_.instances[2];
  EXPECT_EQ(hall_chair.name, "HallChair");
  EXPECT_EQ(table.name, "HallTable");
  EXPECT_EQ(kitchen_chair.name, "KitchenChair");
  EXPECT_EQ(hall_chair.cell, 0u);
  EXPECT_EQ(table.cell, 0u);
  EXPECT_EQ(kitchen_chair.cell, 1u);  // below Kitchen through the plain "Furniture" node
  EXPECT_EQ(hall_chair.mesh, kitchen_chair.mesh);
  expect_near(hall_chair.bounds_world.min, {2.75f, 0, 0.75f});
  expect_near(hall_chair.bounds_world.max, {3.25f, 0.5f, 1.25f});
  expect_near(apply(kitchen_chair.mesh_to_world, {0, 0, 0}), {5, 0, 1.5f});
  const float r = 0.25f * std::sqrt(2.0f) * 2.0f;  // 45 degrees and scale 2 widen the box
  expect_near(kitchen_chair.bounds_world.min, {5 - r, 0, 1.5f - r}, 1e-4f);
  expect_near(kitchen_chair.bounds_world.max, {5 + r, 1, 1.5f + r}, 1e-4f);

  ASSERT_EQ(world_.groups.size(), 2u);
  EXPECT_EQ(world_.groups[0].mesh, 2u);
  EXPECT_EQ(world_.groups[0].instances, (std::vector<uint32_t>{0, 2}));
  EXPECT_EQ(world_.groups[1].mesh, 3u);
  EXPECT_EQ(world_.groups[1].instances, (std::vector<uint32_t>{1}));
  EXPECT_EQ(hall_chair.group, 0u);
  EXPECT_EQ(table.group, 1u);
  EXPECT_EQ(kitchen_chair.group, 0u);
  EXPECT_EQ(world_.cells[0].instances, (std::vector<uint32_t>{0, 1}));
  EXPECT_EQ(world_.cells[1].instances, (std::vector<uint32_t>{2}));
  EXPECT_TRUE(world_.cells[2].instances.empty());
}

TEST_F(ThreeRooms, TwoWayDoorIsFlippedToPointFromHallIntoKitchen) {
  ASSERT_EQ(world_.portals.size(), 2u);
  const Portal& door = world_.portals[0];
  EXPECT_EQ(door.name, "HallKitchenDoor");
  EXPECT_EQ(door.node, 2);
  EXPECT_EQ(door.from, 0u);
  EXPECT_EQ(door.to, 1u);
  EXPECT_TRUE(door.two_way);
  // The file winds it towards the Hall and adds a vertex in the middle of the bottom edge.
  expect_near(door.normal_world, {1, 0, 0});
  EXPECT_NEAR(door.plane_d_world, 4.0f, kEps);
  expect_near(door.centroid_world, {4, 1, 2});
  EXPECT_TRUE(same_point_set(door.polygon_world, {{4, 0, 1.5f}, {4, 0, 2.5f}, {4, 2, 2.5f}, {4, 2, 1.5f}}));
  expect_near(winding_normal(door.polygon_world), door.normal_world);
  EXPECT_TRUE(same_point_set(door.polygon_from_cell, {{0.5f, 0, 2}, {-0.5f, 0, 2}, {-0.5f, 2, 2}, {0.5f, 2, 2}}));
  EXPECT_TRUE(same_point_set(door.polygon_to_cell, {{1, 0, 0.25f}, {1, 0, -0.25f}, {1, 1, -0.25f}, {1, 1, 0.25f}}));
  for (size_t i = 0; i < door.polygon_world.size(); ++i) {
    expect_near(apply(world_.cells[0].world_to_cell, door.polygon_world[i]), door.polygon_from_cell[i]);
    expect_near(apply(world_.cells[1].world_to_cell, door.polygon_world[i]), door.polygon_to_cell[i]);
  }
}

TEST_F(ThreeRooms, OneWayHatchPointsDownAndLinksOnlyFromHall) {
  const Portal& hatch = world_.portals[1];
  EXPECT_EQ(hatch.name, "CellarHatch");
  EXPECT_EQ(hatch.from, 0u);
  EXPECT_EQ(hatch.to, 2u);
  EXPECT_FALSE(hatch.two_way);
  ASSERT_EQ(hatch.polygon_world.size(), 6u);
  expect_near(hatch.normal_world, {0, -1, 0});
  expect_near(winding_normal(hatch.polygon_world), {0, -1, 0});
  EXPECT_NEAR(hatch.plane_d_world, 0.0f, kEps);
  expect_near(hatch.centroid_world, {1, 0, 1});
  for (size_t i = 0; i < 6; ++i) {
    EXPECT_NEAR(glm::length(hatch.polygon_world[i] - glm::vec3(1, 0, 1)), 0.5f, kEps);
    expect_near(hatch.polygon_to_cell[i], hatch.polygon_world[i] - glm::vec3(2, -3, 2));
  }

  const auto links = [&](size_t cell) { return world_.cells[cell].links; };
  ASSERT_EQ(links(0).size(), 2u);
  EXPECT_EQ(links(0)[0].portal, 0u);
  EXPECT_EQ(links(0)[0].neighbour, 1u);
  EXPECT_EQ(links(0)[1].portal, 1u);
  EXPECT_EQ(links(0)[1].neighbour, 2u);
  ASSERT_EQ(links(1).size(), 1u);
  EXPECT_EQ(links(1)[0].portal, 0u);
  EXPECT_EQ(links(1)[0].neighbour, 0u);
  EXPECT_TRUE(links(2).empty());
}

TEST_F(ThreeRooms, LightsTakeTheirCellPositionAndMinusZDirection) {
  ASSERT_EQ(world_.lights.size(), 2u);
  const Light& lamp = world_.lights[0];
  EXPECT_EQ(lamp.name, "HallLamp");
  EXPECT_EQ(lamp.node, 5);
  EXPECT_EQ(lamp.cell, 0u);
  EXPECT_EQ(lamp.type, Light::Type::Spot);
  expect_near(lamp.color, {1, 0.9f, 0.8f});
  EXPECT_FLOAT_EQ(lamp.intensity, 50.0f);
  EXPECT_FLOAT_EQ(lamp.range, 10.0f);
  EXPECT_FLOAT_EQ(lamp.inner_cone_rad, 0.3f);
  EXPECT_FLOAT_EQ(lamp.outer_cone_rad, 0.6f);
  expect_near(lamp.position_world, {2, 2.5f, 2});
  expect_near(lamp.direction_world, {-1, 0, 0});  // local -Z turned by the Hall's +90 degrees

  const Light& bulb = world_.lights[1];
  EXPECT_EQ(bulb.name, "CellarBulb");
  EXPECT_EQ(bulb.cell, 2u);
  EXPECT_EQ(bulb.type, Light::Type::Point);
  EXPECT_FLOAT_EQ(bulb.range, 0.0f);
  expect_near(bulb.color, {1, 1, 1});
  expect_near(bulb.position_world, {2, -0.2f, 2});
  expect_near(bulb.direction_world, {0, 0, -1});
  EXPECT_EQ(world_.cells[0].lights, (std::vector<uint32_t>{0}));
  EXPECT_EQ(world_.cells[2].lights, (std::vector<uint32_t>{1}));
}

TEST_F(ThreeRooms, TimelineIsReadFromSceneExtras) {
  ASSERT_EQ(world_.timelines.size(), 1u);
  const Timeline& walk = world_.timelines[0];
  EXPECT_EQ(walk.name, "walk");
  EXPECT_EQ(world_.find_timeline("walk"), 0);
  EXPECT_DOUBLE_EQ(walk.fps, 30.0);
  EXPECT_DOUBLE_EQ(walk.fov_y_deg, 60.0);
  EXPECT_DOUBLE_EQ(walk.aspect, 1.5);
  ASSERT_EQ(walk.keys.size(), 2u);
  EXPECT_DOUBLE_EQ(walk.keys[1].t, 2.0);
  expect_near(walk.keys[0].eye_world, {1, 1.6f, 2});
  expect_near(walk.keys[1].target_world, {8, 1.6f, 2});
}

// Every field that the three encodings must agree on, exactly (they carry identical bytes).
void expect_same_world(const World& a, const World& b) {
  ASSERT_EQ(a.cells.size(), b.cells.size());
  ASSERT_EQ(a.portals.size(), b.portals.size());
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  ASSERT_EQ(a.instances.size(), b.instances.size());
  ASSERT_EQ(a.groups.size(), b.groups.size());
  ASSERT_EQ(a.lights.size(), b.lights.size());
  ASSERT_EQ(a.timelines.size(), b.timelines.size());
  for (size_t i = 0; i < a.cells.size(); ++i) {
    EXPECT_EQ(a.cells[i].cell_to_world, b.cells[i].cell_to_world);
    EXPECT_EQ(a.cells[i].volume_triangles_cell, b.cells[i].volume_triangles_cell);
  }
  for (size_t i = 0; i < a.portals.size(); ++i) EXPECT_EQ(a.portals[i].polygon_world, b.portals[i].polygon_world);
  for (size_t i = 0; i < a.meshes.size(); ++i) {
    EXPECT_EQ(a.meshes[i].positions, b.meshes[i].positions);
    EXPECT_EQ(a.meshes[i].normals, b.meshes[i].normals);
    EXPECT_EQ(a.meshes[i].indices, b.meshes[i].indices);
  }
  for (size_t i = 0; i < a.instances.size(); ++i) EXPECT_EQ(a.instances[i].mesh_to_world, b.instances[i].mesh_to_world);
}

TEST(SceneEncodings, GltfDataUriExternalBinAndGlbGiveTheSameWorld) {
  World embedded, external, binary;
  ASSERT_TRUE(load_world(test::fixture("good/three_rooms.gltf"), embedded).ok());
  const Status s1 = load_world(test::fixture("good/three_rooms_external.gltf"), external);
  ASSERT_TRUE(s1.ok()) << s1.message();
  const Status s2 = load_world(test::fixture("good/three_rooms.glb"), binary);
  ASSERT_TRUE(s2.ok()) << s2.message();
  expect_same_world(embedded, external);
  expect_same_world(embedded, binary);
}

std::vector<uint8_t> read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(SceneFromMemory, EmbeddedBuffersNeedNoBaseDirectory) {
  const std::vector<uint8_t> bytes = read_bytes(test::fixture("good/three_rooms.glb"));
  World world;
  const Status s = load_world_from_memory(bytes.data(), bytes.size(), "memory.glb", "", world);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(world.source, "memory.glb");
  EXPECT_EQ(world.cells.size(), 3u);
}

TEST(SceneFromMemory, ExternalBufferIsRefusedWithoutBaseDirectoryAndFoundWithOne) {
  const std::vector<uint8_t> bytes = read_bytes(test::fixture("good/three_rooms_external.gltf"));
  World world;
  const Status refused = load_world_from_memory(bytes.data(), bytes.size(), "memory.gltf", "", world);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.message().find("memory.gltf: buffer 0: external buffer 'three_rooms_external.bin' cannot be "
                                   "resolved without a base directory"),
            std::string::npos)
      << refused.message();
  const Status found = load_world_from_memory(bytes.data(), bytes.size(), "memory.gltf", test::fixture("good"), world);
  ASSERT_TRUE(found.ok()) << found.message();
  EXPECT_EQ(world.portals.size(), 2u);
}

TEST(SceneLoadFailure, LeavesTheOutputWorldEmpty) {
  World world;
  ASSERT_TRUE(load_world(test::fixture("good/three_rooms.gltf"), world).ok());
  ASSERT_FALSE(world.cells.empty());
  std::vector<std::string> warnings;
  EXPECT_FALSE(load_world(test::fixture("bad/portal_not_convex.gltf"), world, &warnings).ok());
  EXPECT_TRUE(world.cells.empty());
  EXPECT_TRUE(world.meshes.empty());
  EXPECT_TRUE(world.portals.empty());
  EXPECT_TRUE(world.source.empty());
}

// Triangle strips and fans (glTF modes 5 and 6) are read as the triangles they stand for: the table
// stored as a strip (with a degenerate join at its end, dropped) and as a fan gives the same two
// triangles, each with the same winding (the same corners in the same cyclic order), as its list.
TEST(PrimitiveModes, StripAndFanGiveTheListsTriangles) {
  auto triangles = [](const World& world) {
    std::vector<std::array<uint32_t, 3>> out;
    for (const Mesh& mesh : world.meshes) {
      if (mesh.name != "Table") continue;
      for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        std::array<uint32_t, 3> tri{mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
        std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());  // same cycle, one form
        out.push_back(tri);
      }
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  World list;
  ASSERT_TRUE(load_world(test::fixture("good/three_rooms.gltf"), list).ok());
  const auto expected = triangles(list);
  ASSERT_EQ(expected.size(), 2u);
  for (const char* file : {"good/table_strip.gltf", "good/table_fan.gltf"}) {
    World world;
    std::vector<std::string> warnings;
    const Status s = load_world(test::fixture(file), world, &warnings);
    ASSERT_TRUE(s.ok()) << file << ": " << s.message();
    EXPECT_TRUE(warnings.empty()) << file << ": " << warnings.front();
    EXPECT_EQ(triangles(world), expected) << file;
  }
}

// Sparse accessors (core glTF): the table's corners given all four over zeros (no bufferView) or
// two of them over a dense part whose copies are wrong read as the plain table's corners.
TEST(SparseAccessors, ReplaceTheirElementsOverZerosOrADensePart) {
  auto table_positions = [](const World& world) {
    for (const Mesh& mesh : world.meshes)
      if (mesh.name == "Table") return mesh.positions;
    return std::vector<glm::vec3>{};
  };
  World plain;
  ASSERT_TRUE(load_world(test::fixture("good/three_rooms.gltf"), plain).ok());
  const std::vector<glm::vec3> expected = table_positions(plain);
  ASSERT_EQ(expected.size(), 4u);
  for (const char* file : {"good/table_sparse_zeros.gltf", "good/table_sparse_patch.gltf"}) {
    World world;
    const Status s = load_world(test::fixture(file), world);
    ASSERT_TRUE(s.ok()) << file << ": " << s.message();
    EXPECT_EQ(table_positions(world), expected) << file;
  }
}

}  // namespace
}  // namespace lintel
