// The simple JSON parser (scene/src/read/json_simple_parse.h), the loader's fast path, against
// nlohmann's json::parse, which it stands in for: where it accepts a text, the same DOM; where
// nlohmann refuses one, it declines too (the loader then gets nlohmann's message); and it does
// accept every committed scene and an imported level, so that loading them takes the fast path.
#include "read/json_bounded.h"
#include "read/json_simple_parse.h"

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

// The simple parser with nlohmann's own DOM builder as its handler. True when it accepted.
bool simple_parse(const std::string& text, json& out) {
  nlohmann::detail::json_sax_dom_parser<json> builder(out);
  return parse_simple_json(text.data(), text.size(), builder, kMaxJsonDepth, kMaxJsonValues);
}

std::string json_text_of(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (bytes.size() >= 20 && std::memcmp(bytes.data(), "glTF", 4) == 0) {
    uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);
    return bytes.substr(20, length);
  }
  return bytes;
}

// Property: whenever the simple parser accepts a text, nlohmann parses it too, into an equal DOM
// with the same value types (an unsigned integer stays unsigned, a float stays a float); whenever
// nlohmann refuses a text, the simple parser declines it. Returns whether it accepted.
bool expect_agrees_with_nlohmann(const std::string& text, const std::string& label) {
  json simple, reference;
  const bool accepted = simple_parse(text, simple);
  bool parsed = true;
  try {
    reference = json::parse(text);
  } catch (const json::exception&) {
    parsed = false;
  }
  if (!parsed) {
    EXPECT_FALSE(accepted) << label << ": accepted a text nlohmann refuses";
    return accepted;
  }
  if (accepted) {
    EXPECT_EQ(simple, reference) << label;
    EXPECT_EQ(simple.dump(), reference.dump()) << label;  // dump() spells the value types apart
  }
  return accepted;
}

TEST(JsonSimpleParse, NumbersFollowNlohmannsRules) {
  // Accepted, as nlohmann reads them: unsigned, negative integers, floats rounded as strtod does.
  for (const char* text : {"0", "-0", "7", "18446744073709551615", "-9223372036854775808", "0.1", "-1.5e-3", "1E+2",
                           "1e2", "2.5E-308", "1.7976931348623157e308", "[1, -2, 3.25, 4e0]", "4.9e-324"})
    EXPECT_TRUE(expect_agrees_with_nlohmann(text, text)) << text;
  // Declined: malformed, or where nlohmann turns an integer into a float or refuses an overflow.
  for (const char* text : {"01", "1.", ".5", "+1", "-", "1e", "1e+", "18446744073709551616", "-9223372036854775809",
                           "1e400", "-1e400", "0x10", "1 2", "NaN", "Infinity"})
    EXPECT_FALSE(expect_agrees_with_nlohmann(text, text)) << text;
}

TEST(JsonSimpleParse, StringsLiteralsAndStructure) {
  for (const char* text : {R"("plain ascii, with spaces")", R"({"a": [true, false, null], "b": {}})", " \t\r\n[ ] ",
                           R"({"k": 1, "k": 2})", R"([[[]], {"x": [{}]}])", R"("")", R"({"": ""})"})
    EXPECT_TRUE(expect_agrees_with_nlohmann(text, text)) << text;
  // Escapes, bytes >= 0x80 and control characters are nlohmann's to decode and check.
  for (const char* text : {R"("a\nb")", R"("\u00e9")", "\"\xc3\xa9\"", "\"\x01\"", "\"\xff\"", "\xef\xbb\xbf{}", "",
                           "tru", "nul", "{\"a\" 1}", "{\"a\": 1,}", "[1,]", "{1: 2}", "[1 2]", "{} {}", "\"open"})
    EXPECT_FALSE(expect_agrees_with_nlohmann(text, text)) << text;
}

// The limits: text beyond them is declined (the loader then reports them as json_bounded.h does).
TEST(JsonSimpleParse, DeclinesTextBeyondTheLimits) {
  const std::string deepest = std::string(kMaxJsonDepth, '[') + std::string(kMaxJsonDepth, ']');
  const std::string too_deep = "[" + deepest + "]";
  json out;
  EXPECT_TRUE(simple_parse(deepest, out));
  EXPECT_FALSE(simple_parse(too_deep, out));
  nlohmann::detail::json_sax_dom_parser<json> builder(out);
  EXPECT_TRUE(parse_simple_json("[1, 2]", 6, builder, kMaxJsonDepth, 3));  // 1 + '[' + ',' = 3 values
  nlohmann::detail::json_sax_dom_parser<json> builder2(out);
  EXPECT_FALSE(parse_simple_json("[1, 2]", 6, builder2, kMaxJsonDepth, 2));
}

TEST(JsonSimpleParse, AcceptsEveryCommittedSceneAndAgreesOnCutsAndBreaks) {
  size_t documents = 0;
  for (const std::string& root : {std::string(LINTEL_SOURCE_DIR) + "/scenes", test::fixture("good")}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
      const std::string ext = entry.path().extension().string();
      if (ext != ".gltf" && ext != ".glb") continue;
      EXPECT_TRUE(expect_agrees_with_nlohmann(json_text_of(entry.path()), entry.path().string())) << entry.path();
      ++documents;
    }
  }
  EXPECT_GT(documents, 10u);
  const std::string text = json_text_of(std::string(LINTEL_SOURCE_DIR) + "/scenes/cottage.gltf");
  for (size_t cut = 0; cut < text.size(); cut += cut < 2048 ? 1 : 1499)
    expect_agrees_with_nlohmann(text.substr(0, cut), "cut at " + std::to_string(cut));
  for (size_t at = 0; at < 2048; at += 5) {
    std::string broken = text;
    broken[at] = "},]:\"0-e."[at % 9];
    expect_agrees_with_nlohmann(broken, "broken at " + std::to_string(at));
  }
}

TEST(JsonSimpleParse, AcceptsAnImportedDoomLevel) {
  if (!test::freedoom_installed()) GTEST_SKIP() << test::kFreedoomWad << " not installed (Debian package freedoom)";
  std::vector<uint8_t> glb;
  ASSERT_TRUE(test::imported_level_glb("E1M5", glb));
  uint32_t length = 0;
  std::memcpy(&length, glb.data() + 12, 4);
  EXPECT_TRUE(expect_agrees_with_nlohmann(std::string(reinterpret_cast<const char*>(glb.data()) + 20, length), "E1M5"));
}

}  // namespace
}  // namespace lintel::scene_read
