// Command lines as a hostile user types them: each must exit 2 (bad input) with
// exactly one stderr line and leave the file system as it was apart from the requested output.
// Outputs never replace a device, FIFO, directory or symlink, nor an existing "<out>.tmp"; scene
// URIs stay inside the scene's folder; names reach the terminal escaped.
#include "run_process.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

namespace lintel::test {
namespace {

namespace fs = std::filesystem;

const std::string kCottage = std::string(LINTEL_SOURCE_DIR) + "/scenes/cottage.gltf";
const std::string kFixtures = std::string(LINTEL_SOURCE_DIR) + "/tests/scene/fixtures/";

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_text(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// Everything under `dir`: relative path -> type, size (regular files) and link target.
std::map<std::string, std::string> snapshot(const std::string& dir) {
  std::map<std::string, std::string> out;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec); it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    const fs::file_status st = it->symlink_status();
    std::string what = std::to_string(int(st.type()));
    if (fs::is_regular_file(st)) what += " " + std::to_string(fs::file_size(it->path()));
    if (fs::is_symlink(st)) what += " -> " + fs::read_symlink(it->path()).string();
    out[fs::relative(it->path(), dir).string()] = what;
  }
  return out;
}

struct Hostile {
  std::string args;    // after "lintel", run with the scratch folder as the working directory
  std::string needle;  // the fault the one line must name
  int exit_code = 2;
};

// Runs each case in `dir` and checks exit code, exactly one "lintel: error:" line naming the fault,
// and an unchanged folder.
void expect_refused(const std::string& dir, const std::vector<Hostile>& cases) {
  for (const Hostile& c : cases) {
    const auto before = snapshot(dir);
    const ProcessResult r = run_process("cd '" + dir + "' && " + lintel_bin() + " " + c.args);
    EXPECT_EQ(r.exit_code, c.exit_code) << c.args << "\n" << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << c.args << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("lintel: error: ", 0), 0u) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.needle), std::string::npos) << c.args << "\nexpected '" << c.needle << "' in\n" << r.err;
    EXPECT_EQ(snapshot(dir), before) << c.args << ": the file system changed";
  }
}

TEST(CliHostile, NumbersAreCheckedAndEveryErrorIsOneLine) {
  const std::string dir = make_temp_dir();
  const std::string render = "render " + kCottage + " --time 5 --width 64 --height 36 --out x.png ";
  expect_refused(dir, {
                          {render + "--probe-spacing nan", "--probe-spacing"},
                          {render + "--exposure nan", "--exposure"},
                          {render + "--exposure inf", "--exposure"},
                          {render + "--exposure 1e30", "--exposure"},
                          {render + "--exposure -1", "--exposure"},
                          {"render " + kCottage + " --time nan --out x.png", "--time"},
                          {"render " + kCottage + " --time 5 --fov nan --out x.png", "--fov"},
                          {"bench cull --no-gpu --threads 100000", "--threads"},
                          {"bench cull --no-gpu --instances 0", "--instances"},
                          {"vis " + kCottage + " --eye 0,1.6,0 --target 1,1.6,0 --bogus", "--bogus"},
                          {"vis " + kCottage + " --eye 0,1.6,0 --target 1,1.6,0 --near nan", "--near"},
                          {"vis " + kCottage + " --eye 0,1.6,0 --target 1,1.6,0 --aspect inf", "--aspect"},
                          {"gen random --cells 8 --extra-portals nan -o r.glb", "--extra-portals"},
                          {"walk " + kCottage + " --max-memory lots", "--max-memory"},
                          {"frobnicate", "frobnicate"},
                      });
  fs::remove_all(dir);
}

