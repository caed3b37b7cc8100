// `lintel render <scene> --eye … --target … --out F.png`: one frame through the whole renderer
// (portal visibility, GPU cull, shadows, g-buffer, GTAO, GI, lighting, tonemap), or a debug view
// of one pass with --pass. --json prints the per-pass GPU times and the frame's counts. With --time,
// the doorway timeline's doors and moving instances are as they are at that second.
#include "cli_common.h"
#include "render_args.h"
#include "resource_budget.h"
#include "visibility_args.h"

#include <lintel/cell_locate.h>
#include <lintel/dynamic_instances.h>
#include <lintel/file_commit.h>
#include <lintel/render/image_io.h>
#include <lintel/timeline.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>

namespace lintel::cli {
namespace {

struct RenderCmdArgs {
  std::string scene, eye, target, up = "0,1,0", out = "render.png";
  float fov_y_deg = 70.0f;
  double time = -1.0;  // --time: the camera of the scene's doorway timeline at this second
  bool json = false, graph = false;
  RenderArgs render;
  LoadOptions load;
};

// Applies `timeline`'s door events up to `t` and puts the instances it moves where they are at
// `t` (a jump from where they were loaded: DynamicInstances re-locates them by containment).
Status world_at_time(const std::string& scene, Timeline timeline, double t, World& world) {
  apply_timeline_events(timeline, t, 0, world);
  std::vector<InstanceTrack> tracks;
  if (Status s = resolve_timeline_instances(world, timeline, tracks); !s)
    return Status::error(scene + ": " + s.message());
  if (tracks.empty()) return {};
  DynamicInstances movers;
  if (Status s = movers.reset(world); !s) return s;
  for (const InstanceTrack& track : tracks) {
    glm::mat4 m;
    if (!sample_instance_track(timeline, track, t, m)) continue;
    if (Status s = movers.move(world, track.instance, m); !s) return Status::error(scene + ": " + s.message());
  }
  return {};
}

int run_render(const RenderCmdArgs& a) {
  // A target that may not be replaced is refused before any work (write_png checks it again).
  if (std::string why = output_refusal(a.out); !why.empty()) return fail(a.out + ": " + why);
  render::RenderOptions options;
  if (Status s = render_options_from(a.render, options); !s) return fail(s);
  World world;
  if (Status s = load_scene(a.scene, a.load, world, nullptr, a.json); !s) return fail(s);
  if (Status s = check_render_budget(world, options, a.load.max_memory_bytes); !s)
    return fail(a.scene + ": " + s.message());
  View view;
  if (a.time >= 0.0) {
    if (world.timelines.empty()) return fail(a.scene + ": --time: the scene has no timeline");
    const int d = world.find_timeline("doorway");
    const Timeline& timeline = world.timelines[size_t(std::max(0, d))];
    view = timeline_view(timeline, a.time);
    // The world at that second: its door events up to it, and its moving instances where they are.
    if (Status s = world_at_time(a.scene, timeline, a.time, world); !s) return fail(s);
  } else {
    if (a.eye.empty() || a.target.empty()) return fail("give --eye and --target, or --time");
    if (Status s = parse_vec3(a.eye, "--eye", view.eye_world); !s) return fail(s);
    if (Status s = parse_vec3(a.target, "--target", view.target_world); !s) return fail(s);
    if (Status s = parse_vec3(a.up, "--up", view.up_world); !s) return fail(s);
    view.fov_y_deg = a.fov_y_deg;
  }
  view.aspect = float(a.render.width) / float(a.render.height);
  if (Status s = validate_view(view); !s) return fail("camera: " + s.message());
  const uint32_t cell = locate_cell(world, glm::dvec3(view.eye_world)).cell;

  RenderSession session;
  if (Status s = open_render_session(world, a.render, options, session); !s) return fail(s);
  if (a.graph) std::printf("%s", session.renderer->describe_graph().c_str());
  render::RenderedFrame frame;
  if (Status s = session.renderer->render(view, cell, frame); !s) return fail(s);
  if (a.render.validation) {
    const std::vector<std::string> messages = session.context->take_validation_messages();
    if (!messages.empty()) return fail(Status::internal("validation: " + messages.front()));
  }
  if (frame.unshadowed_lights)
    std::fprintf(stderr, "lintel: note: %u of %u lights lit without shadows (shadow atlas full, %u slots)\n",
                 frame.unshadowed_lights, frame.active_lights, session.renderer->shadow_slots());
  if (Status s = render::write_png(a.out, {frame.width, frame.height, frame.rgba8}); !s) return fail(s);

  if (a.json) {
    nlohmann::json passes = nlohmann::json::object();
    for (const render::PassTime& p : frame.passes) passes[p.name] = p.gpu_ms;
    nlohmann::json out = {{"out", a.out},
                          {"width", frame.width},
                          {"height", frame.height},
                          {"pass", a.render.pass},
                          {"device", session.context->info().name},
                          {"viewer_cell", world.cells[cell].name},
                          {"cells_drawn", frame.cells_drawn},
                          {"active_lights", frame.active_lights},
                          {"shadow_views", frame.shadow_views},
                          {"shadow_views_drawn", frame.shadow_views_drawn},
                          {"shadow_resolution", session.renderer->shadow_resolution()},
                          {"shadow_slots", session.renderer->shadow_slots()},
                          {"unshadowed_lights", frame.unshadowed_lights},
                          {"degradation", session.renderer->setup_note()},
                          {"cpu_visibility_ms", frame.cpu_visibility_ms},
                          {"wall_ms", frame.wall_ms},
                          {"gpu_ms", passes}};
    std::printf("%s\n", out.dump(2).c_str());
  } else {
    std::printf("%s: %ux%u %s view from cell %s on %s: %u cells drawn, %u lights, %u shadow views, %.1f ms\n",
                a.out.c_str(), frame.width, frame.height, a.render.pass.c_str(),
                printable(world.cells[cell].name).c_str(), printable(session.context->info().name).c_str(),
                frame.cells_drawn, frame.active_lights, frame.shadow_views, frame.wall_ms);
  }
  return kExitOk;
}

}  // namespace

void add_render_command(CLI::App& app, Command& run) {
  auto* cmd = app.add_subcommand("render", "Render one frame (deferred, shadows, GI, GTAO) to a PNG");
  auto a = std::make_shared<RenderCmdArgs>();
  cmd->add_option("scene", a->scene, "Scene file (.gltf or .glb)")->required();
  add_load_options(cmd, a->load);
  auto* eye = cmd->add_option("--eye", a->eye, "Eye position X,Y,Z (meters, world space)");
  auto* target = cmd->add_option("--target", a->target, "Point looked at X,Y,Z");
  cmd->add_option("--time", a->time, "Instead of --eye/--target: the doorway timeline's camera at this second")
      ->excludes(eye)
      ->excludes(target)
      ->check(finite_range(0.0, 1e6));
  cmd->add_option("--up", a->up, "Up direction X,Y,Z")->capture_default_str();
  cmd->add_option("--fov", a->fov_y_deg, "Vertical field of view (degrees)")
      ->capture_default_str()
      ->check(finite_range(1e-3, 179.0));
  cmd->add_option("--out", a->out, "PNG to write")->capture_default_str();
  cmd->add_flag("--json", a->json, "Print the frame's counts and per-pass GPU times as JSON");
  cmd->add_flag("--graph", a->graph, "Print the render graph's passes and what each reads and writes");
  add_render_options(cmd, a->render);
  cmd->callback([&run, a] { run = [a] { return run_render(*a); }; });
}

}  // namespace lintel::cli
