// The `lintel` CLI as a user meets it: help, version, exit codes, one-line errors, and the
// cottage summary the foundation issue promises (>= 7 cells, >= 2 cycles, non-identity cells,
// shared meshes, lights, a timeline).
#include "run_process.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

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
  for (const char* cmd :
       {"info", "validate", "gen", "vis", "walk", "cull", "render", "bench", "import", "export", "optimize", "view"})
    EXPECT_NE(r.out.find(cmd), std::string::npos) << cmd;
  for (const char* cmd : {"info", "validate", "gen cottage", "gen grid", "gen ring", "gen random", "vis", "walk",
                          "cull", "render", "bench cull", "bench render"}) {
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

// `validate -q` prints nothing on success, warnings included; without it the warnings go to
// stderr beside the one-line summary on stdout.
TEST(Cli, ValidateQuietPrintsNothingForAValidSceneWithWarnings) {
  const std::string scene = std::string(LINTEL_SOURCE_DIR) + "/tests/scene/fixtures/warn/cell_without_portals.gltf";
  const ProcessResult loud = run_process(lintel_bin() + " validate " + scene);
  ASSERT_EQ(loud.exit_code, 0) << loud.err;
  EXPECT_NE(loud.err.find("warning"), std::string::npos) << "the fixture should warn: " << loud.err;
  const ProcessResult quiet = run_process(lintel_bin() + " validate -q " + scene);
  EXPECT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_TRUE(quiet.out.empty()) << quiet.out;
  EXPECT_TRUE(quiet.err.empty()) << quiet.err;
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
  for (const nlohmann::json info = nlohmann::json::parse(json_run.out);
       const auto& cell : info["cells"])  // C++20: the parsed document outlives the loop
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

// A door closing in front of the camera: on the doorway walk's path to the front door, looking
// through it into the hall, the front door closes at t = 0.5 s (frame 5 at 10 fps). Every frame before it sees the same cells; from
// that frame on, the cells seen only through the door are gone; the summary counts the event.
// An unknown portal name in an event is bad input: one line, exit 2.
TEST(Cli, WalkAppliesADoorEventOnItsFrame) {
  const std::string dir = make_temp_dir();
  std::ofstream(dir + "/door.json") << R"({"name": "door", "fps": 10, "keys": [
      {"t": 0, "eye": [7.85, 1.6, -4.08], "target": [8.26, 1.6, -2.74]},
      {"t": 1, "eye": [7.85, 1.6, -4.08], "target": [8.26, 1.6, -2.74]}],
    "events": [{"t": 0.5, "portal": "front_door", "open": false}]})";
  ProcessResult r =
      run_process(lintel_bin() + " walk --json-lines " + kCottage + " --timeline-file " + dir + "/door.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream lines(r.out);
  std::string line, last;
  std::vector<std::vector<std::string>> cells;
  while (std::getline(lines, line)) {
    last = line;
    const nlohmann::json j = nlohmann::json::parse(line);
    if (j.contains("summary")) break;
    cells.push_back(j["visible_cells"].get<std::vector<std::string>>());
  }
  ASSERT_EQ(cells.size(), 11u);
  for (size_t f = 1; f < 5; ++f) EXPECT_EQ(cells[f], cells[0]) << "frame " << f;
  for (size_t f = 6; f < cells.size(); ++f) EXPECT_EQ(cells[f], cells[5]) << "frame " << f;
  EXPECT_LT(cells[5].size(), cells[0].size()) << "closing the front door hides nothing";
  for (const std::string& c : cells[5])
    EXPECT_NE(std::find(cells[0].begin(), cells[0].end(), c), cells[0].end()) << c << " appeared";
  EXPECT_EQ(nlohmann::json::parse(last)["summary"]["door_events"].get<int>(), 1);

  std::ofstream(dir + "/bad.json") << R"({"name": "door", "keys": [{"t": 0, "eye": [0, 1.6, 8], "target": [0, 1.6, 0]}],
    "events": [{"t": 0.5, "portal": "garage_door", "open": false}]})";
  ProcessResult bad = run_process(lintel_bin() + " walk " + kCottage + " --timeline-file " + dir + "/bad.json");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(count_lines(bad.err), 1) << bad.err;
  EXPECT_NE(bad.err.find("garage_door"), std::string::npos) << bad.err;
  std::filesystem::remove_all(dir);

  // `lintel vis --close` gives the same cells as the walk's frames after the door closed.
  ProcessResult vis = run_process(
      lintel_bin() + " vis --json --eye 7.85,1.6,-4.08 --target 8.26,1.6,-2.74 --close front_door " + kCottage);
  ASSERT_EQ(vis.exit_code, 0) << vis.err;
  std::vector<std::string> vis_cells;
  const nlohmann::json vis_json = nlohmann::json::parse(vis.out);  // kept alive for the loop
  for (const auto& c : vis_json["visible_cells"]) vis_cells.push_back(c["cell"].get<std::string>());
  EXPECT_EQ(vis_cells, cells[5]);
  EXPECT_EQ(run_process(lintel_bin() + " vis --eye 0,1.6,8 --target 0,1.6,0 --close nosuch " + kCottage).exit_code, 2);
}

