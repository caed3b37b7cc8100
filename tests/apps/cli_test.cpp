// The `lintel` CLI as a user meets it: help, version, exit codes, one-line errors, and the
// cottage summary the foundation issue promises (>= 7 cells, >= 2 cycles, non-identity cells,
// shared meshes, lights, a timeline).
#include "run_process.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace lintel::test {
namespace {

const std::string kCottage = std::string(LINTEL_SOURCE_DIR) + "/scenes/cottage.gltf";

TEST(Cli, VersionPrintsNameAndFormat) {
  ProcessResult r = run_process(lintel_bin() + " --version");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("lintel "), std::string::npos);
  EXPECT_NE(r.out.find("scene format 1"), std::string::npos);
}

TEST(Cli, HelpListsEverySubcommand) {
  ProcessResult r = run_process(lintel_bin() + " --help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* cmd : {"info", "validate", "gen", "vis", "walk", "cull", "bench"}) EXPECT_NE(r.out.find(cmd), std::string::npos) << cmd;
  for (const char* cmd : {"info", "validate", "gen cottage", "gen grid", "gen ring", "gen random", "vis", "walk",
                          "cull", "bench cull"}) {
    ProcessResult sub = run_process(lintel_bin() + " " + cmd + " --help");
    EXPECT_EQ(sub.exit_code, 0) << cmd;
    EXPECT_NE(sub.out.find("Usage"), std::string::npos) << cmd;
  }
}

TEST(Cli, UnknownSubcommandIsBadInput) {
  ProcessResult r = run_process(lintel_bin() + " frobnicate");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("lintel: error: ", 0), 0u) << r.err;
}

TEST(Cli, MissingSceneIsOneLineErrorNamingTheFile) {
  ProcessResult r = run_process(lintel_bin() + " info /nonexistent/dir/house.gltf");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("/nonexistent/dir/house.gltf"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
}

TEST(Cli, ValidateAcceptsTheDefaultScene) {
  ProcessResult r = run_process(lintel_bin() + " validate " + kCottage);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("valid"), std::string::npos);
}

bool is_identity(const nlohmann::json& m) {
  for (int i = 0; i < 16; ++i)
    if (std::abs(m[i].get<double>() - ((i % 5 == 0) ? 1.0 : 0.0)) > 1e-6) return false;
  return true;
}

TEST(Cli, InfoJsonDescribesTheCottage) {
  ProcessResult r = run_process(lintel_bin() + " info --json " + kCottage);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json info = nlohmann::json::parse(r.out);
  EXPECT_GE(info["counts"]["cells"].get<int>(), 7);
  EXPECT_GE(info["portal_graph_cycles"].get<int>(), 2);
  for (const auto& cell : info["cells"]) {
    EXPECT_FALSE(is_identity(cell["cell_to_world"])) << cell["name"];
    EXPECT_FALSE(cell["identity_transform"].get<bool>()) << cell["name"];
  }
  int shared_groups = 0;
  for (const auto& group : info["draw_groups"]) shared_groups += group["instances"].get<int>() >= 2;
  EXPECT_GE(shared_groups, 1);
  EXPECT_GE(info["counts"]["lights"].get<int>(), 2);
  EXPECT_GE(info["counts"]["timelines"].get<int>(), 1);
  EXPECT_EQ(info["portals"].size(), info["counts"]["portals"].get<size_t>());
}

TEST(Cli, InfoTextNamesEveryCell) {
  ProcessResult json_run = run_process(lintel_bin() + " info --json " + kCottage);
  ASSERT_EQ(json_run.exit_code, 0);
  ProcessResult text = run_process(lintel_bin() + " info " + kCottage);
  ASSERT_EQ(text.exit_code, 0);
  for (const auto& cell : nlohmann::json::parse(json_run.out)["cells"])
    EXPECT_NE(text.out.find(cell["name"].get<std::string>()), std::string::npos);
}

TEST(Cli, GenIsDeterministicAndValid) {
  const std::string dir = make_temp_dir();
  for (const char* name : {"a.gltf", "b.gltf"})
    ASSERT_EQ(run_process(lintel_bin() + " gen random --seed 7 --cells 9 -o " + dir + "/" + name).exit_code, 0);
  auto slurp = [](const std::string& p) {
    std::ifstream f(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), {});
  };
  EXPECT_EQ(slurp(dir + "/a.bin"), slurp(dir + "/b.bin"));
  EXPECT_FALSE(slurp(dir + "/a.bin").empty());
  EXPECT_EQ(run_process(lintel_bin() + " validate " + dir + "/a.gltf").exit_code, 0);
  ASSERT_EQ(run_process(lintel_bin() + " gen grid --width 3 --height 2 -o " + dir + "/g.glb").exit_code, 0);
  ProcessResult info = run_process(lintel_bin() + " info --json " + dir + "/g.glb");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_EQ(nlohmann::json::parse(info.out)["counts"]["cells"].get<int>(), 6);
  std::filesystem::remove_all(dir);
}