// A timeline whose eye is far away is reported as far away (not as "eye and target coincide"),
// and a frame count over the limit is printed exactly.
TEST(CliHostile, TimelineFaultsAreNamedExactly) {
  const std::string dir = make_temp_dir();
  write_text(
      dir + "/far.json",
      R"({"name":"far","keys":[{"t":0,"eye":[3e38,0,0],"target":[0,0,0]},{"t":1,"eye":[-3e38,0,0],"target":[0,0,0]}]})");
  write_text(dir + "/long.json", R"({"name":"long","fps":1000,"keys":[{"t":0,"eye":[0,1,0],"target":[1,1,0]},)"
                                 R"({"t":100000,"eye":[0,1,0],"target":[1,1,0]}]})");
  write_text(dir + "/many.json", R"({"name":"many","fps":60,"keys":[{"t":0,"eye":[0,1.6,0],"target":[1,1.6,0]},)"
                                 R"({"t":10000,"eye":[0,1.6,0],"target":[1,1.6,0]}]})");
  expect_refused(
      dir,
      {
          {"walk " + kCottage + " -q --timeline-file far.json", "farther than 1000000 m"},
          {"walk " + kCottage + " -q --timeline-file long.json", "spans 100000000 frames, over the limit of 1000000"},
          {"walk " + kCottage + " -q --timeline-file many.json --max-memory 16M", "600001 frames need about"},
      });
  fs::remove_all(dir);
}

// Outputs: a device, a FIFO, a directory and a symlink are refused (before any work); an existing
// "<out>.tmp" is left alone while the output itself is written; the link's target may be written.
TEST(CliHostile, OutputsReplaceOnlyRegularFiles) {
  const std::string dir = make_temp_dir();
  ASSERT_EQ(::mkfifo((dir + "/fifo.glb").c_str(), 0600), 0);
  fs::create_directory(dir + "/folder.glb");
  write_text(dir + "/target.glb", "old");
  fs::create_symlink("target.glb", dir + "/link.glb");
  fs::create_symlink("target.png", dir + "/link.png");
  expect_refused(
      dir,
      {
          {"gen cottage -o /dev/null", "/dev/null"},
          {"gen cottage -o fifo.glb", "fifo.glb: is a FIFO"},
          {"gen cottage -o folder.glb", "folder.glb"},
          {"gen cottage -o link.glb", "is a symbolic link to 'target.glb'"},
          {"render " + kCottage + " --time 5 --width 16 --height 16 --out /dev/null", "is a character device"},
          {"render " + kCottage + " --time 5 --width 16 --height 16 --out link.png", "symbolic link"},
          {"bench cull --no-gpu --instances 1000 --repetitions 1 --out fifo.glb", "is a FIFO"},
          {"walk " + kCottage + " -q --every 1000 --width 16 --height 16 --frames link.glb", "is a symbolic link"},
          {"walk " + kCottage + " -q --every 1000 --width 16 --height 16 --frames target.glb", "is not a directory"},
      });
  EXPECT_EQ(read_text(dir + "/target.glb"), "old");

  // The link's target, named directly, is an ordinary output.
  ProcessResult r = run_process("cd '" + dir + "' && " + lintel_bin() + " gen cottage -o target.glb");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(fs::file_size(dir + "/target.glb"), 1000u);
  EXPECT_TRUE(fs::is_symlink(dir + "/link.glb"));

  // An existing temporary of the old scheme is never clobbered, and no temporary is left behind.
  write_text(dir + "/scene.gltf.tmp", "mine");
  write_text(dir + "/scene.bin.tmp", "mine too");
  r = run_process("cd '" + dir + "' && " + lintel_bin() + " gen grid --width 2 --height 2 -o scene.gltf");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_text(dir + "/scene.gltf.tmp"), "mine");
  EXPECT_EQ(read_text(dir + "/scene.bin.tmp"), "mine too");
  EXPECT_TRUE(fs::exists(dir + "/scene.bin"));
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find(".tmp."), std::string::npos) << "left behind: " << e.path();
  fs::remove_all(dir);
}

// A copy of a fixture .gltf with buffer 0's uri and byteLength replaced.
void scene_with_buffer(const std::string& path, const std::string& uri, uintmax_t byte_length) {
  nlohmann::json doc = nlohmann::json::parse(read_text(kFixtures + "good/three_rooms_external.gltf"));
  doc["buffers"][0]["uri"] = uri;
  doc["buffers"][0]["byteLength"] = byte_length;
  write_text(path, doc.dump());
}

