// Vertex colours (glTF COLOR_0): real files colour whole models this way (low-poly and voxel
// exports, scanned meshes, baked lighting), and the loader used to ignore the attribute, so such
// a file rendered white: a silent wrong picture. COLOR_0 now loads into Mesh::colors (linear RGBA,
// one per position), multiplying the base colour in the renderer, the GI surfels and the path
// tracer, and the writers keep it. Fixture good/vertex_colors.gltf: the three-room scene with the
// Table's colours as normalized bytes (VEC4), the Chair's as floats (VEC3) and a rug primitive of
// the room shell's as normalized shorts (VEC3) beside a primitive without COLOR_0
// (tests/scene/fixtures/make_fixtures.py: TABLE_COLORS_U8, CHAIR_COLOR, RUG_COLOR_U16).
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

// The colours the fixture stores, decoded as glTF 2.0 defines normalized integers.
std::vector<glm::vec4> table_colors() {
  const int bytes[4][4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 255, 51}};
  std::vector<glm::vec4> out;
  for (const auto& c : bytes) out.emplace_back(c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f, c[3] / 255.0f);
  return out;
}
const glm::vec4 kChair(0.25f, 0.5f, 1.0f, 1.0f);
const glm::vec4 kRug(1.0f, 32768.0f / 65535.0f, 0.0f, 1.0f);

// Property: every form glTF allows for COLOR_0 (normalized unsigned bytes and shorts, floats; VEC3
// and VEC4) loads as the colour it encodes, one per position, alpha 1 for VEC3; a primitive
// without COLOR_0 in a mesh whose other primitive has it is white; a mesh without any has none
// (it draws as before).
TEST(VertexColor, EveryFormLoadsAsTheColourItEncodes) {
  World world;
  const Status s = load_world(test::fixture("good/vertex_colors.gltf"), world);
  ASSERT_TRUE(s.ok()) << s.message();

  const Mesh& table = mesh_named(world, "Table");
  EXPECT_EQ(table.colors, table_colors());

  const Mesh& chair = mesh_named(world, "Chair");
  ASSERT_EQ(chair.colors.size(), chair.positions.size());
  for (const glm::vec4& c : chair.colors) EXPECT_EQ(c, kChair);

  // The shell: the box's 8 corners (no COLOR_0: white), then the rug's 4.
  const Mesh& shell = mesh_named(world, "RoomShell");
  ASSERT_EQ(shell.positions.size(), 12u);
  ASSERT_EQ(shell.colors.size(), 12u);
  for (size_t v = 0; v < 8; ++v) EXPECT_EQ(shell.colors[v], glm::vec4(1.0f)) << v;
  for (size_t v = 8; v < 12; ++v) EXPECT_EQ(shell.colors[v], kRug) << v;

  EXPECT_TRUE(mesh_named(world, "KitchenShell").colors.empty());

  World plain;
  ASSERT_TRUE(load_world(test::fixture("good/three_rooms.gltf"), plain).ok());
  for (const Mesh& mesh : plain.meshes) EXPECT_TRUE(mesh.colors.empty()) << mesh.name;
}

// Property: the writers keep the colours: optimize's scene, written to GLB and loaded again, has
// the same colours on the same vertices (floats, so exactly the decoded values).
TEST(VertexColor, WrittenSceneLoadsWithTheSameColours) {
  World world;
  ASSERT_TRUE(load_world(test::fixture("good/vertex_colors.gltf"), world).ok());
  const OptimizeOptions keep = test::nothing_merges();
  SceneDesc written;
  ASSERT_TRUE(optimize_world(world, keep, written).ok());
  std::vector<uint8_t> glb;
  ASSERT_TRUE(scene_to_glb(written, glb).ok());
  World back;
  const Status s = load_world_from_memory(glb.data(), glb.size(), "written.glb", "", back);
  ASSERT_TRUE(s.ok()) << s.message();
  for (const char* name : {"Table", "Chair"}) {
    SCOPED_TRACE(name);
    EXPECT_EQ(mesh_named(back, name).colors, mesh_named(world, name).colors);
  }
  // No colours written where there were none (the file stays as it was before COLOR_0).
  EXPECT_TRUE(mesh_named(back, "KitchenShell").colors.empty());
  std::vector<uint8_t> plain_glb;
  World plain;
  ASSERT_TRUE(load_world(test::fixture("good/three_rooms.gltf"), plain).ok());
  SceneDesc plain_written;
  ASSERT_TRUE(optimize_world(plain, keep, plain_written).ok());
  ASSERT_TRUE(scene_to_glb(plain_written, plain_glb).ok());
  const std::string text(plain_glb.begin(), plain_glb.end());
  EXPECT_EQ(text.find("COLOR_0"), std::string::npos);
}

// Property: cells merged by optimize keep each part's looks: three stair steps of three colours
// (as Doom's light levels tint sectors), one with vertex colours, merge into one shell whose
// vertices carry each step's base colour times its own vertex colour (white where it had none),
// under a white base colour. Before vertex colours, the merged shell took the largest step's
// colour and the others' were lost.
TEST(VertexColor, MergedCellKeepsEachPartsColours) {
  const glm::vec4 tints[3] = {{0.9f, 0.2f, 0.2f, 1.0f}, {0.2f, 0.9f, 0.2f, 1.0f}, {0.2f, 0.2f, 0.9f, 1.0f}};
  SceneDesc scene;
  for (int k = 0; k < 3; ++k) {
    const std::string name = "s" + std::to_string(k);
    const glm::vec3 lo(float(k), 0.2f * float(k), 0.0f), hi(float(k + 1), 3.0f, 2.0f);
    MeshDesc shell = test::box_mesh(name, lo, hi);
    shell.base_color = tints[k];
    if (k == 1)
      for (size_t v = 0; v < shell.positions.size(); ++v)
        shell.colors.emplace_back(v % 2 ? 0.5f : 1.0f, 1.0f, 1.0f, 1.0f);
    test::add_box_cell(scene, name, lo, hi, shell);
  }
  test::add_portal(scene, "p01", "s0", "s1", 1, 0, 2, 0.2f, 3);
  test::add_portal(scene, "p12", "s1", "s2", 2, 0, 2, 0.4f, 3);
  World before;
  ASSERT_TRUE(build_world(scene, "steps", before).ok());
  SceneDesc merged;
  OptimizeReport report;
  ASSERT_TRUE(optimize_world(before, {}, merged, &report).ok());
  ASSERT_EQ(report.cells_after, 1u);
  World after;
  ASSERT_TRUE(build_world(merged, "merged", after).ok());
  const Mesh& shell = after.meshes[size_t(after.cells[0].shell_mesh)];
  EXPECT_EQ(shell.base_color, glm::vec4(1.0f));
  ASSERT_EQ(shell.positions.size(), 24u);
  ASSERT_EQ(shell.colors.size(), 24u);
  for (size_t k = 0; k < 3; ++k)
    for (size_t v = 0; v < 8; ++v) {
      const glm::vec4 own = k == 1 ? before.meshes[size_t(before.cells[1].shell_mesh)].colors[v] : glm::vec4(1.0f);
      EXPECT_EQ(shell.colors[8 * k + v], tints[k] * own) << "step " << k << " vertex " << v;
    }
}

}  // namespace
}  // namespace lintel
