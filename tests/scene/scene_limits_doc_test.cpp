// The limits table of docs/scene-format.md against the constants the loader checks: every row is
// read from the document and each number compared with its constant, so the two cannot drift.
// Also: the per-timeline key limit can be reached (no other cap refuses such a file first).
#include "fixture_support.h"

#include "read/json_bounded.h"
#include "read/load_limits.h"
#include "read/timeline_json.h"

#include <lintel/scene_io.h>
#include <lintel/world.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <sstream>

namespace lintel {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The rows of the table under "## Limits": first column -> second column.
std::map<std::string, std::string> limits_table() {
  const std::string doc = read_text(std::string(LINTEL_SOURCE_DIR) + "/docs/scene-format.md");
  const size_t start = doc.find("## Limits");
  const size_t end = doc.find("\n## ", start + 1);
  std::map<std::string, std::string> rows;
  if (start == std::string::npos) return rows;
  std::istringstream in(doc.substr(start, end - start));
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("| ", 0) != 0 || line.rfind("|---", 0) == 0 || line.rfind("| limit |", 0) == 0) continue;
    const size_t mid = line.find(" | ");
    rows[line.substr(2, mid - 2)] = line.substr(mid + 3, line.size() - mid - 5);
  }
  return rows;
}

// The numbers of a value cell, in order: "1 048 576" is one number (thin groups of three),
// "1 GiB" is 2^30, "64 MiB" 2^26; a backquoted constant name is skipped.
std::vector<double> numbers_in(std::string cell) {
  cell = std::regex_replace(cell, std::regex("`[^`]*`"), "");
  cell = std::regex_replace(cell, std::regex("(\\d) (?=\\d{3}\\b)"), "$1");
  std::vector<double> out;
  const std::regex number("(\\d+)( GiB| MiB)?");
  for (std::sregex_iterator it(cell.begin(), cell.end(), number), last; it != last; ++it) {
    double v = std::stod((*it)[1]);
    if ((*it)[2] == " GiB") v *= double(1u << 30);
    if ((*it)[2] == " MiB") v *= double(1u << 20);
    out.push_back(v);
  }
  return out;
}

TEST(SceneLimitsDoc, EveryRowOfTheTableMatchesTheLoadersConstants) {
  using namespace scene_read;  // NOLINT: the constants' namespace, inside this test only
  const std::map<std::string, std::vector<double>> expected = {
      {"scene file size", {double(kMaxSceneFileBytes)}},
      {"all buffers together", {double(kMaxTotalBufferBytes)}},
      {"JSON nesting depth", {double(kMaxJsonDepth)}},
      {"JSON values (bounds the parsed document's memory)", {double(kMaxJsonValues)}},
      {"nodes / meshes", {double(kMaxNodes)}},
      {"buffers / buffer views / accessors", {double(kMaxBuffers), double(kMaxBufferViews), double(kMaxAccessors)}},
      {"vertices read over all meshes (positions + normals + uvs)", {double(kMaxTotalVertices)}},
      {"indices read over all meshes", {double(kMaxTotalIndices)}},
      {"elements of a vertex accessor without a bufferView (zeros)", {double(kMaxZeroFilledElements)}},
      {"portal polygon corners / portal mesh triangles", {double(kMaxPortalVertices), double(kMaxPortalTriangles)}},
      {"texture width / height (checked from the image header)", {double(kMaxTextureSide), double(kMaxTextureSide)}},
      {"decoded textures together (RGBA8)", {double(kMaxTotalTexelBytes)}},
      {"timelines / keys per timeline", {double(kMaxTimelines), double(kMaxTimelineKeys)}},
      {"timeline length ((last t − first t) × fps)", {kMaxTimelineFrames}},
      {"timeline eye and target coordinates", {kMaxTimelineCoordinate}},
      {"standalone timeline file", {double(kMaxTimelineFileBytes)}},
  };
  ASSERT_EQ(kMaxMeshes, kMaxNodes) << "the table gives one number for nodes and meshes";
  const std::map<std::string, std::string> rows = limits_table();
  ASSERT_FALSE(rows.empty()) << "no limits table found in docs/scene-format.md";
  for (const auto& [label, value] : rows) {
    const auto it = expected.find(label);
    ASSERT_NE(it, expected.end()) << "row '" << label << "' has no constant in this test: add it";
    EXPECT_EQ(numbers_in(value), it->second) << "row '" << label << "': '" << value << "'";
  }
  EXPECT_EQ(rows.size(), expected.size()) << "a limit checked here is missing from the document's table";
}

// A timeline file of `keys` keys, each the smallest a key can be (10 JSON values).
std::string timeline_with_keys(size_t keys) {
  std::string text = "{\"name\":\"long\",\"fps\":1,\"keys\":[";
  text.reserve(keys * 40 + 64);
  for (size_t k = 0; k < keys; ++k) {
    text += k ? "," : "";
    text += "{\"t\":" + std::to_string(k) + ",\"eye\":[0,0,0],\"target\":[0,0,1]}";
  }
  return text + "]}";
}

TEST(SceneLimitsDoc, TheKeyLimitIsReachableAndEnforced) {
  const std::string dir = test::scratch_dir("limits_doc");
  for (const size_t keys : {scene_read::kMaxTimelineKeys, scene_read::kMaxTimelineKeys + 1}) {
    const std::string path = dir + "/keys_" + std::to_string(keys) + ".json";
    std::ofstream(path, std::ios::binary) << timeline_with_keys(keys);
    Timeline timeline;
    const Status s = load_timeline_file(path, timeline);
    if (keys == scene_read::kMaxTimelineKeys) {
      EXPECT_TRUE(s.ok()) << "the documented limit must be reachable: " << s.message();
      EXPECT_EQ(timeline.keys.size(), keys);
    } else {
      ASSERT_FALSE(s.ok());
      EXPECT_NE(s.message().find("more than " + std::to_string(scene_read::kMaxTimelineKeys) + " keys"),
                std::string::npos)
          << s.message();
    }
    std::remove(path.c_str());
  }
}

}  // namespace
}  // namespace lintel
