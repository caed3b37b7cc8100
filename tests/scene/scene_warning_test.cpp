// Suspicious but usable scenes (tests/scene/fixtures/warn): each loads, and reports exactly one
// warning, in the message shape of errors, saying what was odd.
#include "fixture_support.h"

#include <lintel/scene_io.h>

#include <gtest/gtest.h>

namespace lintel {
namespace {

struct WarnCase {
  const char* file;
  const char* element;
  const char* phrase;
};

std::ostream& operator<<(std::ostream& out, const WarnCase& c) { return out << c.file; }

const WarnCase kWarnCases[] = {
    {"warn/cell_without_portals.gltf", "node 12 'Attic'", "cell 'Attic' has no portals"},
    {"warn/mesh_outside_cell.gltf", "node 12 'Lonely'", "mesh node outside any cell (ignored)"},
    {"warn/primitive_not_triangles.gltf", "mesh 6 'Table' primitive 1",
     "has mode 1 (lines); only triangles (lists, strips, fans) are read, skipped"},
    {"warn/version_missing.gltf", "scene 0 'Main'",
     "extras.lintel.version is missing; assuming scene format version 1"},
    {"warn/light_outside_cell.gltf", "node 12 'StrayLight'", "light outside any cell (ignored)"},
    {"warn/extras_unknown_key.gltf", "node 0 'Hall'", "unknown key 'colour' in extras.lintel (ignored)"},
    {"warn/cell_shell_cut_out.gltf", "node 1 'Kitchen'",
     "cell 'Kitchen' has a cut-out shell (alphaMode MASK): other cells seen through it are drawn only where a portal "
     "leads to them"},
    {"warn/material_alpha_blend.gltf", "material 0 'Oak'",
     "alphaMode BLEND is drawn with screen-door transparency (a 4 x 4 dither), not blended"},
    {"warn/emissive_texture_other_uv_set.gltf", "material 1 'Checker'",
     "emissiveTexture reads another uv set or KHR_texture_transform than baseColorTexture; Lintel reads one, the base "
     "colour's"},
};

class WarningScene : public ::testing::TestWithParam<WarnCase> {};

// A glass shell (alphaMode BLEND) gets the material's warning and the cut-out shell's, in load order.
TEST(WarningSceneTwice, SeeThroughShellWarnsForTheMaterialAndTheCell) {
  const std::string path = test::fixture("warn/cell_shell_see_through.gltf");
  World world;
  std::vector<std::string> warnings;
  const Status s = load_world(path, world, &warnings);
  ASSERT_TRUE(s.ok()) << s.message();
  ASSERT_EQ(warnings.size(), 2u) << test::joined(warnings);
  EXPECT_EQ(warnings[0], path +
                             ": material 1 'Glass': alphaMode BLEND is drawn with screen-door transparency (a 4 "
                             "x 4 dither), not blended");
  EXPECT_EQ(warnings[1], path +
                             ": node 1 'Kitchen': cell 'Kitchen' has a see-through shell (alphaMode BLEND): other "
                             "cells seen through it are drawn only where a portal leads to them");
}

TEST_P(WarningScene, LoadsWithExactlyOneWarningNamingTheElement) {
  const WarnCase& c = GetParam();
  const std::string path = test::fixture(c.file);
  World world;
  std::vector<std::string> warnings;
  const Status s = load_world(path, world, &warnings);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_GE(world.cells.size(), 3u);
  ASSERT_EQ(warnings.size(), 1u) << test::joined(warnings);
  EXPECT_EQ(warnings[0], path + ": " + c.element + ": " + c.phrase);
}

TEST_P(WarningScene, ValidatePrintsTheWarningAndExitsZero) {
  const WarnCase& c = GetParam();
  const test::CliResult r = test::run_lintel({"validate", test::fixture(c.file)});
  EXPECT_EQ(r.exit_code, 0);
  ASSERT_EQ(r.stderr_lines.size(), 1u) << test::joined(r.stderr_lines);
  EXPECT_EQ(r.stderr_lines[0].rfind("lintel: warning: ", 0), 0u);
  EXPECT_NE(r.stderr_lines[0].find(c.phrase), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(Fixtures, WarningScene, ::testing::ValuesIn(kWarnCases),
                         [](const ::testing::TestParamInfo<WarnCase>& param) {
                           std::string name = param.param.file;
                           name = name.substr(name.find('/') + 1);
                           return name.substr(0, name.find('.'));
                         });

TEST(WarningScene, NullWarningSinkIsAllowed) {
  World world;
  EXPECT_TRUE(load_world(test::fixture("warn/mesh_outside_cell.gltf"), world, nullptr).ok());
}

}  // namespace
}  // namespace lintel
