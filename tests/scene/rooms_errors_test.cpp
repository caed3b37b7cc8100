// `lintel import rooms` on faulty inputs (docs/rooms.md, "Errors"): each must exit 2 with exactly
// one stderr line "lintel: error: <input>: node N '<name>': <fault>" and write no output file.
// The inputs are two box rooms joined by a door, each broken in one way.
#include "fixture_support.h"
#include "run_process.h"

#include <lintel/rooms_import.h>
#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>

namespace lintel {
namespace {

// A closed box mesh lo..hi (outward winding does not matter to the importer).
MeshDesc box(const std::string& name, glm::vec3 lo, glm::vec3 hi) {
  MeshDesc m;
  m.name = name;
  for (int c = 0; c < 8; ++c)
    m.positions.emplace_back((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
  m.indices = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
               2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  return m;
}

MeshDesc quad(const std::string& name, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
  MeshDesc m;
  m.name = name;
  m.positions = {a, b, c, d};
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

int add(SceneDesc& s, const std::string& name, MeshDesc mesh, glm::vec3 at = glm::vec3(0.0f)) {
  s.meshes.push_back(std::move(mesh));
  NodeDesc n;
  n.name = name;
  n.translation = at;
  n.mesh = int(s.meshes.size()) - 1;
  s.nodes.push_back(n);
  return int(s.nodes.size()) - 1;
}

// West x 0..4, East x 4..8 (z 0..4, y 0..3), a door in x = 4.
SceneDesc two_rooms() {
  SceneDesc s;
  add(s, "West-room", box("West", {0, 0, 0}, {4, 3, 4}));
  add(s, "East-room", box("East", {0, 0, 0}, {4, 3, 4}), {4, 0, 0});
  add(s, "Door-portal", quad("Door", {4, 0, 1.5f}, {4, 0, 2.5f}, {4, 2, 2.5f}, {4, 2, 1.5f}));
  return s;
}

struct ErrorCase {
  const char* name;
  std::function<void(SceneDesc&)> spoil;
  const char* element;  // the node the message must name
  const char* fault;    // a phrase it must contain
};

const ErrorCase kCases[] = {
    {"portal_touching_one_room",
     [](SceneDesc& s) {
       s.meshes[2] = quad("Door", {0, 0, 1.5f}, {0, 0, 2.5f}, {0, 2, 2.5f}, {0, 2, 1.5f});
     },
     "node 2 'Door-portal'", "portal touches only one room ('West')"},
    {"portal_touching_three_rooms",
     [](SceneDesc& s) {
       s.meshes[1] = box("East", {0, 0, 0}, {4, 3, 2});
       add(s, "North-room", box("North", {0, 0, 2}, {4, 3, 4}), {4, 0, 0});
     },
     "node 2 'Door-portal'", "portal touches 3 rooms ('West', 'East', 'North')"},
    {"rooms_overlapping",
     [](SceneDesc& s) {
       s.nodes[1].translation = {3, 0, 0};
     },
     "node 1 'East-room'", "room 'East' overlaps room 'West' (node 0 'West-room')"},
    {"l_shaped_room_without_bound",  // its convex hull swallows part of the notch East fills
     [](SceneDesc& s) {
       MeshDesc l_shape = box("West", {0, 0, 0}, {4, 3, 4});
       const MeshDesc arm = box("Arm", {4, 0, 2}, {8, 3, 4});
       const uint32_t base = uint32_t(l_shape.positions.size());
       l_shape.positions.insert(l_shape.positions.end(), arm.positions.begin(), arm.positions.end());
       for (uint32_t i : arm.indices) l_shape.indices.push_back(base + i);
       s.meshes[0] = l_shape;
       s.meshes[1] = box("East", {0, 0, 0}, {4, 3, 2});
     },
     "node 1 'East-room'", "room 'East' overlaps room 'West' (node 0 'West-room')"},
    {"portal_not_planar", [](SceneDesc& s) { s.meshes[2].positions[2].x += 0.3f; }, "node 2 'Door-portal'",
     "portal mesh is not planar: a vertex is"},
    {"no_rooms",
     [](SceneDesc& s) {
       s.nodes[0].name = "West";
       s.nodes[1].name = "East";
     },
     "", "no room: no node of the scene is named '<name>-room'"},
    {"bound_not_closed",
     [](SceneDesc& s) {
       MeshDesc open = box("WestBound", {0, 0, 0}, {4, 3, 4});
       open.indices.resize(open.indices.size() - 3);
       const int n = add(s, "West-bound", open);
       s.nodes[size_t(n)].parent = 0;
     },
     "node 3 'West-bound'", "bound mesh is not closed (3 open edges"},
    {"duplicate_room_names", [](SceneDesc& s) { s.nodes[1].name = "West-room"; }, "node 1 'West-room'",
     "duplicate room name 'West' (also node 0 'West-room')"},
};

class RoomsImportError : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(RoomsImportError, ExitsTwoWithOneLineNamingTheNodeAndWritesNothing) {
  const ErrorCase& c = GetParam();
  SceneDesc rooms = two_rooms();
  c.spoil(rooms);
  const std::string dir = test::scratch_dir(std::string("rooms_") + c.name);
  const std::string in = dir + "/in.glb", out = dir + "/out.glb";
  ASSERT_TRUE(save_scene(rooms, in).ok());
  const test::CliResult r = test::run_lintel({"import", "rooms", in, "-o", out});
  EXPECT_EQ(r.exit_code, 2);
  ASSERT_EQ(r.stderr_lines.size(), 1u) << test::joined(r.stderr_lines);
  const std::string prefix = "lintel: error: " + in + ": " + (*c.element ? std::string(c.element) + ": " : "");
  EXPECT_EQ(r.stderr_lines[0].rfind(prefix, 0), 0u) << r.stderr_lines[0];
  EXPECT_NE(r.stderr_lines[0].find(c.fault), std::string::npos) << r.stderr_lines[0];
  EXPECT_FALSE(std::filesystem::exists(out));
  // The library says the same.
  SceneDesc scene;
  const Status s = import_rooms(in, scene);
  EXPECT_FALSE(s.ok());
  EXPECT_EQ("lintel: error: " + s.message(), r.stderr_lines[0]);
  EXPECT_TRUE(scene.nodes.empty());
}

INSTANTIATE_TEST_SUITE_P(Inputs, RoomsImportError, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<ErrorCase>& p) { return std::string(p.param.name); });

// The unspoiled input imports (so each failure above is the spoiling's doing), and the CLI's
// whole path works: gen rooms-example -> import rooms -> validate -> export rooms -> import again.
TEST(RoomsImportCli, TwoRoomsAndTheExampleImportValidateAndExport) {
  const std::string dir = test::scratch_dir("rooms_cli");
  ASSERT_TRUE(save_scene(two_rooms(), dir + "/two.glb").ok());
  EXPECT_EQ(test::run_lintel({"import", "rooms", dir + "/two.glb", "-o", dir + "/two_scene.glb"}).exit_code, 0);
  EXPECT_EQ(test::run_lintel({"validate", dir + "/two_scene.glb"}).exit_code, 0);
  EXPECT_EQ(test::run_lintel({"gen", "rooms-example", "-o", dir + "/example.glb"}).exit_code, 0);
  const test::CliResult imported =
      test::run_lintel({"import", "rooms", dir + "/example.glb", "-o", dir + "/scene.glb"});
  EXPECT_EQ(imported.exit_code, 0) << test::joined(imported.stderr_lines);
  EXPECT_TRUE(imported.stderr_lines.empty()) << test::joined(imported.stderr_lines);
  EXPECT_EQ(test::run_lintel({"validate", dir + "/scene.glb"}).exit_code, 0);
  EXPECT_EQ(test::run_lintel({"vis", dir + "/scene.glb", "--eye", "2,1.6,1.5", "--target", "6,1.6,1.5"}).exit_code, 0);
  // The import adds a doorway walk through every room: it crosses portals and never flaps.
  const test::ProcessResult walk =
      test::run_process(test::lintel_bin() + " walk '" + dir + "/scene.glb' --timeline doorways");
  EXPECT_EQ(walk.exit_code, 0) << walk.err;
  EXPECT_NE(walk.out.find(" 0 flaps"), std::string::npos) << walk.out;
  EXPECT_EQ(walk.out.find(" 0 portal crossings"), std::string::npos) << walk.out;
  EXPECT_EQ(test::run_lintel({"export", "rooms", dir + "/scene.glb", "-o", dir + "/back.glb"}).exit_code, 0);
  EXPECT_EQ(test::run_lintel({"import", "rooms", dir + "/back.glb", "-o", dir + "/again.glb"}).exit_code, 0);
  World a, b;
  ASSERT_TRUE(load_world(dir + "/scene.glb", a).ok());
  ASSERT_TRUE(load_world(dir + "/again.glb", b).ok());
  EXPECT_EQ(a.cells.size(), b.cells.size());
  EXPECT_EQ(a.portals.size(), b.portals.size());
  EXPECT_EQ(a.instances.size(), b.instances.size());
}

}  // namespace
}  // namespace lintel