// Buffer URIs resolve inside the scene's folder only: "..", its percent-encoded form and a symlink
// out of the folder are refused by default (the file states /etc/passwd's exact size, so before
// this rule it loaded); --allow-outside-paths lifts the rule.
TEST(CliHostile, UrisStayInsideTheScenesFolder) {
  const std::string dir = make_temp_dir();
  fs::create_directory(dir + "/scene");
  const uintmax_t passwd = fs::file_size("/etc/passwd");
  scene_with_buffer(dir + "/scene/dotdot.gltf", "../../../../../../../../etc/passwd", passwd);
  scene_with_buffer(dir + "/scene/encoded.gltf", "%2e%2e/%2e%2e/%2e%2e/%2e%2e/%2e%2e/%2e%2e/%2e%2e/%2e%2e/etc%2fpasswd",
                    passwd);
  fs::create_symlink("/etc/passwd", dir + "/scene/escape.bin");
  scene_with_buffer(dir + "/scene/symlink.gltf", "escape.bin", passwd);
  scene_with_buffer(dir + "/scene/nul.gltf", "three%00rooms.bin", passwd);
  expect_refused(dir, {
                          {"validate scene/dotdot.gltf", "outside the scene's folder"},
                          {"validate scene/encoded.gltf", "outside the scene's folder"},
                          {"validate scene/symlink.gltf", "outside the scene's folder"},
                          {"validate scene/nul.gltf", "NUL"},
                      });
  // Allowed, the file is read (and then fails as a buffer of the wrong content, not as a path).
  const ProcessResult r = run_process(lintel_bin() + " validate --allow-outside-paths " + dir + "/scene/dotdot.gltf");
  EXPECT_EQ(r.err.find("outside the scene's folder"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

// Budgets: a scene whose buffer is larger than --max-memory is refused from the file's size
// (sparse, so the test costs no disk), and a render whose GI would need too many surfels or
// too much memory is refused before the GPU is touched.
TEST(CliHostile, BudgetsRefuseWorkBeforeAllocating) {
  const std::string dir = make_temp_dir();
  const uintmax_t gib = uintmax_t{1} << 30;
  {
    std::ofstream(dir + "/big.bin").close();
    fs::resize_file(dir + "/big.bin", gib);
  }
  scene_with_buffer(dir + "/big.gltf", "big.bin", gib);
  ProcessResult ring = run_process(lintel_bin() + " gen ring --cells 1024 -o " + dir + "/ring.glb");
  ASSERT_EQ(ring.exit_code, 0) << ring.err;
  expect_refused(dir, {
                          {"validate big.gltf --max-memory 64M", "over the memory budget of 67108864 bytes"},
                          {"render ring.glb --eye 0,1.6,0 --target 1,1.6,0 --surfels 65536 --out x.png",
                           "GI surfels, over the limit"},
                          {"render " + kCottage + " --time 5 --max-memory 1M --out x.png", "--max-memory budget"},
                      });
  fs::remove_all(dir);
}

// Names reach the terminal escaped; a NUL in a name is refused by the loader.
TEST(CliHostile, NamesAreEscapedAndNulIsRefused) {
  const std::string dir = make_temp_dir();
  nlohmann::json doc = nlohmann::json::parse(read_text(kFixtures + "good/two_rooms_minimal.gltf"));
  const std::string hostile = "West\nlintel: error: fake\x1b[31m";
  doc["nodes"][0]["name"] = hostile;
  doc["nodes"][0]["extras"]["lintel"]["cell"] = hostile;
  doc["nodes"][2]["extras"]["lintel"]["portal"]["from"] = hostile;
  write_text(dir + "/names.gltf", doc.dump());
  const ProcessResult r = run_process(lintel_bin() + " info " + dir + "/names.gltf");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("West\\nlintel: error: fake\\x1b[31m"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find('\x1b'), std::string::npos);
  EXPECT_EQ(r.out.find("\nlintel: error"), std::string::npos);

  doc["nodes"][1]["name"] = std::string("Ea\0st", 5);
  write_text(dir + "/nul.gltf", doc.dump());
  expect_refused(dir, {{"info nul.gltf", "NUL"}});
  fs::remove_all(dir);
}

}  // namespace
}  // namespace lintel::test
