// The rooms convention both ways (docs/rooms.md): the generator's example imports into the house it
// draws (rooms, links, one-way direction, bound, instances, lights), and a World exported in the
// convention and imported back is the same world (cells, portals, instances, meshes, volumes) for
// the example, the cottage and a random building with arbitrary cell frames.
#include "fixture_support.h"

#include <lintel/rooms_import.h>
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <tuple>

namespace lintel {
namespace {

// SceneDesc (rooms convention) -> GLB -> import_rooms -> load: the World a user gets.
World import_via_glb(const SceneDesc& rooms, std::vector<std::string>* warnings = nullptr) {
  std::vector<uint8_t> glb;
  EXPECT_TRUE(scene_to_glb(rooms, glb).ok());
  SceneDesc scene;
  const Status s = import_rooms_from_memory(glb.data(), glb.size(), "rooms.glb", "", scene, warnings);
  EXPECT_TRUE(s.ok()) << s.message();
  World world;
  const Status loaded = build_world(scene, "imported.glb", world);
  EXPECT_TRUE(loaded.ok()) << loaded.message();
  return world;
}

World export_and_import(const World& world) {
  SceneDesc rooms;
  const Status s = export_rooms(world, rooms);
  EXPECT_TRUE(s.ok()) << s.message();
  for (const NodeDesc& node : rooms.nodes) EXPECT_EQ(node.kind, NodeDesc::Kind::Plain) << node.name;  // plain glTF
  return import_via_glb(rooms);
}

double scale_of(const World& w) {
  double s = 1.0;
  for (const Cell& c : w.cells)
    s = std::max({s, double(glm::length(c.volume_box_cell.max)), double(glm::length(glm::vec3(c.cell_to_world[3])))});
  return s;
}

bool near(const glm::vec3& a, const glm::vec3& b, double tol) { return glm::length(a - b) <= tol; }

// The mesh a World's instance or shell draws, as comparable data.
using MeshKey = std::tuple<std::string, std::vector<float>, std::vector<uint32_t>>;
MeshKey key_of(const Mesh& m) {
  std::vector<float> p;
  for (const glm::vec3& v : m.positions) p.insert(p.end(), {v.x, v.y, v.z});
  return {m.name, p, m.indices};
}

// Same cells by name (shell mesh, volume box, instances and lights), portals by name (cells,
// direction, polygon), and the same set of drawn meshes. Positions within `tol` metres.
void expect_same_world(const World& a, const World& b) {
  const double tol = 1e-5 * scale_of(a);
  ASSERT_EQ(a.cells.size(), b.cells.size());
  std::vector<MeshKey> meshes_a, meshes_b;
  for (const Mesh& m : a.meshes) meshes_a.push_back(key_of(m));
  for (const Mesh& m : b.meshes) meshes_b.push_back(key_of(m));
  std::sort(meshes_a.begin(), meshes_a.end());
  std::sort(meshes_b.begin(), meshes_b.end());
  EXPECT_TRUE(meshes_a == meshes_b) << "drawn meshes differ";
  for (const Cell& ca : a.cells) {
    const int j = b.find_cell(ca.name);
    ASSERT_GE(j, 0) << ca.name;
    const Cell& cb = b.cells[size_t(j)];
    EXPECT_EQ(ca.shell_mesh < 0, cb.shell_mesh < 0) << ca.name;
    if (ca.shell_mesh >= 0 && cb.shell_mesh >= 0) {
      EXPECT_TRUE(key_of(a.meshes[size_t(ca.shell_mesh)]) == key_of(b.meshes[size_t(cb.shell_mesh)])) << ca.name;
    }
    for (const glm::vec3& corner : {ca.volume_box_cell.min, ca.volume_box_cell.max}) {
      const glm::vec3 world_a = glm::vec3(ca.cell_to_world * glm::vec4(corner, 1.0f));
      const glm::vec3 corner_b = corner == ca.volume_box_cell.min ? cb.volume_box_cell.min : cb.volume_box_cell.max;
      EXPECT_TRUE(near(world_a, glm::vec3(cb.cell_to_world * glm::vec4(corner_b, 1.0f)), tol)) << ca.name << " volume";
    }
    ASSERT_EQ(ca.instances.size(), cb.instances.size()) << ca.name;
    std::map<std::string, std::vector<const Instance*>> by_name;
    for (uint32_t i : cb.instances) by_name[b.instances[i].name].push_back(&b.instances[i]);
    for (uint32_t i : ca.instances) {
      const Instance& ia = a.instances[i];
      bool found = false;
      for (const Instance* ib : by_name[ia.name]) {
        if (key_of(a.meshes[ia.mesh]) != key_of(b.meshes[ib->mesh])) continue;
        bool same = true;
        for (int c = 0; c < 4; ++c)
          same = same && near(glm::vec3(ia.mesh_to_world[c]), glm::vec3(ib->mesh_to_world[c]), tol);
        found = found || same;
      }
      EXPECT_TRUE(found) << ca.name << ": instance '" << ia.name << "' has no twin";
    }
    ASSERT_EQ(ca.lights.size(), cb.lights.size()) << ca.name;
    for (size_t k = 0; k < ca.lights.size(); ++k) {
      const Light& la = a.lights[ca.lights[k]];
      const Light& lb = b.lights[cb.lights[k]];
      EXPECT_EQ(la.name, lb.name);
      EXPECT_TRUE(near(la.position_world, lb.position_world, tol)) << la.name;
      EXPECT_TRUE(near(la.direction_world, lb.direction_world, 1e-5)) << la.name;
      EXPECT_EQ(la.intensity, lb.intensity);
    }
  }
  ASSERT_EQ(a.portals.size(), b.portals.size());
  for (const Portal& pa : a.portals) {
    const auto it =
        std::find_if(b.portals.begin(), b.portals.end(), [&](const Portal& p) { return p.name == pa.name; });
    ASSERT_NE(it, b.portals.end()) << pa.name;
    EXPECT_EQ(a.cells[pa.from].name, b.cells[it->from].name) << pa.name;
    EXPECT_EQ(a.cells[pa.to].name, b.cells[it->to].name) << pa.name;
    EXPECT_EQ(pa.two_way, it->two_way) << pa.name;
    EXPECT_EQ(pa.link, it->link) << pa.name << ": a mirror comes back as a mirror (-mirror)";
    EXPECT_GT(glm::dot(pa.normal_world, it->normal_world), 0.9999f) << pa.name;
    ASSERT_EQ(pa.polygon_world.size(), it->polygon_world.size()) << pa.name;
    for (const glm::vec3& v : pa.polygon_world)
      EXPECT_TRUE(std::any_of(it->polygon_world.begin(), it->polygon_world.end(), [&](const glm::vec3& w) {
        return near(v, w, tol);
      })) << pa.name;
  }
}

// A mirror must face exactly one room: one hung in the air far above the house faces none, and
// the import says so on one line naming the node.
TEST(RoomsImport, AMirrorFacingNoRoomIsRefused) {
  World cottage;
  ASSERT_TRUE(build_world(generate_cottage({}), "cottage", cottage).ok());
  SceneDesc rooms;
  ASSERT_TRUE(export_rooms(cottage, rooms).ok());
  bool moved = false;
  for (NodeDesc& node : rooms.nodes) {
    if (node.name != std::string("study_mirror") + kMirrorSuffix) continue;
    for (glm::vec3& p : rooms.meshes[size_t(node.mesh)].positions) p.y += 100.0f;
    moved = true;
  }
  ASSERT_TRUE(moved) << "the cottage's mirror is exported as <name>-mirror";
  std::vector<uint8_t> glb;
  ASSERT_TRUE(scene_to_glb(rooms, glb).ok());
  SceneDesc scene;
  const Status s = import_rooms_from_memory(glb.data(), glb.size(), "rooms.glb", "", scene, nullptr);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("study_mirror-mirror"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("mirror faces no room"), std::string::npos) << s.message();
}

// A teleport has no place in the rooms convention: export refuses it rather than drop it.
TEST(RoomsExport, ATeleportIsRefused) {
  World teleport;
  ASSERT_TRUE(build_world(generate_teleport({4}), "teleport", teleport).ok());
  SceneDesc rooms;
  const Status s = export_rooms(teleport, rooms);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("is a teleport"), std::string::npos) << s.message();
}

TEST(RoomsImport, ExampleBecomesTheHouseItDraws) {
  std::vector<std::string> warnings;
  const World w = import_via_glb(generate_rooms_example(), &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  ASSERT_EQ(w.cells.size(), 4u);
  for (const char* name : {"Hall", "Kitchen", "Living", "Garden"}) EXPECT_GE(w.find_cell(name), 0) << name;
  const auto cell = [&](const char* name) { return w.cells[size_t(w.find_cell(name))]; };
  // Living's volume is its -bound (the L prism: 7 walls and a 5-triangle fan below and above);
  // the others' the convex hull of their shells, boxes here.
  EXPECT_EQ(cell("Living").volume_triangles_cell.size(), 3u * (14u + 10u));
  EXPECT_FALSE(cell("Hall").volume_triangles_cell.empty());
  for (const char* name : {"Hall", "Kitchen", "Garden"}) {
    const Cell& c = cell(name);
    const Mesh& shell = w.meshes[size_t(c.shell_mesh)];
    EXPECT_EQ(c.volume_box_cell.min, shell.bounds_mesh.min) << name;
    EXPECT_EQ(c.volume_box_cell.max, shell.bounds_mesh.max) << name;
  }
  EXPECT_EQ(cell("Hall").instances.size(), 1u);
  EXPECT_EQ(cell("Kitchen").instances.size(), 3u);
  EXPECT_EQ(cell("Living").instances.size(), 1u);
  EXPECT_EQ(cell("Garden").instances.size(), 1u);
  EXPECT_EQ(w.lights.size(), 2u);
  ASSERT_EQ(w.portals.size(), 4u);
  std::map<std::string, std::pair<std::string, std::string>> links;
  for (const Portal& p : w.portals) {
    links[p.name] = {w.cells[p.from].name, w.cells[p.to].name};
    EXPECT_EQ(p.two_way, p.name != "HallWindow") << p.name;
  }
  const auto joins = [&](const std::string& portal, const std::string& x, const std::string& y) {
    const auto& l = links[portal];
    return (l.first == x && l.second == y) || (l.first == y && l.second == x);
  };
  EXPECT_TRUE(joins("HallKitchen", "Hall", "Kitchen"));
  EXPECT_TRUE(joins("HallLiving", "Hall", "Living"));
  EXPECT_TRUE(joins("KitchenLiving", "Kitchen", "Living"));
  // The one-way window looks along its face normal (-X): from the hall out into the garden.
  EXPECT_EQ(links["HallWindow"].first, "Hall");
  EXPECT_EQ(links["HallWindow"].second, "Garden");
  // The doorway walk visits every room reachable through two-way portals (all but the garden).
  ASSERT_EQ(w.timelines.size(), 1u);
  EXPECT_EQ(w.timelines[0].name, "doorways");
  // Depth first from Hall: Hall -> Kitchen -> Living (HallLiving then leads to a seen room), and
  // back: 4 crossings of 2 keys each, the turn in Living is one key: 7.
  EXPECT_EQ(w.timelines[0].keys.size(), 7u);
  // Garden sees nothing back through it: only Hall links the window.
  for (const PortalLink& link : cell("Garden").links) EXPECT_NE(w.portals[link.portal].name, "HallWindow");
}

TEST(RoomsImport, StrayMeshAndLightOutsideRoomsAreWarnedAndDropped) {
  SceneDesc rooms = generate_rooms_example();
  NodeDesc stray;
  stray.name = "ReferenceBlock";
  stray.mesh = 0;
  stray.translation = {30.0f, 0.0f, 30.0f};
  rooms.nodes.push_back(stray);
  NodeDesc sun;
  sun.name = "Sun";
  sun.light = 0;
  rooms.nodes.push_back(sun);
  std::vector<std::string> warnings;
  const World w = import_via_glb(rooms, &warnings);
  ASSERT_EQ(warnings.size(), 2u);
  const std::string stray_node = "node " + std::to_string(rooms.nodes.size() - 2) + " 'ReferenceBlock'";
  EXPECT_EQ(warnings[0], "rooms.glb: " + stray_node + ": mesh node outside any room and not a portal (ignored)");
  EXPECT_NE(warnings[1].find("'Sun': light outside any room (ignored)"), std::string::npos) << warnings[1];
  EXPECT_EQ(w.instances.size(), 6u);
  EXPECT_EQ(w.lights.size(), 2u);
}

TEST(RoomsImport, OneWayDirectionFollowsTheWinding) {
  // Reversing the window's triangles must reverse the one-way direction (garden -> hall).
  SceneDesc rooms = generate_rooms_example();
  for (const NodeDesc& node : rooms.nodes)
    if (node.name == "HallWindow-portal-oneway") {
      std::vector<uint32_t>& idx = rooms.meshes[size_t(node.mesh)].indices;
      for (size_t i = 0; i + 2 < idx.size(); i += 3) std::swap(idx[i + 1], idx[i + 2]);
    }
  const World w = import_via_glb(rooms);
  const auto it =
      std::find_if(w.portals.begin(), w.portals.end(), [](const Portal& p) { return p.name == "HallWindow"; });
  ASSERT_NE(it, w.portals.end());
  EXPECT_EQ(w.cells[it->from].name, "Garden");
  EXPECT_EQ(w.cells[it->to].name, "Hall");
}

TEST(RoomsRoundTrip, ExampleExportedAndImportedIsTheSameWorld) {
  const World first = import_via_glb(generate_rooms_example());
  expect_same_world(first, export_and_import(first));
}

TEST(RoomsRoundTrip, CottageExportedAndImportedIsTheSameWorld) {
  World cottage;
  ASSERT_TRUE(build_world(generate_cottage({}), "cottage", cottage).ok());
  expect_same_world(cottage, export_and_import(cottage));
}

TEST(RoomsRoundTrip, TexturedSceneKeepsItsTexturesSamplersAndOneWayPortal) {
  World textured;
  ASSERT_TRUE(load_world(test::fixture("good/textured_table_data_uri_image.gltf"), textured).ok());
  ASSERT_FALSE(textured.textures.empty());
  // A glTF sampler is plain glTF: it goes out and comes back in.
  using S = TextureSampler;
  const S sampler{S::Wrap::ClampToEdge, S::Wrap::MirroredRepeat, S::Filter::Nearest, S::Filter::Linear,
                  S::MipMode::Nearest};
  for (Mesh& m : textured.meshes)
    if (m.base_color_texture >= 0) m.base_color_sampler = sampler;
  const World back = export_and_import(textured);
  expect_same_world(textured, back);
  ASSERT_EQ(back.textures.size(), textured.textures.size());
  for (size_t i = 0; i < textured.textures.size(); ++i)
    EXPECT_TRUE(back.textures[i].rgba8 == textured.textures[i].rgba8);
  for (const Mesh& m : back.meshes)
    if (m.base_color_texture >= 0) {
      EXPECT_FALSE(m.uvs.empty()) << m.name;
      EXPECT_EQ(m.base_color_sampler.wrap_s, sampler.wrap_s) << m.name;
      EXPECT_EQ(m.base_color_sampler.wrap_t, sampler.wrap_t) << m.name;
      EXPECT_EQ(m.base_color_sampler.mag, sampler.mag) << m.name;
      EXPECT_EQ(m.base_color_sampler.min, sampler.min) << m.name;
      EXPECT_EQ(m.base_color_sampler.mip, sampler.mip) << m.name;
    }
}

// Every cell with a volume mesh: a shell box in a frame turned against its room overlaps the
// neighbours, which the scene format allows and the rooms convention refuses (docs/rooms.md).
TEST(RoomsRoundTrip, RandomBuildingsWithArbitraryFramesSurvive) {
  for (uint64_t seed = 1; seed <= 4; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    RandomOptions options;
    options.cells = 24;
    options.seed = seed;
    options.volume_fraction = 1.0;
    World building;
    ASSERT_TRUE(build_world(generate_random(options), "random", building).ok());
    expect_same_world(building, export_and_import(building));
  }
}

}  // namespace
}  // namespace lintel
