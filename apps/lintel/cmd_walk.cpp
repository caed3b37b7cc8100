// `lintel walk <scene>`: runs a camera timeline frame by frame — viewer cell tracked by portal
// crossings, one visibility build per frame — and summarizes transitions, flaps and build times.
// It also counts portal crossings geometrically, independently of the tracker, so a reader can
// check that every doorway crossing produced exactly one transition. Door events and instance keys
// of the timeline change the world before each frame is built.
#include "cli_common.h"
#include "resource_budget.h"
#include "visibility_args.h"
#include "walk_frames.h"
#include "walk_gpu_cull.h"

#include <lintel/scene_io.h>
#include <lintel/timeline.h>
#include <lintel/dynamic_instances.h>
#include <lintel/viewer_tracker.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace lintel::cli {
namespace {

struct WalkArgs {
  std::string scene, timeline, timeline_file;
  bool json_lines = false;
  bool quiet = false;
  bool gpu_cull = false;
  std::string device;
  uint32_t flap_window = 3;
  VisibilityArgs vis;
  std::string frames_dir;  // --frames: render every `every`-th frame here
  uint32_t every = 1;
  RenderArgs render;
  LoadOptions load;
};

// Whether the segment a -> b passes through the portal's polygon (changes side inside it).
bool segment_crosses_portal(const Portal& p, const glm::vec3& a, const glm::vec3& b) {
  const double da = glm::dot(glm::dvec3(p.normal_world), glm::dvec3(a)) - p.plane_d_world;
  const double db = glm::dot(glm::dvec3(p.normal_world), glm::dvec3(b)) - p.plane_d_world;
  if ((da > 0) == (db > 0)) return false;
  const glm::dvec3 x = glm::dvec3(a) + (glm::dvec3(b) - glm::dvec3(a)) * (da / (da - db));
  const size_t n = p.polygon_world.size();
  for (size_t i = 0; i < n; ++i) {
    const glm::dvec3 e = glm::dvec3(p.polygon_world[(i + 1) % n]) - glm::dvec3(p.polygon_world[i]);
    const glm::dvec3 to_x = x - glm::dvec3(p.polygon_world[i]);
    if (glm::dot(glm::cross(e, to_x), glm::dvec3(p.normal_world)) < -1e-9) return false;
  }
  return true;
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t i = std::min(v.size() - 1, static_cast<size_t>(q * static_cast<double>(v.size() - 1) + 0.5));
  return v[i];
}

int run_walk(const WalkArgs& a) {
  if (Status s = validate_options(a.vis.options); !s) return fail(s);
  World world;
  if (Status s = load_scene(a.scene, a.load, world, nullptr, a.json_lines); !s) return fail(s);

  Timeline timeline;
  if (!a.timeline_file.empty()) {
    if (Status s = load_timeline_file(a.timeline_file, timeline); !s) return fail(s);
    if (Status s = resolve_timeline_events(world, timeline); !s) return fail(a.timeline_file + ": " + s.message());
  } else if (!a.timeline.empty()) {
    const int t = world.find_timeline(a.timeline);
    if (t < 0) return fail(a.scene + ": --timeline '" + a.timeline + "': no timeline of that name");
    timeline = world.timelines[size_t(t)];
  } else {
    if (world.timelines.empty()) return fail(a.scene + ": the scene has no timeline; give --timeline-file");
    const int doorway = world.find_timeline("doorway");
    timeline = world.timelines[doorway >= 0 ? size_t(doorway) : 0];
  }
  // Instances the timeline moves (instance_keys): resolved against the loaded world.
  std::vector<InstanceTrack> tracks;
  if (Status s = resolve_timeline_instances(world, timeline, tracks); !s)
    return fail((a.timeline_file.empty() ? a.scene : a.timeline_file) + ": " + s.message());
  DynamicInstances movers;
  if (!tracks.empty())
    if (Status s = movers.reset(world); !s) return fail(s);

  const size_t frames = timeline_frame_count(timeline);
  if (Status s = check_walk_budget(world, frames, a.load.max_memory_bytes); !s)
    return fail(a.scene + ": " + s.message());
  if (!a.frames_dir.empty()) {
    render::RenderOptions options;
    if (Status s = render_options_from(a.render, options); !s) return fail(s);
    if (Status s = check_render_budget(world, options, a.load.max_memory_bytes); !s)
      return fail(a.scene + ": " + s.message());
  }

  WalkFrames rendered;
  if (!a.frames_dir.empty())
    if (Status s = rendered.init(world, a.frames_dir, a.render, a.device); !s) return fail(s);
  WalkGpuCull gpu_cull;  // on the renderer's device when there is one
  if (a.gpu_cull)
    if (Status s = a.frames_dir.empty() ? gpu_cull.init(world, a.device) : gpu_cull.init(world, rendered.context()); !s)
      return fail(s);
  size_t gpu_mismatches = 0;
  uint64_t gpu_drawn_total = 0;
  ViewerTracker tracker;
  VisibilityBuilder builder;
  VisibleSet visible;
  builder.prepare(world, a.vis.options, visible);  // as a game at load: no allocation in the first frame
  std::vector<double> build_us;
  std::vector<CellTransition> history;  // every transition, with its frame in `frame_of`
  std::vector<size_t> frame_of;
  size_t crossings = 0, flaps = 0, door_events = 0, next_event = 0;
  size_t instance_moves = 0, instance_cell_changes = 0;
  std::vector<uint8_t> ever_moved(world.instances.size(), 0);
  uint64_t max_pops = 0, cap_hits = 0;
  glm::vec3 previous_eye{0.0f};
  // Teleports carry the camera: the timeline's keys are in its own frame, mapped by `camera_carry`,
  // the product of the teleports crossed so far (docs/visibility.md, "Linked portals").
  glm::dmat4 camera_carry(1.0);
  size_t teleports = 0, linked_cells_total = 0, frames_with_linked = 0, max_linked = 0;
  // Jumps: frames whose eye moved farther than the tracker's jump distance (a teleporter of an
  // imported map, docs/levels.md): the tracker re-locates by containment, and no portal is crossed.
  size_t jumps = 0;
  const double jump_distance_m = double(TrackerOptions{}.jump_distance_m);
  auto carry = [](const glm::dmat4& m, View& v) {
    v.eye_world = glm::vec3(m * glm::dvec4(glm::dvec3(v.eye_world), 1.0));
    v.target_world = glm::vec3(m * glm::dvec4(glm::dvec3(v.target_world), 1.0));
    v.up_world = glm::vec3(m * glm::dvec4(glm::dvec3(v.up_world), 0.0));
  };

  if (!a.json_lines && !a.quiet)
    std::printf("walking '%s' of %s: %zu frames at %g fps%s%s\n", printable(timeline.name).c_str(), a.scene.c_str(),
                frames, timeline.fps, a.gpu_cull ? ", instances culled on the GPU: " : "",
                gpu_cull.device_name().c_str());
  for (size_t f = 0; f < frames; ++f) {
    const double t = timeline.keys.front().t + double(f) / timeline.fps;
    View view = timeline_view(timeline, t);
    view.near_m = a.vis.near_m;
    if (teleports > 0) carry(camera_carry, view);
    // Door events up to this frame's time change the world before the frame is built.
    const size_t applied = apply_timeline_events(timeline, t, next_event, world);
    std::string doors;
    for (size_t e = next_event; e < applied; ++e)
      doors +=
          (doors.empty() ? "" : ", ") + timeline.events[e].portal + (timeline.events[e].open ? " opens" : " closes");
    door_events += applied - next_event;
    next_event = applied;
    // Then the instances it carries: a move only where the sampled transform changed.
    std::string carried;
    for (const InstanceTrack& track : tracks) {
      glm::mat4 m;
      if (!sample_instance_track(timeline, track, t, m) || m == world.instances[track.instance].mesh_to_world) continue;
      const uint32_t cell_before = world.instances[track.instance].cell;
      if (Status s = movers.move(world, track.instance, m); !s)
        return fail(a.scene + ": timeline '" + timeline.name + "' frame " + std::to_string(f) + ": " + s.message());
      ++instance_moves;
      ever_moved[track.instance] = 1;
      if (world.instances[track.instance].cell != cell_before) {
        ++instance_cell_changes;
        carried += (carried.empty() ? "" : ", ") + world.instances[track.instance].name + " " +
                   world.cells[cell_before].name + " -> " + world.cells[world.instances[track.instance].cell].name;
      }
    }
    if (!tracks.empty()) {
      movers.take_moved();
      builder.instances_moved(world, movers);  // the CPU cull re-bounds just the moved ones
      if (!a.frames_dir.empty()) rendered.note_moved(movers.taken());
      if (a.gpu_cull)  // and the GPU cull uploads just those records
        if (Status s = gpu_cull.moved(world, movers.taken()); !s) return fail(s);
    }
    if (!a.frames_dir.empty()) view.aspect = rendered.aspect();  // build what the rendered camera sees
    if (Status s = validate_view(view); !s)
      return fail(a.scene + ": timeline '" + timeline.name + "' frame " + std::to_string(f) + ": " + s.message());
    if (Status s = f == 0 ? tracker.reset(world, view.eye_world) : tracker.update(world, view.eye_world); !s)
      return fail(s);
    if (tracker.teleported()) {  // the eye went through a teleport: the camera goes with it from now on
      carry(tracker.teleport(), view);
      camera_carry = tracker.teleport() * camera_carry;
      previous_eye =
          glm::vec3(tracker.teleport() * glm::dvec4(glm::dvec3(previous_eye), 1.0));  // crossings: same frame
      ++teleports;
    }
    const bool jumped = f > 0 && glm::length(glm::dvec3(view.eye_world - previous_eye)) > jump_distance_m;
    jumps += jumped;
    if (f > 0 && !jumped)
      for (const Portal& p : world.portals) crossings += segment_crosses_portal(p, previous_eye, view.eye_world);
    previous_eye = view.eye_world;

    const auto t0 = std::chrono::steady_clock::now();
    Status built = builder.build(world, view, tracker.cell(), a.vis.options, visible);
    const auto t1 = std::chrono::steady_clock::now();
    if (!built) return fail(built);
    const double us = std::chrono::duration<double, std::micro>(t1 - t0).count();
    build_us.push_back(us);
    max_pops = std::max(max_pops, visible.stats.pops);
    GpuFrameDraws draws;
    if (a.gpu_cull) {
      if (Status s = gpu_cull.cull(world, view, visible, draws); !s) return fail(s);
      // The CPU reference decided the same frame: the two must draw the same number of instances.
      gpu_mismatches += draws.instances != visible.instances.size();
      gpu_drawn_total += draws.instances;
    }
    cap_hits += visible.stats.cap_hits;
    linked_cells_total += visible.linked_cells.size();
    frames_with_linked += !visible.linked_cells.empty();
    max_linked = std::max(max_linked, visible.linked_cells.size());
    if (!a.frames_dir.empty() && f % a.every == 0) {
      if (Status s = rendered.render(f, view, visible, world); !s) return fail(s);
      if (a.quiet && !a.json_lines && rendered.frames_written() % 50 == 0)
        std::fprintf(stderr, "rendered %zu of %zu frames\n", rendered.frames_written(),
                     (frames + a.every - 1) / a.every);
    }

    std::string moves;
    for (const CellTransition& tr : tracker.transitions()) {
      if (f > 0) {
        // A flap: going straight back to the cell just left, within a few frames.
        if (!history.empty() && history.back().to == tr.from && history.back().from == tr.to &&
            f - frame_of.back() <= a.flap_window)
          ++flaps;
        history.push_back(tr);
        frame_of.push_back(f);
      }
      moves += (moves.empty() ? "" : ", ") + (tr.from == kNoCell ? std::string("start") : world.cells[tr.from].name) +
               " -> " + world.cells[tr.to].name + " (" + transition_reason_name(tr.reason) + ")";
    }
    if (a.json_lines) {
      nlohmann::json line = visible_set_json(world, visible, /*with_regions=*/false);
      line.erase("visible_instances");
      nlohmann::json cell_names = nlohmann::json::array();
      for (const VisibleCell& c : visible.cells) cell_names.push_back(world.cells[c.cell].name);
      line["visible_cells"] = cell_names;
      line["frame"] = f;
      line["t"] = t;
      line["eye"] = {view.eye_world.x, view.eye_world.y, view.eye_world.z};
      line["viewer_cell"] = world.cells[tracker.cell()].name;
      if (!visible.linked_cells.empty()) {
        nlohmann::json linked = nlohmann::json::array();
        for (const VisibleCell& c : visible.linked_cells)
          linked.push_back({{"cell", world.cells[c.cell].name}, {"transform", c.transform}});
        line["linked_cells"] = linked;
      }
      line["transitions"] = moves;
      if (!doors.empty()) line["doors"] = doors;
      if (!carried.empty()) line["instances_changing_cell"] = carried;
      line["build_us"] = us;
      if (a.gpu_cull) line["gpu_drawn"] = {{"instances", draws.instances}, {"groups", draws.groups_drawing}};
      std::printf("%s\n", line.dump().c_str());
    } else if (!a.quiet) {
      const std::string gpu_note = a.gpu_cull ? "  gpu draws " + std::to_string(draws.instances) + " in " +
                                                    std::to_string(draws.groups_drawing) + " groups"
                                              : std::string();
      const std::string linked_note = visible.linked_cells.empty()
                                          ? std::string()
                                          : " + " + std::to_string(visible.linked_cells.size()) + " linked";
      std::printf("frame %4zu t=%6.2fs cell %-12s visible %2zu cells%s %4zu instances  pops %3llu  %7.1f us%s%s%s\n", f,
                  t, printable(world.cells[tracker.cell()].name).c_str(), visible.cells.size(), linked_note.c_str(),
                  visible.instances.size(), (unsigned long long)visible.stats.pops, us, gpu_note.c_str(),
                  moves.empty() ? "" : "  ", printable(moves).c_str());
      if (!doors.empty()) std::printf("           door events: %s\n", printable(doors).c_str());
      if (!carried.empty()) std::printf("           instances changing cell: %s\n", printable(carried).c_str());
    }
  }

  if (!a.frames_dir.empty()) {
    if (Status s = rendered.finish(timeline.fps / double(a.every), a.json_lines); !s) return fail(s);
    if (!a.json_lines)
      std::printf("rendered %zu frames, %.1f ms per frame on average\n", rendered.frames_written(),
                  rendered.total_ms() / double(std::max<size_t>(1, rendered.frames_written())));
  }
  const double median = percentile(build_us, 0.5), p99 = percentile(build_us, 0.99);
  const size_t instances_moved = size_t(std::count(ever_moved.begin(), ever_moved.end(), uint8_t(1)));
  if (a.json_lines) {
    nlohmann::json summary = {{"frames", frames},
                              {"transitions", history.size()},
                              {"portal_crossings", crossings},
                              {"flaps", flaps},
                              {"door_events", door_events},
                              {"instances_moved", instances_moved},
                              {"instance_moves", instance_moves},
                              {"instance_cell_changes", instance_cell_changes},
                              {"max_pops", max_pops},
                              {"cap_hits", cap_hits},
                              {"teleports", teleports},
                              {"jumps", jumps},
                              {"linked_cells", linked_cells_total},
                              {"frames_with_linked_cells", frames_with_linked},
                              {"max_linked_cells", max_linked},
                              {"median_build_us", median},
                              {"p99_build_us", p99},
                              {"timeline", timeline.name}};
    if (a.gpu_cull)
      summary["gpu"] = {{"device", gpu_cull.device_name()},
                        {"instances_drawn", gpu_drawn_total},
                        {"frames_differing_from_cpu", gpu_mismatches}};
    std::printf("%s\n", nlohmann::json{{"summary", summary}}.dump().c_str());
  } else {
    std::printf(
        "summary: %zu frames, %zu transitions, %zu portal crossings, %zu flaps, %zu door events, "
        "%zu moved instances (%zu moves, %zu cell changes), max pops %llu, cap hits %llu, build median %.1f us, "
        "p99 %.1f us\n",
        frames, history.size(), crossings, flaps, door_events, instances_moved, instance_moves, instance_cell_changes,
        (unsigned long long)max_pops, (unsigned long long)cap_hits, median, p99);
    if (jumps > 0)
      std::printf("jumps (eye moved more than %g m in a frame, re-located by containment): %zu\n", jump_distance_m,
                  jumps);
    if (linked_cells_total > 0 || teleports > 0)
      std::printf(
          "linked cells (drawn with a link transform): %zu over %zu frames, at most %zu per frame; %zu teleports\n",
          linked_cells_total, frames_with_linked, max_linked, teleports);
    if (a.gpu_cull)
      std::printf("gpu cull on %s: %llu instance draws over the walk, %zu frames differing from the CPU reference\n",
                  gpu_cull.device_name().c_str(), (unsigned long long)gpu_drawn_total, gpu_mismatches);
  }
  if (gpu_mismatches > 0)
    return fail(a.scene + ": the GPU cull drew a different number of instances than the CPU reference in " +
                std::to_string(gpu_mismatches) + " frames");
  return kExitOk;
}

}  // namespace