TEST(Cli, GenIntoMissingDirectoryFailsWithoutPartialFiles) {
  const std::string dir = make_temp_dir();
  ProcessResult r = run_process(lintel_bin() + " gen cottage -o " + dir + "/missing/sub/c.gltf");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/missing"));
  std::filesystem::remove_all(dir);
}

TEST(Cli, GenRejectsOutOfRangeSizes) {
  ProcessResult r = run_process(lintel_bin() + " gen grid --width 0 --height 3 -o /tmp/never.gltf");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_FALSE(std::filesystem::exists("/tmp/never.gltf"));
}

// The doorway timeline of the default scene: the tracker switches cell exactly at each portal
// crossing (the walk counts crossings geometrically, independently of the tracker) and never flaps.
TEST(Cli, WalkOfTheCottageTransitionsAtEachDoorwayAndNeverFlaps) {
  ProcessResult r = run_process(lintel_bin() + " walk --json-lines " + kCottage);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream lines(r.out);
  std::string line, last;
  int frames = 0, crossing_transitions = 0;
  while (std::getline(lines, line)) {
    last = line;
    const nlohmann::json j = nlohmann::json::parse(line);
    if (j.contains("summary")) break;
    ++frames;
    const std::string moves = j["transitions"].get<std::string>();
    if (j["frame"].get<int>() > 0 && !moves.empty()) {
      EXPECT_NE(moves.find("(portal crossing)"), std::string::npos) << "frame " << j["frame"] << ": " << moves;
      ++crossing_transitions;
    }
    EXPECT_LE(j["stats"]["pops"].get<int>(), j["stats"]["pop_bound"].get<int>());
  }
  const nlohmann::json summary = nlohmann::json::parse(last)["summary"];
  EXPECT_EQ(summary["frames"].get<int>(), frames);
  EXPECT_EQ(summary["flaps"].get<int>(), 0);
  EXPECT_GE(summary["portal_crossings"].get<int>(), 5);
  EXPECT_EQ(summary["transitions"].get<int>(), summary["portal_crossings"].get<int>());
  EXPECT_EQ(crossing_transitions, summary["transitions"].get<int>());
  EXPECT_EQ(summary["cap_hits"].get<int>(), 0);
}

TEST(Cli, WalkRejectsABadTimelineFile) {
  const std::string dir = make_temp_dir();
  std::ofstream(dir + "/t.json") << R"({"name": "x", "fps": 0, "keys": [{"t": 0, "eye": [0,1,0], "target": [0,1,-1]}]})";
  ProcessResult r = run_process(lintel_bin() + " walk " + kCottage + " --timeline-file " + dir + "/t.json");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("t.json"), std::string::npos) << r.err;
  ProcessResult missing = run_process(lintel_bin() + " walk " + kCottage + " --timeline nosuch");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("nosuch"), std::string::npos) << missing.err;
  std::filesystem::remove_all(dir);
}

TEST(Cli, VisFromTheFrontGardenSeesIntoTheHouseThroughItsOpenings) {
  ProcessResult r = run_process(lintel_bin() + " vis --json --eye 0,1.6,8 --target 0,1.6,0 " + kCottage);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["viewer_cell"], "outside");
  ASSERT_GE(j["visible_cells"].size(), 2u);
  for (const auto& c : j["visible_cells"]) {
    EXPECT_FALSE(c["region_ndc"].empty()) << c["cell"];
    for (const auto& poly : c["region_ndc"]) EXPECT_GE(poly.size(), 3u);
  }
}

TEST(Cli, VisRejectsABadCameraWithExitTwo) {
  for (const char* args : {"--eye 1,2 --target 0,0,0", "--eye 0,1,0 --target 0,1,0", "--eye nan,1,0 --target 0,0,0"}) {
    ProcessResult r = run_process(lintel_bin() + " vis " + kCottage + " " + args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(count_lines(r.err), 1) << args << ": " << r.err;
  }
}

// The GPU pass (lavapipe in CI) and the CPU reference agree command for command on the cottage.
TEST(Cli, CullOnTheGpuDrawsExactlyWhatTheCpuReferenceDraws) {
  for (const char* view : {"--eye 0,1.6,8 --target 0,1.6,0", "--eye 0.5,1.6,2 --target -3,1.2,-2"}) {
    ProcessResult gpu = run_process(lintel_bin() + " cull --json --gpu " + kCottage + " " + view);
    ProcessResult cpu = run_process(lintel_bin() + " cull --json --cpu " + kCottage + " " + view);
    ASSERT_EQ(gpu.exit_code, 0) << gpu.err;
    ASSERT_EQ(cpu.exit_code, 0) << cpu.err;
    const nlohmann::json g = nlohmann::json::parse(gpu.out), c = nlohmann::json::parse(cpu.out);
    EXPECT_EQ(g["groups"], c["groups"]) << view;
    EXPECT_EQ(g["visible_cells"], c["visible_cells"]) << view;
    int first_instance_nonzero = 0;
    for (const auto& group : g["groups"]) first_instance_nonzero += group["command"]["firstInstance"].get<int>() > 0;
    EXPECT_GE(first_instance_nonzero, 1);
  }
}

}  // namespace
}  // namespace lintel::test
