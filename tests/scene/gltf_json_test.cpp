// parse_gltf_json (scene/src/read/gltf_json.h) against parse_json_bounded, the parse it stands in
// for: the same DOM less the left-out parts (each accessor's "min" and "max"), the same reason
// for every text that does not parse, and the whole DOM -- so the same
// preflight error -- when a left-out integer lies outside 32 bits. Documents: every committed
// scene and fixture, hand-made edge cases and, where Freedoom is installed, an imported level.
#include "read/gltf_json.h"
#include "read/json_bounded.h"

#include "fixture_support.h"
#include "imported_level.h"

#include <lintel/doom_import.h>
#include <lintel/scene_io.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace lintel::scene_read {
namespace {

using nlohmann::json;

// What parse_gltf_json keeps of a whole DOM.
json without_left_out(json doc) {
  if (!doc.is_object()) return doc;
  if (auto accessors = doc.find("accessors"); accessors != doc.end() && accessors->is_array())
    for (json& accessor : *accessors)
      if (accessor.is_object()) {
        accessor.erase("min");
        accessor.erase("max");
      }
  return doc;
}

// The JSON text of a .gltf, or the JSON chunk of a .glb.
std::string json_text_of(const std::vector<uint8_t>& bytes) {
  if (bytes.size() >= 20 && std::memcmp(bytes.data(), "glTF", 4) == 0) {
    uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);
    return std::string(reinterpret_cast<const char*>(bytes.data()) + 20, std::min<size_t>(length, bytes.size() - 20));
  }
  return std::string(bytes.begin(), bytes.end());
}

std::vector<uint8_t> read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The whole comparison for one text: success and DOM, or the same reason.
void expect_as_bounded(const std::string& text, const std::string& label, bool left_out_expected) {
  json whole, kept;
  const std::string why_whole = parse_json_bounded(text.data(), text.size(), whole);
  const std::string why_kept = parse_gltf_json(text.data(), text.size(), kept);
  ASSERT_EQ(why_kept, why_whole) << label;
  if (!why_whole.empty()) return;
  if (left_out_expected)
    EXPECT_EQ(kept, without_left_out(whole)) << label;
  else
    EXPECT_EQ(kept, whole) << label;
}

TEST(GltfJson, CommittedScenesAndFixturesParseAsTheWholeDomLessTheLeftOutParts) {
  size_t documents = 0, with_bounds = 0;
  for (const std::string& root : {std::string(LINTEL_SOURCE_DIR) + "/scenes", test::fixture("")}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
      const std::string ext = entry.path().extension().string();
      if (ext != ".gltf" && ext != ".glb") continue;
      const std::string text = json_text_of(read_bytes(entry.path()));
      expect_as_bounded(text, entry.path().string(), true);
      ++documents;
      json whole;
      if (parse_json_bounded(text.data(), text.size(), whole).empty() && whole.is_object() &&
          whole.contains("accessors") && whole["accessors"].is_array() && !whole["accessors"].empty() &&
          whole["accessors"][0].contains("min"))
        ++with_bounds;
    }
  }
  EXPECT_GT(documents, 50u);
  EXPECT_GT(with_bounds, 20u);  // the left-out parts are really there to leave out
}

TEST(GltfJson, TruncatedAndBrokenTextsGiveTheSameReason) {
  const std::string text = json_text_of(read_bytes(std::string(LINTEL_SOURCE_DIR) + "/scenes/cottage.gltf"));
  ASSERT_GT(text.size(), 1000u);
  // Cuts everywhere in the first 4 KiB (keys, numbers, strings, nesting), then coarser.
  for (size_t cut = 0; cut < text.size(); cut += cut < 4096 ? 1 : 997)
    expect_as_bounded(text.substr(0, cut), "cut at " + std::to_string(cut), true);
  for (size_t at = 0; at < 4096; at += 7) {
    std::string broken = text;
    broken[at] = broken[at] == '}' ? ']' : '}';
    expect_as_bounded(broken, "broken at " + std::to_string(at), true);
  }
}

TEST(GltfJson, EdgeCases) {
  const char* kept_cases[] = {
      R"([{"meshes": [1]}, 2])",                           // root is not an object
      R"({"meshes": 7, "nodes": [{"mesh": 0}]})",          // meshes are kept, whatever they are
      R"({"meshes": [], "meshes": [{"name": "again"}]})",  // a repeated key
      R"({"accessors": [1, [{"min": [0]}], {"min": [1], "max": {"x": [2, {"y": 3}]}, "count": 4}]})",
      R"({"accessors": {"min": [0]}, "nodes": [{"min": [0], "max": [1]}]})",  // min/max kept elsewhere
      R"({"a": {"accessors": [{"min": [5]}]}, "accessors": [], "accessors": [{"max": [1], "type": "VEC3"}]})",
      R"({"nodes": [{"mesh": 4294967296}], "meshes": [{"extras": {"big": 2147483647}, "n": -2147483648}]})",
      R"({"accessors": [{"min": [2147483647, -2147483648, 1e300, 4294967296.0], "max": "x"}]})",
      R"({"meshes": [{"name": "\"quoted\" and \\ escaped \u00e9"}], "s": "x\u0000y"})",
      "{}",
      "[]",
      "3",
  };
  for (const char* text : kept_cases) expect_as_bounded(text, text, true);
  // A left-out integer outside 32 bits (anywhere in the left-out parts): the whole DOM. Meshes are
  // kept, so an integer there is simply in the DOM.
  const char* whole_cases[] = {
      R"({"meshes": [{"primitives": [{"indices": 4294967296}]}], "nodes": []})",
      R"({"meshes": [{"extras": {"n": -2147483649}}]})",
      R"({"nodes": [{"mesh": 4294967296}], "meshes": [{"extras": {"big": 4294967295}}]})",
      R"({"accessors": [{"count": 3, "min": [18446744073709551615]}]})",
      R"({"accessors": [{"max": [[0, [2147483648]]]}], "meshes": []})",
  };
  for (const char* text : whole_cases) expect_as_bounded(text, text, false);
}

