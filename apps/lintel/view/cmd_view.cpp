// `lintel view <scene>`: an interactive window on a scene (docs/view.md). Fly around, play the
// timeline, switch culling methods and debug views, and see each visible cell's clip region.
// --script drives the same input from a file (tests), --screenshot saves what was presented.
#include "../cli_common.h"
#include "../render_args.h"
#include "../resource_budget.h"
#include "open_heading.h"
#include "viewer.h"
#include "window_device.h"

#include <lintel/cell_locate.h>
#include <lintel/file_commit.h>
#include <lintel/timeline.h>

#include <algorithm>
#include <cstdlib>
#include <optional>

namespace lintel::cli {
namespace {

struct ViewArgs {
  std::string scene, script, screenshot, eye, target, up = "0,1,0";
  float fov_y_deg = 70.0f;
  bool timeline = false, no_overlay = false, quiet = false;
  uint64_t frames = 0;
  RenderArgs render;
  LoadOptions load;
};

// The first camera: --eye/--target, else the timeline's first key (turned to its most open heading
// unless --timeline plays the timeline itself: open_heading.h), else the middle of the first cell
// looking down -Z.
Status start_view(const ViewArgs& a, const World& world, View& view) {
  bool from_timeline = false;
  if (!a.eye.empty() || !a.target.empty()) {
    if (a.eye.empty() || a.target.empty()) return Status::error("give both --eye and --target");
    if (Status s = parse_vec3(a.eye, "--eye", view.eye_world); !s) return s;
    if (Status s = parse_vec3(a.target, "--target", view.target_world); !s) return s;
    if (Status s = parse_vec3(a.up, "--up", view.up_world); !s) return s;
    view.fov_y_deg = a.fov_y_deg;
  } else if (!world.timelines.empty()) {
    const int d = world.find_timeline("doorway");
    const Timeline& t = world.timelines[size_t(std::max(0, d))];
    view = timeline_view(t, t.keys.front().t);
    from_timeline = !a.timeline;
  } else {
    const Cell& c = world.cells.front();
    view.eye_world = glm::vec3(c.cell_to_world * glm::vec4(c.volume_box_cell.center(), 1.0f));
    view.target_world = view.eye_world + glm::vec3(0.0f, 0.0f, -1.0f);
    view.fov_y_deg = a.fov_y_deg;
  }
  view.aspect = float(a.render.width) / float(a.render.height);
  if (Status s = validate_view(view); !s) return Status::error("camera: " + s.message());
  if (from_timeline) view = view::most_open_heading(world, view);
  return {};
}

int run_view(const ViewArgs& a) {
  // Everything the user typed is checked before a window opens.
  std::optional<std::vector<view::ScriptEvent>> script;
  if (!a.script.empty()) {
    script.emplace();
    if (Status s = view::load_script(a.script, *script); !s) return fail(s);
    for (const view::ScriptEvent& e : *script) {
      if (e.event.type != view::InputType::Screenshot) continue;
      if (e.event.path.empty() && a.screenshot.empty())
        return fail(a.script + ": frame " + std::to_string(e.frame) +
                    ": 'screenshot' without a file needs --screenshot");
      // A target that may not be replaced is refused before any frame (write_png checks it again).
      if (!e.event.path.empty())
        if (std::string why = output_refusal(e.event.path); !why.empty())
          return fail(a.script + ": frame " + std::to_string(e.frame) + ": screenshot " + e.event.path + ": " + why);
    }
  }
  if (!a.screenshot.empty())
    if (std::string why = output_refusal(a.screenshot); !why.empty()) return fail(a.screenshot + ": " + why);
  view::ViewerOptions options;
  if (Status s = render_options_from(a.render, options.render); !s) return fail(s);
  options.overlays = !a.no_overlay;
  options.max_frames = a.frames;
  options.screenshot = a.screenshot;
  options.quiet = a.quiet;
  World world;
  if (Status s = load_scene(a.scene, a.load, world, nullptr, a.quiet); !s) return fail(s);
  if (Status s = check_render_budget(world, options.render, a.load.max_memory_bytes); !s)
    return fail(a.scene + ": " + s.message());
  if (a.timeline && world.timelines.empty()) return fail(a.scene + ": --timeline: the scene has no timeline");
  options.play_timeline = a.timeline;
  View start;
  if (Status s = start_view(a, world, start); !s) return fail(s);

  // No display: a scripted run goes offscreen (same upload path, two images of its own instead
  // of a swapchain); an interactive one cannot run at all.
  const bool display = std::getenv("DISPLAY") || std::getenv("WAYLAND_DISPLAY");
  if (!display && !script)
    return fail(
        Status::unsupported("view: no display to open a window on (DISPLAY is unset): run it under "
                            "'xvfb-run -a', or give --script to run offscreen"));
  view::WindowDeviceOptions wo;
  wo.width = a.render.width;
  wo.height = a.render.height;
  wo.title = "lintel view " + a.scene;
  wo.offscreen = !display;
  wo.validation = a.render.validation;
  wo.device = a.render.device;
  std::unique_ptr<view::WindowDevice> device;
  if (Status s = view::WindowDevice::create(wo, device); !s) return fail(s);
  view::ViewerSummary summary;
  {
    view::Viewer viewer(world, *device, options, start, std::move(script));
    if (Status s = viewer.open(); !s) return fail(s);
    if (Status s = viewer.run(summary); !s) return fail(s);
  }
  if (!a.quiet) {
    const View& v = summary.last_view;
    std::printf(
        "view: %llu frames on %s (%s), median %.1f ms per frame; last eye %.4f,%.4f,%.4f target %.4f,%.4f,%.4f in cell "
        "%s\n",
        (unsigned long long)summary.frames, printable(device->device_name()).c_str(),
        device->window() ? "window" : "offscreen", summary.median_frame_ms, v.eye_world.x, v.eye_world.y, v.eye_world.z,
        v.target_world.x, v.target_world.y, v.target_world.z, printable(world.cells[summary.last_cell].name).c_str());
    for (const std::string& p : summary.screenshots) std::printf("screenshot: %s\n", printable(p).c_str());
  }
  return kExitOk;
}

}  // namespace

void add_view_command(CLI::App& app, Command& run) {
  auto* cmd =
      app.add_subcommand("view", "Interactive viewer: fly camera, timeline, culling toggles, clip-region overlays");
  auto a = std::make_shared<ViewArgs>();
  cmd->add_option("scene", a->scene, "Scene file (.gltf or .glb)")->required();
  add_load_options(cmd, a->load);
  cmd->add_flag("--timeline", a->timeline, "Start playing the scene's timeline ('doorway', else the first); P pauses");
  cmd->add_option("--script", a->script, "Timed inputs (docs/view.md); without a display the run is offscreen");
  cmd->add_option("--screenshot", a->screenshot,
                  "PNG of the presented frame: the script's 'screenshot' lines, else the last frame");
  cmd->add_option("--frames", a->frames, "Exit after this many frames (0: when the window closes or the script ends)")
      ->check(CLI::Range(uint64_t(0), uint64_t(1) << 40));
  cmd->add_option("--eye", a->eye, "Start eye X,Y,Z (default: the timeline's first key)");
  cmd->add_option("--target", a->target, "Start target X,Y,Z");
  cmd->add_option("--up", a->up, "Up direction X,Y,Z")->capture_default_str();
  cmd->add_option("--fov", a->fov_y_deg, "Vertical field of view (degrees)")
      ->capture_default_str()
      ->check(finite_range(1e-3, 179.0));
  cmd->add_flag("--no-overlay", a->no_overlay, "Start with the overlays off (H toggles them)");
  cmd->add_flag("-q,--quiet", a->quiet, "Print nothing but errors");
  add_render_options(cmd, a->render);
  cmd->callback([&run, a] { run = [a] { return run_view(*a); }; });
}

}  // namespace lintel::cli