void add_walk_command(CLI::App& app, Command& run) {
  auto* cmd =
      app.add_subcommand("walk", "Run a camera timeline frame by frame: viewer cell, visible cells, build time");
  auto a = std::make_shared<WalkArgs>();
  cmd->add_option("scene", a->scene, "Scene file (.gltf or .glb)")->required();
  add_load_options(cmd, a->load);
  auto* name = cmd->add_option("--timeline", a->timeline, "Timeline in the scene (default: 'doorway', else the first)");
  cmd->add_option("--timeline-file", a->timeline_file, "Standalone timeline .json (docs/scene-format.md)")
      ->excludes(name);
  cmd->add_flag("--json-lines", a->json_lines, "One JSON object per frame, then {\"summary\": ...}");
  cmd->add_flag("-q,--quiet", a->quiet, "Print only the summary");
  cmd->add_flag("--gpu-cull", a->gpu_cull, "Also cull each frame's instances on the GPU and report its draws");
  cmd->add_option("--device", a->device, "Vulkan device for --gpu-cull: index or name substring")
      ->envname("LINTEL_VK_DEVICE");
  cmd->add_option("--flap-window", a->flap_window, "Frames within which A->B->A counts as a flap")
      ->capture_default_str();
  add_visibility_options(cmd, a->vis, /*camera_shape=*/false);
  cmd->add_option("--frames", a->frames_dir,
                  "Render the frames to PNGs in this directory (+ contact sheet, MP4 with ffmpeg)");
  cmd->add_option("--every", a->every, "With --frames: render every Nth frame")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  add_render_options(cmd, a->render, /*with_device=*/false);
  cmd->callback([&run, a] { run = [a] { return run_walk(*a); }; });
}

}  // namespace lintel::cli