// A timeline that carries an instance (instance_keys): the hall shelf is carried from outside the
// front door through the hall into the living room while the camera stands still. The walk moves
// it every frame, reports the frames it changes cell, and its summary counts it; an unknown
// instance name is bad input (one line naming the key, exit 2); --frames renders it (the renderer
// follows the moves through Renderer::update_world).
TEST(Cli, WalkCarriesAnInstanceThroughRooms) {
  const std::string dir = make_temp_dir();
  const std::string keys =
      R"({"name": "carry", "fps": 10, "keys": [{"t": 0, "eye": [6.56, 1.6, -8.32], "target": [7.14, 1.6, -6.4]},
      {"t": 6, "eye": [6.56, 1.6, -8.32], "target": [7.14, 1.6, -6.4]}], "instance_keys": [)";
  std::ofstream(dir + "/carry.json") << keys << R"(
      {"t": 0, "instance": "hall_shelf", "translation": [6.91, 1.0, -7.169]},
      {"t": 2.857, "instance": "hall_shelf", "translation": [8.079, 1.0, -3.344]},
      {"t": 4.286, "instance": "hall_shelf", "translation": [8.432, 1.0, -1.385]},
      {"t": 5.196, "instance": "hall_shelf", "translation": [7.292, 1.0, -0.959]},
      {"t": 6, "instance": "hall_shelf", "translation": [6.923, 1.0, 0.407], "rotation": [0, 0.3826834, 0, 0.9238795]}]})";
  ProcessResult r =
      run_process(lintel_bin() + " walk --json-lines " + kCottage + " --timeline-file " + dir + "/carry.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream lines(r.out);
  std::string line;
  std::vector<std::string> changes;
  nlohmann::json summary;
  while (std::getline(lines, line)) {
    const nlohmann::json j = nlohmann::json::parse(line);
    if (j.contains("summary"))
      summary = j["summary"];
    else if (j.contains("instances_changing_cell"))
      changes.push_back(j["instances_changing_cell"].get<std::string>());
  }
  EXPECT_NE(std::find(changes.begin(), changes.end(), "hall_shelf outside -> hall"), changes.end());
  EXPECT_NE(std::find(changes.begin(), changes.end(), "hall_shelf hall -> living"), changes.end());
  EXPECT_EQ(summary["instances_moved"].get<int>(), 1);
  EXPECT_EQ(summary["instance_moves"].get<int>(), 61);
  EXPECT_EQ(summary["instance_cell_changes"].get<int>(), int(changes.size()));

  std::ofstream(dir + "/bad.json") << keys << R"({"t": 0, "instance": "hall_shelff", "translation": [0, 0, 0]}]})";
  ProcessResult bad = run_process(lintel_bin() + " walk " + kCottage + " --timeline-file " + dir + "/bad.json");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(count_lines(bad.err), 1) << bad.err;
  EXPECT_NE(bad.err.find("instance key 0: no instance named 'hall_shelff'"), std::string::npos) << bad.err;
  // The GPU cull follows the carried shelf by uploading its record alone: every frame draws what
  // the CPU reference lists.
  ProcessResult gpu = run_process(lintel_bin() + " walk --json-lines --gpu-cull " + kCottage + " --timeline-file " +
                                  dir + "/carry.json");
  ASSERT_EQ(gpu.exit_code, 0) << gpu.err;
  const nlohmann::json gpu_summary = nlohmann::json::parse(gpu.out.substr(gpu.out.rfind("{\"summary\"")))["summary"];
  EXPECT_EQ(gpu_summary["gpu"]["frames_differing_from_cpu"].get<int>(), 0);
  EXPECT_GT(gpu_summary["gpu"]["instances_drawn"].get<int>(), 0);
  // --frames follows the carried shelf too (Renderer::update_world before each rendered frame).
  ProcessResult frames = run_process(lintel_bin() + " walk -q " + kCottage + " --timeline-file " + dir +
                                     "/carry.json --frames " + dir + "/out --every 30 --width 64 --height 36");
  EXPECT_EQ(frames.exit_code, 0) << frames.err;
  EXPECT_TRUE(std::filesystem::exists(dir + "/out/frame_00030.png"));
  std::filesystem::remove_all(dir);
}