// Through the loader: an out-of-range integer in a mesh or a left-out part is reported where it
// is, and before one later in the document's key order.
TEST(GltfJson, LoaderReportsAnIntegerOutOfRangeInTheLeftOutParts) {
  const std::string path = std::string(LINTEL_SOURCE_DIR) + "/scenes/cottage.gltf";
  json doc = json::parse(json_text_of(read_bytes(path)));
  auto load_message = [&](const json& d) {
    const std::string text = d.dump();
    World world;
    const Status s = load_world_from_memory(reinterpret_cast<const uint8_t*>(text.data()), text.size(), "doc.gltf",
                                            std::string(LINTEL_SOURCE_DIR) + "/scenes", world);
    return s.ok() ? std::string("ok") : s.message();
  };
  ASSERT_EQ(load_message(doc), "ok");
  json in_mesh = doc;
  in_mesh["meshes"][1]["primitives"][0]["indices"] = 4294967296ull;
  EXPECT_EQ(load_message(in_mesh),
            "doc.gltf: meshes[1].primitives[0].indices: integer 4294967296 is out of the 32-bit range glTF readers "
            "support");
  in_mesh["nodes"][0]["mesh"] = -4294967296ll;  // later in key order than "meshes"
  EXPECT_NE(load_message(in_mesh).find("meshes[1].primitives[0].indices"), std::string::npos);
  json in_bounds = doc;
  in_bounds["accessors"][2]["max"][0] = -3000000000ll;
  EXPECT_EQ(load_message(in_bounds),
            "doc.gltf: accessors[2].max[0]: integer -3000000000 is out of the 32-bit range glTF readers support");
}

// The rule preflight's integer check walks the DOM with: every integer, except under a key
// "extras" or "extensions" (user data), fits 32 bits.
bool checked_integers_fit(const json& value) {
  if (value.is_number_unsigned()) return value.get<uint64_t>() <= uint64_t(INT32_MAX);
  if (value.is_number_integer()) return value.get<int64_t>() >= INT32_MIN && value.get<int64_t>() <= INT32_MAX;
  if (value.is_object()) {
    for (const auto& [key, child] : value.items())
      if (key != "extras" && key != "extensions" && !checked_integers_fit(child)) return false;
  }
  if (value.is_array())
    for (const json& element : value)
      if (!checked_integers_fit(element)) return false;
  return true;
}

// Property: when parse_gltf_json says every checked integer fits (so preflight skips its walk),
// that walk would have found none; and on the documents below it says so exactly when the walk
// finds none (a false "unsure" only on the whole-DOM path). Documents: every committed scene and
// fixture, and integers placed in and around "extras"/"extensions" values of every kind.
TEST(GltfJson, IntegersFitAgreesWithPreflightsWalk) {
  auto expect_flag = [](const std::string& text, bool expected) {
    json doc;
    bool fit = !expected;
    ASSERT_EQ(parse_gltf_json(text.data(), text.size(), doc, &fit), "") << text;
    json whole = json::parse(text);
    if (fit) {
      EXPECT_TRUE(checked_integers_fit(whole)) << text;
    }
    EXPECT_EQ(fit, expected) << text;
  };
  for (const std::string& root : {std::string(LINTEL_SOURCE_DIR) + "/scenes", test::fixture("good")})
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
      const std::string ext = entry.path().extension().string();
      if (ext == ".gltf" || ext == ".glb") expect_flag(json_text_of(read_bytes(entry.path())), true);
    }
  expect_flag(R"({"nodes": [{"mesh": 4294967296}]})", false);
  expect_flag(R"({"nodes": [{"mesh": -2147483649}]})", false);
  expect_flag(R"({"nodes": [{"mesh": 2147483647, "x": -2147483648}]})", true);
  expect_flag(R"({"nodes": [{"extras": {"a": 4294967296}}]})", true);
  expect_flag(R"({"extensions": {"X": [4294967296, {"y": [-4294967296]}]}})", true);
  expect_flag(R"({"extras": 4294967296, "n": 1})", true);
  expect_flag(R"({"extras": 1, "n": 4294967296})", false);           // the exempt value was the 1
  expect_flag(R"({"a": {"extras": {}}, "b": -2147483649})", false);  // after the exempt object
  expect_flag(R"({"extras": {"x": {"extras": 5}}, "y": 2147483648})", false);
  expect_flag(R"({"extras": [[4294967296]], "z": [[1]]})", true);
  expect_flag(R"({"accessors": [{"count": 1, "min": [1]}], "k": 3000000000})", false);
  expect_flag(R"({"accessors": [{"min": [4294967296]}]})", false);  // the whole-DOM path: unsure
}

TEST(GltfJson, ImportedDoomLevel) {
  if (!test::freedoom_installed()) GTEST_SKIP() << test::kFreedoomWad << " not installed (Debian package freedoom)";
  std::vector<uint8_t> glb;
  ASSERT_TRUE(test::imported_level_glb("E1M5", glb));
  expect_as_bounded(json_text_of(glb), "E1M5", true);
}

}  // namespace
}  // namespace lintel::scene_read
