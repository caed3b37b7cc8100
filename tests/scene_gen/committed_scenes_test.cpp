// The scenes committed in scenes/ are exactly what `lintel gen` makes today: each manifest line
// "<file> <gen arguments>" is regenerated into a temporary directory and compared byte for byte
// (the .gltf and its .bin). A generator change that moves a byte must regenerate the scenes.
#include "run_process.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct Entry {
  std::string file, args;
};

std::vector<Entry> manifest() {
  std::vector<Entry> out;
  std::ifstream in(fs::path(LINTEL_SOURCE_DIR) / "scenes" / "manifest.txt");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const size_t space = line.find(' ');
    out.push_back({line.substr(0, space), space == std::string::npos ? "" : line.substr(space + 1)});
  }
  return out;
}

TEST(CommittedScenes, ManifestListsEveryScene) {
  const std::vector<Entry> entries = manifest();
  ASSERT_FALSE(entries.empty());
  for (const auto& f : fs::directory_iterator(fs::path(LINTEL_SOURCE_DIR) / "scenes")) {
    const std::string ext = f.path().extension().string();
    if (ext != ".gltf" && ext != ".glb") continue;
    const std::string name = f.path().filename().string();
    EXPECT_TRUE(std::any_of(entries.begin(), entries.end(), [&](const Entry& e) { return e.file == name; }))
        << name << " is not in scenes/manifest.txt";
  }
}

TEST(CommittedScenes, RegenerateByteIdentical) {
  const fs::path scenes = fs::path(LINTEL_SOURCE_DIR) / "scenes";
  const std::string dir = lintel::test::make_temp_dir();
  for (const Entry& e : manifest()) {
    SCOPED_TRACE(e.file + ": lintel " + e.args);
    const fs::path out = fs::path(dir) / e.file;
    const auto r = lintel::test::run_process(lintel::test::lintel_bin() + " " + e.args + " -o '" + out.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(read_bytes(out) == read_bytes(scenes / e.file))
        << "differs: regenerate with scripts/run " << e.args << " -o scenes/" << e.file;
    if (out.extension() == ".gltf") {
      const std::string bin = out.stem().string() + ".bin";
      ASSERT_TRUE(fs::exists(scenes / bin)) << bin;
      EXPECT_TRUE(read_bytes(fs::path(dir) / bin) == read_bytes(scenes / bin)) << bin << " differs";
    }
  }
  fs::remove_all(dir);
}

}  // namespace
