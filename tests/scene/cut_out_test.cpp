// Cut-outs (glTF alphaMode MASK): leaves, fences, grates and railings are quads whose texture's
// alpha says where the surface is. The loader used to read alphaMode only to warn that it was
// drawn opaque; now MASK and alphaCutoff load into Mesh::alpha_mode / alpha_cutoff, the writer
// keeps them, and optimize never merges a cut-out with a shell of another alpha mode, cutoff or
// base alpha (the merged shell has one of each). What the renderers do with them is tested in
// tests/render (sidedness_test: the albedo pass against the path tracer's ray cast) and
// tests/pathtrace.
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

// Property: a cut-out as another tool writes it (good/cut_out_table.gltf, by make_fixtures.py: the
// Table's material MASK with alphaCutoff 0.4 over a 2x2 PNG whose black texels have alpha 0)
// loads as a Mask mesh with that cutoff and the texels' alpha as stored; every other mesh stays
// Opaque, and nothing warns.
TEST(CutOut, FileFromAnotherWriterLoadsAsACutOut) {
  World world;
  std::vector<std::string> warnings;
  const Status s = load_world(test::fixture("good/cut_out_table.gltf"), world, &warnings);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_TRUE(warnings.empty()) << test::joined(warnings);
  const Mesh& table = mesh_named(world, "Table");
  EXPECT_EQ(table.alpha_mode, Mesh::AlphaMode::Mask);
  EXPECT_FLOAT_EQ(table.alpha_cutoff, 0.4f);
  EXPECT_TRUE(table.double_sided);
  ASSERT_EQ(world.textures.size(), 1u);
  const std::vector<uint8_t>& t = world.textures[0].rgba8;
  ASSERT_EQ(t.size(), 16u);
  EXPECT_EQ(t[3], 255);  // white: covered
  EXPECT_EQ(t[7], 0);    // black: not
  EXPECT_EQ(t[11], 0);
  EXPECT_EQ(t[15], 255);
  for (const Mesh& m : world.meshes) {
    if (&m == &table) continue;
    EXPECT_EQ(m.alpha_mode, Mesh::AlphaMode::Opaque) << m.name;
  }
}

// Property: alphaMode and alphaCutoff survive the writer and the loader: a mesh written MASK with
// cutoff c loads as Mask with c (0.5, glTF's default, is not written and loads as 0.5), BLEND as
// Blend, and a mesh that never had either loads Opaque.
TEST(CutOut, AlphaModeAndCutoffRoundTrip) {
  World world;
  ASSERT_TRUE(load_world(test::fixture("good/three_rooms.gltf"), world).ok());
  for (const Mesh& m : world.meshes) EXPECT_EQ(m.alpha_mode, Mesh::AlphaMode::Opaque) << m.name;
  const OptimizeOptions keep = test::nothing_merges();
  SceneDesc written;
  ASSERT_TRUE(optimize_world(world, keep, written).ok());
  struct Want {
    const char* mesh;
    Mesh::AlphaMode mode;
    float cutoff;
  };
  const Want wants[] = {{"Table", Mesh::AlphaMode::Mask, 0.3f},
                        {"Chair", Mesh::AlphaMode::Mask, 0.5f},
                        {"KitchenShell", Mesh::AlphaMode::Blend, 0.5f}};
  for (const Want& w : wants) {
    bool found = false;
    for (MeshDesc& m : written.meshes)
      if (m.name == w.mesh) {
        m.alpha_mode = w.mode;
        m.alpha_cutoff = w.cutoff;
        found = true;
      }
    ASSERT_TRUE(found) << w.mesh;
  }
  std::vector<uint8_t> glb;
  ASSERT_TRUE(scene_to_glb(written, glb).ok());
  const std::string text(glb.begin(), glb.end());
  EXPECT_NE(text.find("\"alphaCutoff\""), std::string::npos) << "0.3 is written";
  World back;
  const Status s = load_world_from_memory(glb.data(), glb.size(), "written.glb", "", back);
  ASSERT_TRUE(s.ok()) << s.message();
  for (const Want& w : wants) {
    SCOPED_TRACE(w.mesh);
    EXPECT_EQ(mesh_named(back, w.mesh).alpha_mode, w.mode);
    if (w.mode == Mesh::AlphaMode::Mask) {
      EXPECT_EQ(mesh_named(back, w.mesh).alpha_cutoff, w.cutoff);
    }
  }
  EXPECT_EQ(mesh_named(back, "RoomShell").alpha_mode, Mesh::AlphaMode::Opaque);
}

// Property: optimize merges two open-walled cells only when their shells cut out alike: three
// cells in a row, the middle one's shell a cut-out, stay three cells; made alike (all Mask with
// one cutoff and base alpha), they merge into one, and the merged shell is a cut-out with that
// cutoff and base alpha (its tints in the vertex colours, as for opaque shells).
TEST(CutOut, OptimizeMergesOnlyShellsThatCutOutAlike) {
  auto scene_with = [](bool all_cut_out) {
    return test::row_of_three_cells([&](int k, MeshDesc& shell) {
      shell.base_color = glm::vec4(0.2f + 0.3f * float(k), 0.5f, 0.5f, 0.8f);
      if (all_cut_out || k == 1) {
        shell.alpha_mode = Mesh::AlphaMode::Mask;
        shell.alpha_cutoff = 0.25f;
      }
    });
  };
  for (const bool alike : {false, true}) {
    SCOPED_TRACE(alike ? "all cut out" : "middle cut out");
    World before;
    ASSERT_TRUE(build_world(scene_with(alike), "row", before).ok());
    SceneDesc merged;
    OptimizeReport report;
    ASSERT_TRUE(optimize_world(before, {}, merged, &report).ok());
    EXPECT_EQ(report.cells_after, alike ? 1u : 3u);
    World after;
    ASSERT_TRUE(build_world(merged, "merged", after).ok());
    size_t cut_outs = 0;
    for (const Cell& c : after.cells) {
      const Mesh& shell = after.meshes[size_t(c.shell_mesh)];
      if (shell.alpha_mode != Mesh::AlphaMode::Mask) continue;
      ++cut_outs;
      EXPECT_EQ(shell.alpha_cutoff, 0.25f);
      EXPECT_EQ(shell.base_color.a, 0.8f) << "coverage uses the base alpha: kept through the tints";
    }
    EXPECT_EQ(cut_outs, 1u);
  }
}

}  // namespace
}  // namespace lintel
