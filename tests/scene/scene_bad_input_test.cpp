// One fixture per class of malformed input (tests/scene/fixtures/bad, written by
// make_fixtures.py): `lintel validate` must exit 2 with exactly one stderr line
// "lintel: error: <file>: <element>: <fault>", and load_world() must return the same message.
#include "fixture_support.h"

#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <fstream>

namespace lintel {
namespace {

struct BadCase {
  const char* file;     // under tests/scene/fixtures/
  const char* element;  // the element the message must name ("" for faults of the whole file)
  const char* fault;    // a phrase the message must contain
};

std::ostream& operator<<(std::ostream& out, const BadCase& c) { return out << c.file; }

const BadCase kBadCases[] = {
    // unreadable or truncated files
    {"bad/not_json.gltf", "", "not valid JSON"},
    {"bad/json_truncated.gltf", "", "not valid JSON"},
    {"bad/glb_truncated.glb", "", "truncated GLB"},
    {"bad/extras_too_deep.gltf", "", "JSON nesting is deeper than 64 levels"},
    // buffers and accessors
    {"bad/buffer_file_missing.gltf", "buffer 0", "cannot read 'missing.bin'"},
    {"bad/buffer_data_uri_too_short.gltf", "buffer 0", "data URI holds 1128 bytes, byteLength says 1132"},
    {"bad/buffer_view_beyond_buffer.gltf", "bufferView 12", "exceed buffer 0"},
    {"bad/accessor_count_beyond_view.gltf", "accessor 9 (POSITION of mesh 5 'Chair' primitive 0)",
     "needs 108 bytes, bufferView 9 has 96"},
    {"bad/accessor_component_type_wrong.gltf", "accessor 9 (POSITION of mesh 5 'Chair' primitive 0)",
     "must be VEC3 of FLOAT (componentType 5126) or of 8- or 16-bit integers (5120-5123), got type 3 componentType "
     "5125"},
    {"bad/accessor_component_type_unknown.gltf", "accessor 9", "componentType 9999 is not a glTF component type"},
    {"bad/index_out_of_range.gltf", "accessor 13 (indices of mesh 6 'Table' primitive 0)",
     "index 99 at position 4 is >= the vertex count 4"},
    {"bad/integer_overflow.gltf", "accessors[0].bufferView", "out of the 32-bit range"},
    {"bad/mesh_index_out_of_range.gltf", "node 3 'HallChair'", "mesh index 99 is out of range"},
    // non-finite numbers and bad transforms
    {"bad/vertex_nan.gltf", "accessor 12 (POSITION of mesh 6 'Table' primitive 0)", "element 2 is not finite"},
    {"bad/translation_not_finite.gltf", "node 3 'HallChair'", "translation element 0 value 1e+39 is not finite"},
    {"bad/scale_zero.gltf", "node 4 'HallTable'", "scale [1, 0, 1] has a zero component"},
    {"bad/matrix_singular.gltf", "node 4 'HallTable'", "matrix has determinant 0 (a zero scale collapses an axis)"},
    {"bad/no_cells.gltf", "scene 0 'Main'", "has no cells: mark cell nodes with extras.lintel.cell"},
    {"bad/cell_mirrored.gltf", "node 1 'Kitchen'", "cell transform mirrors (negative scale or determinant)"},
    {"bad/matrix_and_trs.gltf", "node 4 'HallTable'", "has both 'matrix' and translation/rotation/scale"},
    // node hierarchy
    {"bad/hierarchy_cycle.gltf", "node 1 'Kitchen'", "node hierarchy cycle"},
    {"bad/hierarchy_self_child.gltf", "node 7 'Furniture'", "node hierarchy cycle: the node is its own child"},
    {"bad/hierarchy_two_parents.gltf", "node 3 'HallChair'", "has two parents (node 0 and node 10)"},
    // cells
    {"bad/cell_name_duplicate.gltf", "node 10 'Cellar'", "duplicate cell name 'Hall'"},
    {"bad/cell_without_shell_or_volume.gltf", "node 10 'Cellar'", "has neither a shell mesh nor a volume node"},
    {"bad/volume_not_closed.gltf", "node 6 'KitchenVolume'", "volume mesh is not closed"},
    // portals
    {"bad/portal_unknown_cell.gltf", "node 2 'HallKitchenDoor'", "portal 'to' names unknown cell 'Garage'"},
    {"bad/portal_from_equals_to.gltf", "node 2 'HallKitchenDoor'", "to itself (from == to)"},
    {"bad/portal_not_planar.gltf", "node 2 'HallKitchenDoor'", "portal polygon is not planar"},
    {"bad/portal_not_convex.gltf", "node 2 'HallKitchenDoor'", "portal polygon is not convex"},
    {"bad/portal_overlapping_triangles.gltf", "node 2 'HallKitchenDoor'", "portal polygon is not one convex polygon"},
    {"bad/portal_degenerate.gltf", "node 2 'HallKitchenDoor'", "portal polygon is degenerate"},
    {"bad/portal_too_many_vertices.gltf", "node 2 'HallKitchenDoor'", "more than 64 distinct vertices"},
    {"bad/portal_not_touching_volume.gltf", "node 2 'HallKitchenDoor'", "does not touch the volume of cell 'Kitchen'"},
    {"bad/portal_without_mesh.gltf", "node 9 'CellarHatch'", "portal node has no mesh"},
    // Lintel extras and version
    {"bad/sparse_not_increasing.gltf", "accessor 14 (POSITION of mesh 6 'Table' primitive 0)",
     "sparse indices are not strictly increasing at position 2"},
    {"bad/sparse_index_out_of_range.gltf", "accessor 14 (POSITION of mesh 6 'Table' primitive 0)",
     "sparse index 4 at position 3 is >= count"},
    {"bad/accessor_zeros_too_many.gltf", "accessor 14 (POSITION of mesh 6 'Table' primitive 0)",
     "count 65537 without a bufferView is more than 65536 zeros"},
    {"bad/extension_required_unknown.gltf", "extensionsRequired[0]",
     "extension 'KHR_draco_mesh_compression' is required by the file and not read by Lintel"},
    {"bad/version_unknown.gltf", "scene 0 'Main'", "unsupported scene format version 2"},
    {"bad/version_not_integer.gltf", "scene 0 'Main'", "extras.lintel.version must be an integer, got string"},
    {"bad/extras_cell_not_string.gltf", "node 0 'Hall'", "extras.lintel.cell must be a string, got integer"},
    {"bad/extras_two_way_not_bool.gltf", "node 2 'HallKitchenDoor'", "two_way must be true or false, got string"},
    {"bad/extras_open_not_bool.gltf", "node 2 'HallKitchenDoor'",
     "extras.lintel.portal.open must be true or false, got string"},
    {"bad/extras_lintel_not_object.gltf", "node 4 'HallTable'", "extras.lintel must be an object, got array"},
    {"bad/light_unknown_type.gltf", "light 0 'SpotDef'", "unknown KHR_lights_punctual type 'area'"},
    // timelines in the scene
    {"bad/timeline_no_keys.gltf", "timeline 'walk'", "keys is empty"},
    {"bad/timeline_event_unknown_portal.gltf", "timeline 'walk' event 0", "no portal named 'GarageDoor'"},
    {"bad/timeline_t_not_increasing.gltf", "timeline 'walk' key 1", "is not greater than the previous key's t"},
    {"bad/timeline_fps_zero.gltf", "timeline 'walk'", "fps 0 is outside (0, 1000]"},
    {"bad/timeline_fov_180.gltf", "timeline 'walk'", "fov_y_deg 180 is outside (0, 180)"},
    {"bad/timeline_eye_not_finite.gltf", "timeline 'walk' key 0", "is not finite as a 32-bit float"},
    {"bad/timeline_eye_equals_target.gltf", "timeline 'walk' key 1", "eye and target coincide"},
    // base colour textures (the Table, mesh 6, textured by material 1 'Checker', texture 0, image 0)
    {"bad/texture_index_out_of_range.gltf", "materials[1].pbrMetallicRoughness.baseColorTexture",
     "texture index 3 does not exist (1 textures)"},
    {"bad/texture_uv_set_missing.gltf", "mesh 6 'Table' primitive 0",
     "has no TEXCOORD_1, but the mesh has a base colour texture"},
    {"bad/texture_uv_set_out_of_range.gltf", "materials[1].pbrMetallicRoughness.baseColorTexture",
     "texCoord 40 is not a uv set (0..31)"},
    {"bad/texture_source_out_of_range.gltf", "textures[0]", "source image 4 does not exist (1 images)"},
    {"bad/texture_without_source.gltf", "textures[0]", "has no source image"},
    {"bad/image_file_missing.gltf", "images[0] 'checker'", "cannot read 'missing.png': No such file or directory"},
    {"bad/image_not_png_or_jpeg.gltf", "images[0] 'checker'", "is not a PNG or JPEG image"},
    {"bad/image_undecodable.gltf", "images[0] 'checker'", "cannot decode: "},
    {"bad/image_too_large.gltf", "images[0] 'checker'", "is 8193x1 pixels, over the limit of 8192x8192"},
    {"bad/texcoord_missing.gltf", "mesh 6 'Table' primitive 0",
     "has no TEXCOORD_0, but the mesh has a base colour texture (material 1)"},
    {"bad/texcoord_count_mismatch.gltf", "mesh 6 'Table' primitive 0", "TEXCOORD_0 has 3 elements, POSITION has 4"},
    {"bad/texcoord_not_finite.gltf", "accessor 14 (TEXCOORD_0 of mesh 6 'Table' primitive 0)",
     "element 1 is not finite (NaN or Inf)"},
    {"bad/texcoord_not_vec2.gltf", "accessor 14 (TEXCOORD_0 of mesh 6 'Table' primitive 0)",
     "must be VEC2 of FLOAT (componentType 5126) or of 8- or 16-bit integers (5120-5123), got type 3 componentType "
     "5126"},
    // vertex colours (COLOR_0): the forms glTF 2.0 allows, one per position
    {"bad/color_not_normalized.gltf", "accessor 14 (COLOR_0 of mesh 6 'Table' primitive 0)",
     "must be VEC3 or VEC4 of FLOAT (componentType 5126) or of normalized UNSIGNED_BYTE or UNSIGNED_SHORT (5121, "
     "5123), got type 4 componentType 5121 not normalized"},
    {"bad/color_count_mismatch.gltf", "mesh 6 'Table' primitive 0", "COLOR_0 has 3 elements, POSITION has 4"},
    {"bad/material_alpha_mode_not_string.gltf", "material 0 'Oak'", "alphaMode must be a string, got integer"},
    {"bad/material_alpha_mode_unknown.gltf", "material 0 'Oak'",
     "alphaMode must be OPAQUE, MASK or BLEND, got 'CUTOUT'"},
    {"bad/material_alpha_cutoff_negative.gltf", "material 0 'Oak'", "alphaCutoff -0.5 is negative or beyond 1e9"},
    {"bad/material_alpha_cutoff_not_number.gltf", "material 0 'Oak'", "alphaCutoff must be a number, got string"},
    {"bad/material_emissive_factor_negative.gltf", "material 0 'Oak'", "emissiveFactor -1 is negative or beyond 1e9"},
    {"bad/material_emissive_factor_not_number.gltf", "material 0 'Oak'",
     "emissiveFactor element 1 must be a number, got string"},
    {"bad/emissive_texture_without_uvs.gltf", "mesh 6 'Table' primitive 0",
     "has no TEXCOORD_0, but the mesh has an emissive texture (material 1)"},
    {"bad/material_emissive_strength_negative.gltf", "material 0 'Oak'.extensions.KHR_materials_emissive_strength",
     "emissiveStrength -2 is negative or beyond 1e9"},
    {"bad/color_not_vec3_or_vec4.gltf", "accessor 14 (COLOR_0 of mesh 6 'Table' primitive 0)",
     "must be VEC3 or VEC4 of FLOAT (componentType 5126) or of normalized UNSIGNED_BYTE or UNSIGNED_SHORT (5121, "
     "5123), got type 2 componentType 5121"},
};

std::string base_name(const std::string& path) { return path.substr(path.find_last_of('/') + 1); }

// The message shape every bad input must produce: "<path>: <element>: <fault ...>".
void expect_message(const std::string& message, const std::string& path, const BadCase& c) {
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
  if (*c.element) {
    EXPECT_EQ(message.rfind(path + ": " + c.element + ": ", 0), 0u) << message;
  }
  EXPECT_NE(message.find(c.fault), std::string::npos) << message;
}

class BadSceneFile : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadSceneFile, ValidateExitsTwoWithOneErrorLineNamingFileElementAndFault) {
  const BadCase& c = GetParam();
  const std::string path = test::fixture(c.file);
  const test::CliResult r = test::run_lintel({"validate", path});
  EXPECT_EQ(r.exit_code, 2);
  ASSERT_EQ(r.stderr_lines.size(), 1u) << test::joined(r.stderr_lines);
  const std::string prefix = "lintel: error: ";
  ASSERT_EQ(r.stderr_lines[0].rfind(prefix, 0), 0u) << r.stderr_lines[0];
  EXPECT_NE(r.stderr_lines[0].find(base_name(path)), std::string::npos);
  expect_message(r.stderr_lines[0].substr(prefix.size()), path, c);
}

TEST_P(BadSceneFile, LoaderReturnsTheSameMessageAndAnEmptyWorld) {
  const BadCase& c = GetParam();
  const std::string path = test::fixture(c.file);
  World world;
  world.cells.resize(1);  // must be cleared
  std::vector<std::string> warnings;
  const Status s = load_world(path, world, &warnings);
  ASSERT_FALSE(s.ok());
  expect_message(s.message(), path, c);
  EXPECT_TRUE(world.cells.empty());
  EXPECT_TRUE(warnings.empty()) << "a failed load reports no warnings";
  const test::CliResult r = test::run_lintel({"validate", path});
  ASSERT_EQ(r.stderr_lines.size(), 1u);
  EXPECT_EQ(r.stderr_lines[0], "lintel: error: " + s.message());
}

INSTANTIATE_TEST_SUITE_P(Fixtures, BadSceneFile, ::testing::ValuesIn(kBadCases),
                         [](const ::testing::TestParamInfo<BadCase>& param) {
                           std::string name = base_name(param.param.file);
                           name = name.substr(0, name.find('.'));
                           return name;
                         });

TEST(BadScenePath, NonexistentPathIsOneErrorLine) {
  const std::string path = test::fixture("bad/no_such_file.gltf");
  const test::CliResult r = test::run_lintel({"validate", path});
  EXPECT_EQ(r.exit_code, 2);
  ASSERT_EQ(r.stderr_lines.size(), 1u);
  EXPECT_EQ(r.stderr_lines[0], "lintel: error: " + path + ": No such file or directory");
}

TEST(BadScenePath, DirectoryIsRefusedWithoutReading) {
  const std::string path = test::fixture("bad");
  const test::CliResult r = test::run_lintel({"validate", path});
  EXPECT_EQ(r.exit_code, 2);
  ASSERT_EQ(r.stderr_lines.size(), 1u);
  EXPECT_EQ(r.stderr_lines[0], "lintel: error: " + path + ": is a directory");
}

TEST(BadScenePath, EmptyFileIsAnError) {
  const std::string path = test::scratch_dir("empty") + "/empty.gltf";
  std::ofstream(path).close();
  World world;
  const Status s = load_world(path, world);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.message(), path + ": the file is empty");
}

TEST(BadScenePath, DeviceFileIsNotRead) {
  World world;
  const Status s = load_world("/dev/zero", world);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.message(), "/dev/zero: is not a regular file");
}

}  // namespace
}  // namespace lintel
