// `lintel import doom` as a user runs it: bad input is one line on stderr naming the file (and the
// map or lump), exit code 2, and no output file; with Freedoom installed, a map is written and
// `lintel validate` accepts it.
#include "map_pwad.h"
#include "run_process.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <vector>

namespace lintel {
namespace {

const char* const kWad = "/usr/share/games/doom/freedoom1.wad";

TEST(ImportDoomCli, BadWadOrMapExitsTwoWithOneLineAndNoFile) {
  const std::string dir = test::make_temp_dir();
  const std::string out = dir + "/out.glb";
  { std::ofstream(dir + "/short.wad") << "IWAD\x05"; }
  const std::string cases[][2] = {{dir + "/missing.wad", "missing.wad"}, {dir + "/short.wad", "header"}};
  for (const auto& c : cases) {
    const test::ProcessResult r =
        test::run_process(test::lintel_bin() + " import doom '" + c[0] + "' E1M1 -o '" + out + "'");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(c[1]), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
  }
  if (!std::filesystem::exists(kWad)) GTEST_SKIP() << kWad << " is missing (apt-get install freedoom)";
  const test::ProcessResult r =
      test::run_process(test::lintel_bin() + " import doom " + kWad + " E9M9 -o '" + out + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("map 'E9M9' not found"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(ImportDoomCli, FreedoomMapIsWrittenAndValidates) {
  if (!std::filesystem::exists(kWad)) GTEST_SKIP() << kWad << " is missing (apt-get install freedoom)";
  const std::string out = test::make_temp_dir() + "/e1m8.glb";
  const test::ProcessResult imported =
      test::run_process(test::lintel_bin() + " import doom " + kWad + " e1m8 -o '" + out + "'");
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  EXPECT_NE(imported.out.find("cells"), std::string::npos);
  const test::ProcessResult valid = test::run_process(test::lintel_bin() + " validate '" + out + "'");
  EXPECT_EQ(valid.exit_code, 0) << valid.err;
}

// A map the importer cannot represent is refused, not written: freedoom1's E2M8 (copied into a
// PWAD of its own) with vertex 0 moved to x = 32767 makes a portal that misses its cell's volume.
// One line naming the file, the map and the element, exit code 2, no file (before, the scene was
// written and refused at its next load).
TEST(ImportDoomCli, ImportedSceneTheLoaderRefusesIsNotWritten) {
  if (!std::filesystem::exists(kWad)) GTEST_SKIP() << kWad << " is missing (apt-get install freedoom)";
  std::ifstream in(kWad, std::ios::binary);
  const std::vector<uint8_t> wad{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::vector<uint8_t> pwad = test::map_pwad(wad, "E2M8");
  ASSERT_FALSE(pwad.empty());
  for (const test::PwadLump& lump : test::pwad_lumps(pwad))
    if (lump.name == "VERTEXES") pwad[lump.at] = 0xff, pwad[lump.at + 1] = 0x7f;  // vertex 0: x = 32767
  const std::string dir_path = test::make_temp_dir();
  std::ofstream(dir_path + "/moved.wad", std::ios::binary)
      .write(reinterpret_cast<const char*>(pwad.data()), std::streamsize(pwad.size()));
  const std::string out = dir_path + "/out.glb";
  const test::ProcessResult r =
      test::run_process(test::lintel_bin() + " import doom '" + dir_path + "/moved.wad' E2M8 -o '" + out + "'");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  for (const char* part : {"moved.wad: map E2M8: node ", "'line_", "nothing written"})
    EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// `lintel bench levels` reports the walk's teleporter jumps: on E3M5, whose doorway walk takes
// teleporters (docs/levels.md, "Timeline `doorway`"), one jump per teleporter the importer says the
// walk takes (each a frame whose eye moved beyond the tracker's jump distance), and its portal
// crossings apart from them.
TEST(BenchLevelsCli, ReportsTheWalksJumps) {
  if (!std::filesystem::exists(kWad)) GTEST_SKIP() << kWad << " is missing (apt-get install freedoom)";
  const std::string dir = test::make_temp_dir();
  const test::ProcessResult imported =
      test::run_process(test::lintel_bin() + " import doom " + kWad + " E3M5 -o '" + dir + "/e3m5.glb'");
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  std::smatch teleporters;
  ASSERT_TRUE(std::regex_search(imported.out, teleporters, std::regex("(\\d+) teleporters"))) << imported.out;
  const test::ProcessResult r = test::run_process(test::lintel_bin() + " bench levels --wad " + kWad +
                                                  " --maps E3M5 --views 4 --resolution 16 --out '" + dir + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(dir + "/levels.json");
  const std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::smatch jumps, crossings;
  ASSERT_TRUE(std::regex_search(json, jumps, std::regex("\"walk_jumps\":\\s*(\\d+)"))) << json.substr(0, 400);
  ASSERT_TRUE(std::regex_search(json, crossings, std::regex("\"walk_crossings\":\\s*(\\d+)")));
  EXPECT_GE(std::stoi(teleporters[1]), 1);
  EXPECT_EQ(std::stoi(jumps[1]), std::stoi(teleporters[1]));
  EXPECT_GT(std::stoi(crossings[1]), 0);
}

// `lintel bench levels` on a PWAD whose second map the importer refuses (E2M8 twice, the copy
// renamed E2M9 with vertex 0 moved as above): by default the failure ends the run (exit 2, one
// line naming the map, no levels.json); with --keep-going the good map is measured, the bad one is
// listed under failed_maps with the same message, and the run exits 0. Every map failing is still
// exit 2 with nothing written.
TEST(BenchLevelsCli, KeepGoingListsAFailedMapAndMeasuresTheRest) {
  if (!std::filesystem::exists(kWad)) GTEST_SKIP() << kWad << " is missing (apt-get install freedoom)";
  std::ifstream in(kWad, std::ios::binary);
  const std::vector<uint8_t> wad{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::vector<uint8_t> good = test::map_pwad(wad, "E2M8");
  ASSERT_FALSE(good.empty());
  std::vector<uint8_t> bad = good;
  test::rename_pwad_map(bad, "E2M9");
  for (const test::PwadLump& lump : test::pwad_lumps(bad))
    if (lump.name == "VERTEXES") bad[lump.at] = 0xff, bad[lump.at + 1] = 0x7f;  // vertex 0: x = 32767
  const std::string dir = test::make_temp_dir();
  for (const auto& [name, bytes] : {std::pair{"two.wad", test::join_pwads({good, bad})}, {"bad.wad", bad}})
    std::ofstream(dir + "/" + name, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  auto bench = [&](const std::string& wad_name, const std::string& out, const std::string& flags) {
    return test::run_process(test::lintel_bin() + " bench levels --wad '" + dir + "/" + wad_name +
                             "' --views 4 --resolution 16 --out '" + dir + "/" + out + "' " + flags);
  };
  const test::ProcessResult stop = bench("two.wad", "stop", "");
  EXPECT_EQ(stop.exit_code, 2) << stop.err;
  EXPECT_EQ(test::count_lines(stop.err), 1) << stop.err;
  EXPECT_NE(stop.err.find("map E2M9"), std::string::npos) << stop.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/stop/levels.json"));

  const test::ProcessResult going = bench("two.wad", "going", "--keep-going --optimize");
  ASSERT_EQ(going.exit_code, 0) << going.err;
  EXPECT_EQ(test::count_lines(going.err), 1) << going.err;
  std::ifstream report(dir + "/going/levels.json");
  const std::string json((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
  // E2M8 measured imported and optimized; E2M9 listed once, with the error stderr gave.
  const std::regex measured("\"map\":\\s*\"E2M8\"");
  EXPECT_EQ(std::distance(std::sregex_iterator(json.begin(), json.end(), measured), std::sregex_iterator()), 2)
      << json.substr(0, 400);
  const size_t listed = json.find("\"failed_maps\"");
  ASSERT_NE(listed, std::string::npos);
  EXPECT_NE(json.find("\"E2M9\"", listed), std::string::npos);
  EXPECT_EQ(json.find("\"E2M9\""), json.find("\"E2M9\"", listed)) << "E2M9 measured as well as failed";
  const std::string reason = going.err.substr(going.err.find("map E2M9"), 30);
  EXPECT_NE(json.find(reason, listed), std::string::npos) << reason;

  const test::ProcessResult none = bench("bad.wad", "none", "--keep-going");
  EXPECT_EQ(none.exit_code, 2) << none.err;
  EXPECT_NE(none.err.find("every map failed"), std::string::npos) << none.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/none/levels.json"));
}

// `lintel optimize` and `import doom --optimize`: a missing or broken scene is one line, exit 2, no
// output; a map optimized either way validates and has fewer cells than the plain import.
TEST(OptimizeCli, BadSceneExitsTwoAndAMapOptimizedEitherWayValidates) {
  const std::string dir = test::make_temp_dir();
  { std::ofstream(dir + "/broken.glb") << "glTF not really"; }
  for (const char* input : {"missing.glb", "broken.glb"}) {
    const test::ProcessResult r =
        test::run_process(test::lintel_bin() + " optimize '" + dir + "/" + input + "' -o '" + dir + "/out.glb'");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(input), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir + "/out.glb"));
  }
  if (!std::filesystem::exists(kWad)) GTEST_SKIP() << kWad << " is missing (apt-get install freedoom)";
  const std::string plain = dir + "/e1m8.glb", merged = dir + "/e1m8_opt.glb", direct = dir + "/e1m8_direct.glb";
  ASSERT_EQ(test::run_process(test::lintel_bin() + " import doom " + kWad + " E1M8 -o '" + plain + "'").exit_code, 0);
  const test::ProcessResult optimized =
      test::run_process(test::lintel_bin() + " optimize '" + plain + "' -o '" + merged + "'");
  ASSERT_EQ(optimized.exit_code, 0) << optimized.err;
  EXPECT_NE(optimized.out.find("cells ->"), std::string::npos) << optimized.out;
  const test::ProcessResult imported =
      test::run_process(test::lintel_bin() + " import doom " + kWad + " E1M8 --optimize -o '" + direct + "'");
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  EXPECT_NE(imported.out.find("optimized: "), std::string::npos) << imported.out;
  for (const std::string& file : {merged, direct}) {
    const test::ProcessResult info = test::run_process(test::lintel_bin() + " validate '" + file + "'");
    EXPECT_EQ(info.exit_code, 0) << file << ": " << info.err;
  }
  // Both ways give the same file content (the same merge of the same World).
  std::ifstream a(merged, std::ios::binary), b(direct, std::ios::binary);
  const std::string bytes_a((std::istreambuf_iterator<char>(a)), {}), bytes_b((std::istreambuf_iterator<char>(b)), {});
  EXPECT_TRUE(bytes_a == bytes_b) << bytes_a.size() << " vs " << bytes_b.size() << " bytes";
}

}  // namespace
}  // namespace lintel
