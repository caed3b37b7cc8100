// `lintel import doom` as a user runs it: bad input is one line on stderr naming the file (and the
// map or lump), exit code 2, and no output file; with Freedoom installed, a map is written and
// `lintel validate` accepts it.
#include "run_process.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

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

}  // namespace
}  // namespace lintel
