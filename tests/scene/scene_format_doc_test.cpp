// docs/scene-format.md and docs/scene-format.schema.json must stay true: the document's example
// is the fixture good/two_rooms_minimal.gltf byte for byte and loads as described, and the schema
// parses and names the format version this build reads.
#include "fixture_support.h"

#include <lintel/scene_io.h>
#include <lintel/version.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <iterator>

namespace lintel {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(SceneFormatDoc, ExampleInTheDocumentIsTheMinimalFixture) {
  const std::string doc = read_text(std::string(LINTEL_SOURCE_DIR) + "/docs/scene-format.md");
  const std::string begin = "<!-- example:begin -->\n```json\n";
  const size_t a = doc.find(begin);
  const size_t b = doc.find("```\n<!-- example:end -->");
  ASSERT_NE(a, std::string::npos);
  ASSERT_NE(b, std::string::npos);
  EXPECT_EQ(doc.substr(a + begin.size(), b - a - begin.size()), read_text(test::fixture("good/two_rooms_minimal.gltf")))
      << "regenerate with tests/scene/fixtures/make_fixtures.py and paste the file into the document";
}

TEST(SceneFormatDoc, ExampleLoadsAsTheDocumentSays) {
  World world;
  std::vector<std::string> warnings;
  const Status s = load_world(test::fixture("good/two_rooms_minimal.gltf"), world, &warnings);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_TRUE(warnings.empty());
  ASSERT_EQ(world.cells.size(), 2u);
  ASSERT_EQ(world.portals.size(), 1u);
  const Portal& door = world.portals[0];
  EXPECT_EQ(world.cells[door.from].name, "West");
  EXPECT_EQ(world.cells[door.to].name, "East");
  EXPECT_NEAR(door.normal_world.x, 1.0f, 1e-6f);  // wound towards -X in the file
  EXPECT_EQ(world.cells[0].links.size(), 1u);
  EXPECT_EQ(world.cells[1].links.size(), 1u);
  // East is turned 180 degrees: its cell-space +X is world -X.
  const glm::vec3 east_x = glm::vec3(world.cells[1].cell_to_world * glm::vec4(1, 0, 0, 0));
  EXPECT_NEAR(east_x.x, -1.0f, 1e-6f);
  ASSERT_EQ(world.timelines.size(), 1u);
  EXPECT_EQ(world.timelines[0].name, "through_the_door");
}

TEST(SceneFormatSchema, ParsesAndPinsThisBuildsFormatVersion) {
  const nlohmann::json schema = nlohmann::json::parse(
      read_text(std::string(LINTEL_SOURCE_DIR) + "/docs/scene-format.schema.json"), nullptr, false);
  ASSERT_FALSE(schema.is_discarded());
  const auto& defs = schema.at("$defs");
  EXPECT_EQ(defs.at("sceneLintel").at("properties").at("version").at("const"), LINTEL_SCENE_FORMAT_VERSION);
  for (const char* key : {"cell", "portal", "volume"})
    EXPECT_TRUE(defs.at("nodeLintel").at("properties").contains(key)) << key;
  EXPECT_EQ(defs.at("portal").at("properties").at("two_way").at("default"), true);
  EXPECT_EQ(defs.at("timeline").at("properties").at("fps").at("default"), 60);
}

}  // namespace
}  // namespace lintel
