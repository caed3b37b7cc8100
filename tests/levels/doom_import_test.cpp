// `import doom` on a WAD built here byte by byte: two rooms joined by a step (one BSP node), so the
// rules of docs/levels.md are checked without Freedoom; and the bad-input cases (truncated file,
// missing map, wrong lump sizes, indices out of range), each one line naming file, map and lump.
#include <lintel/doom_import.h>
#include <lintel/scene_io.h>

#include "walk_jumps.h"

#include <gtest/gtest.h>

#include <cstring>
#include <set>
#include <string>
#include <vector>

namespace lintel {
namespace {

struct Lump {
  std::string name;
  std::vector<uint8_t> data;
};

void put16(std::vector<uint8_t>& b, int v) {
  b.push_back(uint8_t(v & 0xff));
  b.push_back(uint8_t((v >> 8) & 0xff));
}
void put32(std::vector<uint8_t>& b, uint32_t v) {
  for (int i = 0; i < 4; ++i) b.push_back(uint8_t((v >> (8 * i)) & 0xff));
}
void put_name(std::vector<uint8_t>& b, const std::string& name) {
  for (size_t i = 0; i < 8; ++i) b.push_back(i < name.size() ? uint8_t(name[i]) : 0);
}

std::vector<uint8_t> wad_bytes(const std::vector<Lump>& lumps) {
  std::vector<uint8_t> body;
  std::vector<uint32_t> offsets;
  for (const Lump& l : lumps) {
    offsets.push_back(uint32_t(12 + body.size()));
    body.insert(body.end(), l.data.begin(), l.data.end());
  }
  std::vector<uint8_t> out = {'P', 'W', 'A', 'D'};
  put32(out, uint32_t(lumps.size()));
  put32(out, uint32_t(12 + body.size()));
  out.insert(out.end(), body.begin(), body.end());
  for (size_t i = 0; i < lumps.size(); ++i) {
    put32(out, offsets[i]);
    put32(out, uint32_t(lumps[i].data.size()));
    put_name(out, lumps[i].name);
  }
  return out;
}

// Two 64 x 64 rooms side by side: sector 0 (x 0..64, floor 0, ceiling 128) and sector 1 (x 64..128,
// floor 16, ceiling `east_ceiling`), joined by the two-sided line x = 64. Walls run with their
// room on the right (Doom's front side). One node splits along x = 64; a player start and an imp
// stand in room 0 and room 1. `switch_special` on room 0's west wall (x = 0) targets tag 1, which
// room 1 carries when `east_tag` is 1.
std::vector<Lump> two_rooms(int east_ceiling = 112, int east_floor = 16, int east_tag = 0, int switch_special = 0) {
  std::vector<Lump> lumps(11);
  lumps[0].name = "E1M1";
  const char* names[] = {"THINGS",   "LINEDEFS", "SIDEDEFS", "VERTEXES", "SEGS",
                         "SSECTORS", "NODES",    "SECTORS",  "REJECT",   "BLOCKMAP"};
  for (int i = 0; i < 10; ++i) lumps[size_t(i + 1)].name = names[i];
  auto& things = lumps[1].data;
  for (int v : {32, 32, 0, 1, 7}) put16(things, v);       // player 1 start in room 0
  for (int v : {96, 32, 180, 3001, 7}) put16(things, v);  // an imp in room 1
  auto& vertices = lumps[4].data;
  const int xy[6][2] = {{0, 0}, {64, 0}, {128, 0}, {128, 64}, {64, 64}, {0, 64}};
  for (const auto& v : xy) put16(vertices, v[0]), put16(vertices, v[1]);
  // v1, v2, front sidedef, back sidedef (-1: none), sector of the front side
  struct L {
    int v1, v2, front, back;
  };
  const L lines[7] = {{0, 5, 0, -1}, {5, 4, 1, -1}, {1, 0, 2, -1}, {4, 3, 3, -1},
                      {3, 2, 4, -1}, {2, 1, 5, -1}, {1, 4, 6, 7}};
  const int side_sector[8] = {0, 0, 0, 1, 1, 1, 1, 0};
  for (const L& l : lines) {
    const bool west_wall = &l == &lines[0];
    for (int v : {l.v1, l.v2, 0, west_wall ? switch_special : 0, west_wall && switch_special ? 1 : 0, l.front, l.back})
      put16(lumps[2].data, v);
  }
  for (int s : side_sector) {
    put16(lumps[3].data, 0), put16(lumps[3].data, 0);
    for (int k = 0; k < 3; ++k) put_name(lumps[3].data, "-");
    put16(lumps[3].data, s);
  }
  // Segs: subsector 0 = room 1 (right of the partition), subsector 1 = room 0.
  struct S {
    int v1, v2, line, reversed;
  };
  const S segs[8] = {{4, 3, 3, 0}, {3, 2, 4, 0}, {2, 1, 5, 0}, {1, 4, 6, 0},
                     {0, 5, 0, 0}, {5, 4, 1, 0}, {1, 0, 2, 0}, {4, 1, 6, 1}};
  for (const S& s : segs)
    for (int v : {s.v1, s.v2, 0, s.line, s.reversed, 0}) put16(lumps[5].data, v);
  for (int v : {4, 0, 4, 4}) put16(lumps[6].data, v);
  for (int v : {64, 0, 0, 64, 64, 0, 64, 128, 64, 0, 0, 64}) put16(lumps[7].data, v);
  put16(lumps[7].data, 0x8000);
  put16(lumps[7].data, 0x8001);
  auto sector = [&](int floor, int ceiling, int light, int tag) {
    put16(lumps[8].data, floor), put16(lumps[8].data, ceiling);
    put_name(lumps[8].data, "FLOOR0_1"), put_name(lumps[8].data, "CEIL1_1");
    put16(lumps[8].data, light), put16(lumps[8].data, 0), put16(lumps[8].data, tag);
  };
  sector(0, 128, 160, 0);
  sector(east_floor, east_ceiling, 255, east_tag);
  return lumps;
}

// A closed room whose only way out is a teleporter: room A (sector 0, x 0..64, the player start)
// and pad P (sector 1, x 64..128) share the line x = 64, whose front faces A, with `special` and
// tag 1; room B (sector 2, x 256..320, tag 1, ceiling `b_ceiling`) touches nothing and holds the
// teleport destination (thing type 14). Two nodes: x = 192 (B to its right), then x = 64.
std::vector<Lump> teleport_rooms(int special = 97, int b_ceiling = 128) {
  std::vector<Lump> lumps(11);
  lumps[0].name = "E1M1";
  const char* names[] = {"THINGS",   "LINEDEFS", "SIDEDEFS", "VERTEXES", "SEGS",
                         "SSECTORS", "NODES",    "SECTORS",  "REJECT",   "BLOCKMAP"};
  for (int i = 0; i < 10; ++i) lumps[size_t(i + 1)].name = names[i];
  for (int v : {32, 32, 0, 1, 7}) put16(lumps[1].data, v);     // player 1 start in A
  for (int v : {288, 32, 90, 14, 7}) put16(lumps[1].data, v);  // teleport destination in B
  const int xy[10][2] = {{0, 0},    {64, 0},  {64, 64}, {0, 64},   {128, 0},
                         {128, 64}, {256, 0}, {320, 0}, {320, 64}, {256, 64}};
  for (const auto& v : xy) put16(lumps[4].data, v[0]), put16(lumps[4].data, v[1]);
  struct L {
    int v1, v2, special, tag, front, back;
  };
  const L lines[11] = {{0, 3, 0, 0, 0, -1}, {3, 2, 0, 0, 1, -1},  {1, 0, 0, 0, 2, -1}, {2, 1, special, 1, 3, 4},
                       {2, 5, 0, 0, 5, -1}, {5, 4, 0, 0, 6, -1},  {4, 1, 0, 0, 7, -1}, {6, 9, 0, 0, 8, -1},
                       {9, 8, 0, 0, 9, -1}, {8, 7, 0, 0, 10, -1}, {7, 6, 0, 0, 11, -1}};
  for (const L& l : lines)
    for (int v : {l.v1, l.v2, 0, l.special, l.tag, l.front, l.back}) put16(lumps[2].data, v);
  for (int s : {0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2}) {
    put16(lumps[3].data, 0), put16(lumps[3].data, 0);
    for (int k = 0; k < 3; ++k) put_name(lumps[3].data, "-");
    put16(lumps[3].data, s);
  }
  // Subsector 0 = B, 1 = P, 2 = A, each a closed chain of segs.
  const int segs[12][4] = {{6, 9, 7, 0}, {9, 8, 8, 0}, {8, 7, 9, 0}, {7, 6, 10, 0}, {2, 5, 4, 0}, {5, 4, 5, 0},
                           {4, 1, 6, 0}, {1, 2, 3, 1}, {0, 3, 0, 0}, {3, 2, 1, 0},  {2, 1, 3, 0}, {1, 0, 2, 0}};
  for (const auto& sg : segs)
    for (int v : {sg[0], sg[1], 0, sg[2], sg[3], 0}) put16(lumps[5].data, v);
  for (int v : {4, 0, 4, 4, 4, 8}) put16(lumps[6].data, v);
  // Node 0: x = 64, P to the right, A to the left. Node 1 (root): x = 192, B to the right.
  for (int v : {64, 0, 0, 64, 64, 0, 64, 128, 64, 0, 0, 64, 0x8001, 0x8002}) put16(lumps[7].data, v);
  for (int v : {192, 0, 0, 64, 64, 0, 256, 320, 64, 0, 0, 128, 0x8000, 0}) put16(lumps[7].data, v);
  auto sector = [&](int floor, int ceiling, int tag) {
    put16(lumps[8].data, floor), put16(lumps[8].data, ceiling);
    put_name(lumps[8].data, "FLOOR0_1"), put_name(lumps[8].data, "CEIL1_1");
    put16(lumps[8].data, 160), put16(lumps[8].data, 0), put16(lumps[8].data, tag);
  };
  sector(0, 128, 0);
  sector(0, 128, 0);
  sector(0, b_ceiling, 1);
  return lumps;
}

Status import(const std::vector<Lump>& lumps, SceneDesc& scene, DoomImportStats* stats = nullptr,
              const std::string& map = "E1M1", DoomImportOptions options = {}) {
  return import_doom_from_memory(wad_bytes(lumps), "test.wad", map, options, scene, stats);
}

TEST(DoomImport, TwoRoomsBecomeTwoCellsOnePortalOverTheStepAndTheLoaderAcceptsThem) {
  SceneDesc scene;
  DoomImportStats stats;
  ASSERT_TRUE(import(two_rooms(), scene, &stats).ok());
  EXPECT_EQ(stats.cells, 2u);
  EXPECT_EQ(stats.portals, 1u);
  EXPECT_EQ(stats.instances, 1u);       // the imp; the player start is not drawn
  EXPECT_EQ(stats.lights, 1u);          // room 1 is bright (255)
  EXPECT_EQ(stats.walk_crossings, 5u);  // into room 1, then back and forth 4 times (no new sector)
  World world;
  std::vector<std::string> warnings;
  const Status loaded = build_world(scene, "two_rooms", world, &warnings);
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  ASSERT_EQ(world.portals.size(), 1u);
  const Portal& p = world.portals[0];
  // The open span is floor 16 .. ceiling 112 units at x = 64: Y from 0.5 m to 3.5 m, X = 2 m.
  for (const glm::vec3& v : p.polygon_world) {
    EXPECT_NEAR(v.x, 2.0, 1e-6);
    EXPECT_TRUE(std::fabs(v.y - 0.5f) < 1e-6 || std::fabs(v.y - 3.5f) < 1e-6) << v.y;
  }
  // Oriented from sector_1 (the line's front, to +X) into sector_0 (-X side).
  EXPECT_EQ(world.cells[p.from].name, "sector_1");
  EXPECT_LT(p.normal_world.x, -0.999f);
  ASSERT_EQ(world.instances.size(), 1u);
  EXPECT_EQ(world.cells[world.instances[0].cell].name, "sector_1");
  // Doom's y becomes -Z: the imp at map (96, 32) stands at (3, 0.5, -1) m, on room 1's floor.
  const glm::vec3 c = world.instances[0].bounds_world.center();
  EXPECT_NEAR(c.x, 3.0, 1e-4);
  EXPECT_NEAR(c.z, -1.0, 1e-4);
  EXPECT_NEAR(world.instances[0].bounds_world.min.y, 0.5, 1e-4);
  ASSERT_EQ(scene.timelines.size(), 1u);
  EXPECT_EQ(scene.timelines[0].name, "doorway");
  // The dim sky that stands for Doom's sector light away from the lamps, kept through the loader.
  ASSERT_TRUE(scene.environment.has_value());
  EXPECT_GT(world.environment.x, 0.0f);
  EXPECT_EQ(world.environment, *scene.environment);
}

// Property: Doom's light-source decorations glow and nothing else does: a floor lamp (type 2028)
// put beside the player start imports as a box whose mesh emits warm light (Mesh::emissive > 0,
// red >= blue) and its base colour's hue; the imp's mesh emits nothing.
TEST(DoomImport, LampsGlowAndMonstersDoNot) {
  std::vector<Lump> lumps = two_rooms();
  for (int v : {16, 48, 0, 2028, 7}) put16(lumps[1].data, v);  // a floor lamp in room 0
  SceneDesc scene;
  DoomImportStats stats;
  ASSERT_TRUE(import(lumps, scene, &stats).ok());
  EXPECT_EQ(stats.instances, 2u);
  World world;
  const Status loaded = build_world(scene, "two_rooms", world);
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  size_t glowing = 0, dark = 0;
  for (const Instance& instance : world.instances) {
    const Mesh& mesh = world.meshes[instance.mesh];
    if (mesh.name == "thing_type_2028") {
      ++glowing;
      EXPECT_GT(mesh.emissive.r, 0.0f);
      EXPECT_GE(mesh.emissive.r, mesh.emissive.b);
      EXPECT_EQ(world.cells[instance.cell].name, "sector_0");
    } else {
      ++dark;
      EXPECT_EQ(mesh.emissive, glm::vec3(0.0f)) << mesh.name;
    }
  }
  EXPECT_EQ(glowing, 1u);
  EXPECT_EQ(dark, 1u);
}

// The only way out of room A is the teleporter: the walk goes over it from its front side and
// jumps to the destination in room B (6.6 m away). The jump's two keys are 1 ms apart, no frame
// time falls between them, every frame's eye stands in a cell, and the tracker, re-locating by
// containment, ends in B without a flap.
TEST(DoomImport, TeleporterIsWalkedFromItsFrontToTheDestination) {
  SceneDesc scene;
  DoomImportStats stats;
  ASSERT_TRUE(import(teleport_rooms(), scene, &stats).ok());
  EXPECT_EQ(stats.cells, 3u);
  EXPECT_EQ(stats.portals, 1u);  // A | P
  EXPECT_EQ(stats.walk_teleports, 1u);
  EXPECT_EQ(stats.walk_crossings, 0u);  // crossed from its front, the line teleports: P is never entered by walking
  World world;
  const Status loaded = build_world(scene, "teleport_rooms", world);
  ASSERT_TRUE(loaded.ok()) << loaded.message();
  ASSERT_EQ(world.timelines.size(), 1u);
  const Timeline& walk = world.timelines[0];
  const std::vector<size_t> jumps = test::jump_keys(walk);
  ASSERT_EQ(jumps.size(), 1u);
  const TimelineKey& a = walk.keys[jumps[0]];
  const TimelineKey& b = walk.keys[jumps[0] + 1];
  EXPECT_NEAR(a.eye_world.x, 76.0 / 32.0, 1e-6);   // 12 units past the line, over the pad
  EXPECT_NEAR(b.eye_world.x, 288.0 / 32.0, 1e-6);  // at the destination
  EXPECT_NEAR(b.eye_world.z, -1.0, 1e-6);
  const test::JumpWalk w = test::walk_with_jumps(world, walk);
  EXPECT_EQ(w.jumps_not_1ms, 0u);
  EXPECT_EQ(w.frames_in_a_jump, 0u);
  EXPECT_EQ(w.jump_frames, 1u);
  EXPECT_EQ(w.eyes_outside_cells, 0u);
  EXPECT_EQ(w.flaps, 0u);
  EXPECT_EQ(w.sectors, (std::set<std::string>{"sector_0", "sector_1", "sector_2"}));
  // The last frame shows where the jump landed.
  EXPECT_NEAR(timeline_view(walk, walk.keys.front().t + double(w.frames - 1) / walk.fps).eye_world.x, 9.0, 1e-6);
}

// Monster-only teleporters (126) are plain lines to the player; a destination in a sector with
// no cell (B closed and no neighbour to open it as a door) is not followed, and the line, which
// would teleport in Doom, is not walked through either.
TEST(DoomImport, MonsterTeleporterIsALineAndADestinationWithoutACellIsSkipped) {
  {
    SceneDesc scene;
    DoomImportStats stats;
    ASSERT_TRUE(import(teleport_rooms(126), scene, &stats).ok());
    EXPECT_EQ(stats.walk_teleports, 0u);
    EXPECT_EQ(stats.walk_crossings, 5u);  // into P, then back and forth 4 times
    ASSERT_EQ(scene.timelines.size(), 1u);
    EXPECT_TRUE(test::jump_keys(scene.timelines[0]).empty());
    for (const TimelineKey& k : scene.timelines[0].keys) EXPECT_LT(k.eye_world.x, 4.0);  // never in B
  }
  {
    SceneDesc scene;
    DoomImportStats stats;
    ASSERT_TRUE(import(teleport_rooms(97, 0), scene, &stats).ok());
    EXPECT_EQ(stats.cells, 2u);
    EXPECT_EQ(stats.walk_teleports, 0u);
    EXPECT_EQ(stats.walk_crossings, 0u);
    ASSERT_EQ(scene.timelines.size(), 1u);
    EXPECT_EQ(scene.timelines[0].keys.size(), 2u);  // the one-frame walk of a closed start
  }
}

// A closed sector (ceiling == floor) is a door: opened to the lowest neighbouring ceiling minus 4
// units; with --doors closed its portal is written with open: false.
TEST(DoomImport, ClosedSectorIsADoorOpenedOrMarkedClosed) {
  for (bool open : {true, false}) {
    SceneDesc scene;
    DoomImportStats stats;
    DoomImportOptions options;
    options.doors_open = open;
    ASSERT_TRUE(import(two_rooms(16), scene, &stats, "e1m1", options).ok());
    EXPECT_EQ(stats.doors, 1u);
    ASSERT_EQ(stats.portals, 1u);
    for (const NodeDesc& n : scene.nodes)
      if (n.kind == NodeDesc::Kind::Portal) {
        EXPECT_EQ(n.portal_open, open);
        float top = 0.0f;
        for (const glm::vec3& v : scene.meshes[size_t(n.mesh)].positions) top = std::max(top, v.y);
        EXPECT_NEAR(top, (128.0 - 4.0) / 32.0, 1e-6);
      }
  }
}

// Room 1 raised to room 0's ceiling (floor 128, ceiling 256) is sealed: no opening joins it to
// anything. A switch that lowers it to the lowest floor around (special 23, tag 1), a lift (88)
// or a lowering to the highest floor around (19) makes it a platform imported lowered, to floor 0:
// the portal spans 0..128 units. Without the switch it stays sealed (no portal), and a room that
// is not sealed keeps its height whatever targets it.
TEST(DoomImport, SealedPlatformThatALineLowersIsImportedLowered) {
  struct Case {
    int floor, special;
    uint32_t lowered, portals;
    double portal_bottom;  // map units
  };
  for (const Case& c : {Case{128, 23, 1, 1, 0.0}, Case{128, 0, 0, 0, 0.0}, Case{16, 23, 0, 1, 16.0},
                        Case{128, 88, 1, 1, 0.0}, Case{128, 19, 1, 1, 0.0}}) {
    SCOPED_TRACE("floor " + std::to_string(c.floor) + ", special " + std::to_string(c.special));
    SceneDesc scene;
    DoomImportStats stats;
    ASSERT_TRUE(import(two_rooms(256, c.floor, 1, c.special), scene, &stats).ok());
    EXPECT_EQ(stats.lowered_floors, c.lowered);
    EXPECT_EQ(stats.portals, c.portals);
    for (const NodeDesc& n : scene.nodes)
      if (n.kind == NodeDesc::Kind::Portal) {
        float bottom = 1e9f;
        for (const glm::vec3& v : scene.meshes[size_t(n.mesh)].positions) bottom = std::min(bottom, v.y);
        EXPECT_NEAR(bottom, c.portal_bottom / 32.0, 1e-6);
      }
  }
}

void expect_error(const Status& s, const std::vector<std::string>& parts) {
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.kind(), StatusKind::BadInput);
  EXPECT_EQ(s.message().find('\n'), std::string::npos) << s.message();
  for (const std::string& part : parts) EXPECT_NE(s.message().find(part), std::string::npos) << s.message();
}

TEST(DoomImportBadInput, TruncatedWadNamesTheDirectory) {
  std::vector<uint8_t> bytes = wad_bytes(two_rooms());
  bytes.resize(bytes.size() - 20);
  SceneDesc scene;
  expect_error(import_doom_from_memory(bytes, "test.wad", "E1M1", {}, scene), {"test.wad", "directory", "truncated"});
  bytes.resize(6);
  expect_error(import_doom_from_memory(bytes, "test.wad", "E1M1", {}, scene), {"test.wad", "header"});
  EXPECT_TRUE(scene.nodes.empty());
}

TEST(DoomImportBadInput, NotAWadAndMissingMapAndMissingLump) {
  std::vector<uint8_t> bytes = wad_bytes(two_rooms());
  bytes[0] = 'X';
  SceneDesc scene;
  expect_error(import_doom_from_memory(bytes, "test.wad", "E1M1", {}, scene), {"test.wad", "not a WAD"});
  expect_error(import(two_rooms(), scene, nullptr, "E1M9"), {"test.wad", "map 'E1M9' not found"});
  std::vector<Lump> no_nodes = two_rooms();
  no_nodes.erase(no_nodes.begin() + 7);
  expect_error(import(no_nodes, scene, nullptr), {"test.wad", "map E1M1", "lump NODES missing"});
  EXPECT_EQ(import_doom("/nonexistent/x.wad", "E1M1", {}, scene).kind(), StatusKind::BadInput);
}

// Maps of the same family in formats this reader does not parse are named, not misread: Hexen
// (a BEHAVIOR lump after BLOCKMAP), UDMF (TEXTMAP right after the marker), ZDoom's extended or
// compressed nodes (NODES starting with XNOD, ZNOD, ...).
TEST(DoomImportBadInput, OtherMapFormatsAreNamed) {
  SceneDesc scene;
  std::vector<Lump> hexen = two_rooms();
  hexen.push_back({"BEHAVIOR", {'A', 'C', 'S', 0}});
  expect_error(import(hexen, scene), {"test.wad", "map E1M1", "Hexen-format map (lump BEHAVIOR)"});
  std::vector<Lump> udmf = {{"E1M1", {}}, {"TEXTMAP", {'n', 'a', 'm', 'e'}}, {"ENDMAP", {}}};
  expect_error(import(udmf, scene), {"test.wad", "map E1M1", "UDMF map (lump TEXTMAP)"});
  for (const char* signature : {"XNOD", "ZNOD", "ZGL3"}) {
    std::vector<Lump> zdoom = two_rooms();
    std::copy(signature, signature + 4, zdoom[7].data.begin());
    expect_error(import(zdoom, scene), {"test.wad", "map E1M1", "lump NODES", std::string("ZDoom ") + signature});
  }
}

TEST(DoomImportBadInput, WrongLumpSizesNameTheLump) {
  for (size_t lump : {1u, 2u, 3u, 4u, 5u, 6u, 7u, 8u}) {
    std::vector<Lump> lumps = two_rooms();
    lumps[lump].data.push_back(0);
    SceneDesc scene;
    expect_error(import(lumps, scene), {"test.wad", "map E1M1", "lump " + lumps[lump].name, "not a multiple"});
  }
}

TEST(DoomImportBadInput, IndicesOutOfRangeNameTheRecord) {
  std::vector<Lump> lumps = two_rooms();
  lumps[2].data[0] = 99;  // linedef 0's first vertex
  SceneDesc scene;
  expect_error(import(lumps, scene), {"lump LINEDEFS", "linedef 0", "vertex 99 out of range"});
  lumps = two_rooms();
  lumps[3].data[28] = 7;  // sidedef 0's sector
  expect_error(import(lumps, scene), {"lump SIDEDEFS", "sidedef 0", "sector 7 out of range"});
  lumps = two_rooms();
  lumps[7].data[24] = 5;  // the node's right child: subsector 5 (bit 15 kept)
  expect_error(import(lumps, scene), {"lump NODES", "node 0"});
}

}  // namespace
}  // namespace lintel
