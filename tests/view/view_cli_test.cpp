// `lintel view` as a user runs it: under Xvfb on lavapipe with the validation layers, a scripted
// run exits 0 without validation messages and its screenshot (overlays off) equals `lintel render`
// of the same camera; offscreen (no display) a script still drives the fly camera; bad scripts and
// a missing display are one-line errors.
#include "run_process.h"

#include <lintel/render/image_io.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace lintel::test {
namespace {

const std::string kCottage = std::string(LINTEL_SOURCE_DIR) + "/scenes/cottage.gltf";
// The doorway timeline's key at 4.286 s: in the hall, looking on into the house.
const std::string kCamera =
    " --eye 8.312972,1.6,-2.5786467 --target 8.511266,1.6,-0.5885011 --width 160 --height 90 --no-gi";

void write_file(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

bool xvfb_available() { return std::system("command -v xvfb-run >/dev/null 2>&1") == 0; }

// The device the CLI tests use (LINTEL_VK_DEVICE, as the other GPU tests), else the default.
std::string device_option() {
  const char* d = std::getenv("LINTEL_VK_DEVICE");
  return d && *d ? std::string(" --device '") + d + "'" : std::string();
}

TEST(ViewCli, BadScriptIsOneLineErrorNamingFileAndLine) {
  const std::string dir = make_temp_dir();
  write_file(dir + "/bad.txt", "0 key down W\n# fine so far\n4 key wiggle W\n");
  const ProcessResult r =
      run_process("env -u DISPLAY " + lintel_bin() + " view " + kCottage + " --script " + dir + "/bad.txt");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(dir + "/bad.txt:3:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("wiggle"), std::string::npos) << r.err;
  // Not a script at all: refused by size or content, before any window.
  const ProcessResult zero = run_process(lintel_bin() + " view " + kCottage + " --script /dev/zero");
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_EQ(count_lines(zero.err), 1) << zero.err;
  // A screenshot target that may not be replaced is refused before the first frame.
  write_file(dir + "/dir_shot.txt", "0 screenshot " + dir + "\n");
  const ProcessResult to_dir =
      run_process("env -u DISPLAY " + lintel_bin() + " view " + kCottage + " --script " + dir + "/dir_shot.txt");
  EXPECT_EQ(to_dir.exit_code, 2);
  EXPECT_NE(to_dir.err.find("is a directory"), std::string::npos) << to_dir.err;
  EXPECT_TRUE(to_dir.out.empty()) << to_dir.out;
  const ProcessResult missing = run_process(lintel_bin() + " view " + kCottage + " --script " + dir + "/none.txt");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find(dir + "/none.txt"), std::string::npos) << missing.err;
}

TEST(ViewCli, NoDisplayAndNoScriptIsOneLineError) {
  const ProcessResult r = run_process("env -u DISPLAY -u WAYLAND_DISPLAY " + lintel_bin() + " view " + kCottage);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("xvfb-run"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

// Held W for 15 scripted frames of 1/30 s at the default 2 m/s: the eye moves 1 m along the view
// (here +X, since the camera looks along +X); offscreen, since no display is set.
TEST(ViewCli, ScriptDrivesTheFlyCameraOffscreen) {
  const std::string dir = make_temp_dir();
  write_file(dir + "/walk.txt", "0 key down W\n15 key up W\n16 quit\n");
  const ProcessResult r =
      run_process("env -u DISPLAY -u WAYLAND_DISPLAY " + lintel_bin() + " view " + kCottage +
                  " --eye 8.3,1.6,-2.58 --target 12.3,1.6,-2.58 --width 64 --height 36 --no-gi --no-ao --validation" +
                  device_option() + " --script " + dir + "/walk.txt");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_NE(r.out.find("view: 17 frames"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(offscreen)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("last eye 9.3000,1.6000,-2.5800"), std::string::npos) << r.out;
}

// Timeline playback: a scripted frame lasts 1/30 s, so frame f shows the timeline at f / 30 s,
// which is `lintel walk`'s frame f of the cottage's 30 fps timeline: the same eye and, tracked by
// portal crossings all the way, the same viewer cell (frame 108 is where the walk enters the hall).
TEST(ViewCli, TimelinePlaybackFollowsTheWalk) {
  const ProcessResult r = run_process("env -u DISPLAY -u WAYLAND_DISPLAY " + lintel_bin() + " view " + kCottage +
                                      " --timeline --frames 109 --width 64 --height 36 --no-gi --no-ao --validation" +
                                      device_option() + " --script /dev/null");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  float x = 0, y = 0, z = 0;
  const size_t at = r.out.find("last eye ");
  ASSERT_NE(at, std::string::npos) << r.out;
  ASSERT_EQ(std::sscanf(r.out.c_str() + at, "last eye %f,%f,%f", &x, &y, &z), 3) << r.out;
  const ProcessResult walk = run_process(lintel_bin() + " walk " + kCottage + " --json-lines");
  ASSERT_EQ(walk.exit_code, 0) << walk.err;
  std::istringstream lines(walk.out);
  bool found = false;
  for (std::string line; std::getline(lines, line);) {
    const nlohmann::json j = nlohmann::json::parse(line);
    if (!j.contains("frame") || j["frame"].get<int>() != 108) continue;
    found = true;
    EXPECT_NEAR(x, j["eye"][0].get<float>(), 1e-3f);
    EXPECT_NEAR(y, j["eye"][1].get<float>(), 1e-3f);
    EXPECT_NEAR(z, j["eye"][2].get<float>(), 1e-3f);
    EXPECT_NE(r.out.find("in cell " + j["viewer_cell"].get<std::string>() + "\n"), std::string::npos) << r.out;
  }
  EXPECT_TRUE(found);
}

// The property: what the viewer presents (read back from the swapchain image) is what the headless
// renderer draws for the same camera and size, within a small tolerance; toggles that come back
// to the start state (debug views cycled round, overlays on and off, culling methods cycled round,
// AO off and on) leave no trace.
TEST(ViewCli, ScreenshotUnderXvfbMatchesTheHeadlessRenderer) {
  if (!xvfb_available()) GTEST_SKIP() << "xvfb-run is not installed";
  const std::string dir = make_temp_dir();
  std::string script = "0 mouse move 30 10\n";  // no button held: the camera must not turn
  for (int f = 1; f <= 7; ++f) script += std::to_string(f) + " key press V\n";  // seven views, back to final
  script += "8 key press H\n9 key press H\n";
  // Culling portal -> portal+hiz -> frustum -> none -> portal and AO off and on: six renderer
  // rebuilds on the borrowed device, each a destroy + create under validation.
  script += "10 key press C\n11 key press C\n12 key press C\n13 key press C\n14 key press O\n15 key press O\n";
  script += "17 screenshot\n17 quit\n";  // quit still shows its own frame, screenshot included
  write_file(dir + "/shot.txt", script);
  const std::string shot = dir + "/shot.png", ref = dir + "/ref.png";
  const ProcessResult r =
      run_process("xvfb-run -a " + lintel_bin() + " view " + kCottage + kCamera + " --no-overlay --validation" +
                  device_option() + " --script " + dir + "/shot.txt --screenshot " + shot);
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("(window)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("view: 18 frames"), std::string::npos) << r.out;
  const ProcessResult headless =
      run_process(lintel_bin() + " render " + kCottage + kCamera + device_option() + " --out " + ref);
  ASSERT_EQ(headless.exit_code, 0) << headless.err;

  render::Rgba8Image a, b;
  ASSERT_TRUE(render::read_png(shot, a).ok());
  ASSERT_TRUE(render::read_png(ref, b).ok());
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  size_t differing = 0, distinct_from_first = 0;
  for (size_t i = 0; i < a.pixels.size(); i += 4) {
    int worst = 0;
    for (size_t k = 0; k < 3; ++k) worst = std::max(worst, std::abs(int(a.pixels[i + k]) - int(b.pixels[i + k])));
    differing += worst > 3;
    distinct_from_first += b.pixels[i] != b.pixels[0] || b.pixels[i + 1] != b.pixels[1];
  }
  const size_t pixels = a.pixels.size() / 4;
  EXPECT_GT(distinct_from_first, pixels / 10) << "the reference is not a flat image, so equality means something";
  EXPECT_LE(differing, pixels / 200) << differing << " of " << pixels << " pixels differ by more than 3";
}

}  // namespace
}  // namespace lintel::test