// The lesson's doorway flap: an eye at rest on the cottage's hall/living door plane with +-1..3 um
// of jitter for 3 s at 60 fps (fixtures/cottage_doorway_jitter.json, written by
// bench/doorway_jitter_timeline.py) crosses the plane about 100 times but never switches cell.
TEST(Cli, WalkAtRestInADoorwayWithMicrometreJitterNeverSwitches) {
  ProcessResult r = run_process(lintel_bin() + " walk --json-lines -q " + kCottage + " --timeline-file " +
                                std::string(LINTEL_SOURCE_DIR) + "/tests/apps/fixtures/cottage_doorway_jitter.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream lines(r.out);
  std::string line, last;
  while (std::getline(lines, line)) last = line;
  const nlohmann::json summary = nlohmann::json::parse(last)["summary"];
  EXPECT_EQ(summary["frames"].get<int>(), 181);
  EXPECT_GT(summary["portal_crossings"].get<int>(), 50) << "the jitter must really cross the plane";
  EXPECT_EQ(summary["transitions"].get<int>(), 0);
  EXPECT_EQ(summary["flaps"].get<int>(), 0);
}

TEST(Cli, WalkRejectsABadTimelineFile) {
  const std::string dir = make_temp_dir();
  std::ofstream(dir + "/t.json")
      << R"({"name": "x", "fps": 0, "keys": [{"t": 0, "eye": [0,1,0], "target": [0,1,-1]}]})";
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

// One frame through the renderer: a PNG of the asked size, and the JSON names the passes it timed.
TEST(Cli, RenderWritesAPngOfTheAskedSize) {
  const std::string dir = make_temp_dir();
  ProcessResult r = run_process(lintel_bin() + " render " + kCottage +
                                " --time 5 --width 96 --height 54 --json --out " + dir + "/f.png");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["width"].get<int>(), 96);
  EXPECT_EQ(j["height"].get<int>(), 54);
  EXPECT_EQ(j["viewer_cell"], "hall");
  std::ifstream png(dir + "/f.png", std::ios::binary);
  char header[24] = {};
  ASSERT_TRUE(png.read(header, sizeof header));
  EXPECT_EQ(std::string(header + 1, 3), "PNG");
  // IHDR width and height, big-endian at bytes 16..23.
  auto be32 = [&](int at) {
    return (uint32_t(uint8_t(header[at])) << 24) | (uint32_t(uint8_t(header[at + 1])) << 16) |
           (uint32_t(uint8_t(header[at + 2])) << 8) | uint32_t(uint8_t(header[at + 3]));
  };
  EXPECT_EQ(be32(16), 96u);
  EXPECT_EQ(be32(20), 54u);
  std::filesystem::remove_all(dir);
}

// Bad input to the renderer's commands: exit 2, one line naming the fault, and no file left behind.
TEST(Cli, RenderRejectsBadInputWithoutPartialFiles) {
  const std::string dir = make_temp_dir();
  struct Case {
    std::string args, needle;
  } cases[] = {
      {"--time 5 --pass shiny --out " + dir + "/a.png", "--pass 'shiny'"},
      {"--time 5 --out " + dir + "/missing/a.png", dir + "/missing/a.png"},
      {"--out " + dir + "/a.png", "--eye and --target, or --time"},
      {"--eye 1,1.6,1 --target 1,1.6,1 --out " + dir + "/a.png", "camera"},
      {"--eye 1,nan,1 --target 0,0,0 --out " + dir + "/a.png", "--eye"},
  };
  for (const Case& c : cases) {
    ProcessResult r = run_process(lintel_bin() + " render " + kCottage + " " + c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.needle), std::string::npos) << c.args << "\n" << r.err;
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir)) << "a failed render left a file behind";
  ProcessResult walk = run_process(lintel_bin() + " walk " + kCottage + " -q --frames " + dir + "/no/such/frames");
  EXPECT_EQ(walk.exit_code, 2) << walk.err;
  EXPECT_NE(walk.err.find("parent directory does not exist"), std::string::npos) << walk.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/no"));
  std::filesystem::remove_all(dir);
}

// `walk --frames`: one PNG per rendered frame and a contact sheet.
TEST(Cli, WalkFramesWritesEveryNthFrameAndAContactSheet) {
  const std::string dir = make_temp_dir();
  ProcessResult r = run_process(lintel_bin() + " walk " + kCottage + " -q --frames " + dir +
                                "/frames --every 200 --width 64 --height 36");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  size_t pngs = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir + "/frames"))
    pngs += e.path().filename().string().rfind("frame_", 0) == 0;
  EXPECT_EQ(pngs, 4u) << "frames 0, 200, 400, 600 of 682";
  EXPECT_TRUE(std::filesystem::exists(dir + "/frames/frame_00400.png"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/frames/contact_sheet.png"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace lintel::test
