// `lintel bench render`: the renderer's figures, in one run.
//   1. per-pass GPU time on the cottage's doorway timeline (median over views and repetitions);
//   2. grid 32x32 frame time with portal culling, frustum-only and no culling, same views;
//   3. (with the path tracer, --quality) image error of GI settings against a path-traced
//      reference, against frame time: quality_vs_cost.{csv,png,svg} (bench_render_quality.cpp).
// Writes DIR/render_bench.json; prints tables with progress on stderr.
#include "bench_render.h"
#include "cli_common.h"
#include "render_args.h"
#include "resource_budget.h"

#include <lintel/file_commit.h>
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>
#include <lintel/timeline.h>
#include <lintel/viewer_tracker.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>

namespace lintel::cli {

double median_of(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

Status timeline_views(const World& world, uint32_t count, std::vector<BenchView>& out) {
  out.clear();
  if (world.timelines.empty()) return Status::error(world.source + ": no timeline to take views from");
  const int d = world.find_timeline("doorway");
  const Timeline& t = world.timelines[size_t(std::max(0, d))];
  const size_t frames = timeline_frame_count(t);
  ViewerTracker tracker;
  const size_t stride = std::max<size_t>(1, frames / std::max<uint32_t>(1, count));
  for (size_t f = 0; f < frames; ++f) {
    View v = timeline_view(t, t.keys.front().t + double(f) / t.fps);
    if (Status s = f == 0 ? tracker.reset(world, v.eye_world) : tracker.update(world, v.eye_world); !s) return s;
    if (f % stride == stride / 2 && out.size() < count) out.push_back({v, tracker.cell()});
  }
  return {};
}

namespace {

struct BenchRenderArgs {
  std::string scene = "scenes/cottage.gltf", out = "out/bench-render";
  uint32_t views = 8, repetitions = 5, grid = 32, grid_views = 4;
  bool quality = false, skip_grid = false, gi_persist = false;
  QualityArgs quality_args;
  RenderArgs render;
  LoadOptions load;
};

struct ModeTimes {
  std::vector<double> wall_ms, gpu_ms;
  std::map<std::string, std::vector<double>> pass_ms;
  std::vector<double> cells, lights, shadow_views_drawn, gi_bounces;
  std::vector<double> draws_tested, draws_drawn;  // --cull portal+hiz: the portal cull's draws, and those drawn
};

Status measure(render::Renderer& r, const std::vector<BenchView>& views, uint32_t reps, uint32_t width, uint32_t height,
               ModeTimes& out) {
  render::RenderedFrame frame;
  for (const BenchView& bv : views) {
    View v = bv.view;
    v.aspect = float(width) / float(height);
    if (Status s = r.render(v, bv.cell, frame); !s) return s;  // warm-up (shader variants, caches)
    for (uint32_t k = 0; k < reps; ++k) {
      if (Status s = r.render(v, bv.cell, frame); !s) return s;
      double gpu = 0.0;
      for (const render::PassTime& p : frame.passes) {
        out.pass_ms[p.name].push_back(p.gpu_ms);
        gpu += p.gpu_ms;
      }
      out.wall_ms.push_back(frame.wall_ms);
      out.gpu_ms.push_back(gpu);
      out.cells.push_back(frame.cells_drawn);
      out.lights.push_back(frame.active_lights);
      out.shadow_views_drawn.push_back(frame.shadow_views_drawn);
      out.gi_bounces.push_back(frame.gi_bounces);
      out.draws_tested.push_back(frame.occlusion.tested);
      out.draws_drawn.push_back(frame.occlusion.drawn_early + frame.occlusion.drawn_late);
    }
  }
  return {};
}

nlohmann::json times_json(const ModeTimes& t) {
  nlohmann::json passes = nlohmann::json::object();
  for (const auto& [name, v] : t.pass_ms) passes[name] = median_of(v);
  return {{"median_wall_ms", median_of(t.wall_ms)},
          {"median_gpu_ms", median_of(t.gpu_ms)},
          {"median_cells_drawn", median_of(t.cells)},
          {"median_hiz_draws_tested", median_of(t.draws_tested)},
          {"median_hiz_draws_drawn", median_of(t.draws_drawn)},
          {"median_active_lights", median_of(t.lights)},
          {"passes_median_gpu_ms", passes},
          {"samples", t.wall_ms.size()},
          {"median_shadow_views_drawn", median_of(t.shadow_views_drawn)},
          {"median_gi_bounces", median_of(t.gi_bounces)}};
}

int run_bench_render(const BenchRenderArgs& a) {
  render::RenderOptions options;
  if (Status s = render_options_from(a.render, options); !s) return fail(s);
  options.gi_persist = a.gi_persist;
  World world;
  if (Status s = load_scene(a.scene, a.load, world, nullptr, true); !s) return fail(s);
  if (Status s = check_render_budget(world, options, a.load.max_memory_bytes); !s)
    return fail(a.scene + ": " + s.message());
  // Created only once the input is known good, so a bad scene leaves no empty folder behind.
  std::error_code ec;
  std::filesystem::create_directories(a.out, ec);
  if (!std::filesystem::is_directory(a.out)) return fail("--out " + a.out + ": cannot create the directory");
  std::vector<BenchView> views;
  if (Status s = timeline_views(world, a.views, views); !s) return fail(s);

  RenderSession session;
  if (Status s = open_render_session(world, a.render, options, session); !s) return fail(s);
  const std::string device = session.context->info().name;
  std::fprintf(stderr, "bench render: %s, %zu views x %u repetitions at %ux%u on %s\n", a.scene.c_str(), views.size(),
               a.repetitions, options.width, options.height, device.c_str());
  ModeTimes breakdown;
  if (Status s = measure(*session.renderer, views, a.repetitions, options.width, options.height, breakdown); !s)
    return fail(s);
  nlohmann::json result = {{"device", device},
                           {"scene", a.scene},
                           {"cull", a.render.cull},
                           {"width", options.width},
                           {"height", options.height},
                           {"views", views.size()},
                           {"repetitions", a.repetitions},
                           {"gi_persist", a.gi_persist},
                           {"gi_amortized_bounces", options.gi_options.amortized_bounces},
                           {"breakdown", times_json(breakdown)}};
  std::printf("per-pass GPU time, %s, %ux%u, %s (median of %zu frames):\n", a.scene.c_str(), options.width,
              options.height, device.c_str(), breakdown.wall_ms.size());
  for (const auto& [name, v] : breakdown.pass_ms) std::printf("  %-14s %9.3f ms\n", name.c_str(), median_of(v));
  std::printf("  %-14s %9.3f ms GPU, %.3f ms wall per frame\n", "total", median_of(breakdown.gpu_ms),
              median_of(breakdown.wall_ms));
  if (options.camera_cull == render::CameraCull::PortalHiz)
    std::printf("  occlusion: median %.0f draws of the portal cull, %.0f drawn\n", median_of(breakdown.draws_tested),
                median_of(breakdown.draws_drawn));
  session.renderer.reset();

  if (!a.skip_grid) {
    World grid;
    if (Status s = build_world(generate_grid({a.grid, a.grid, false, 1}), "grid" + std::to_string(a.grid), grid); !s)
      return fail(s);
    std::vector<BenchView> grid_views;
    if (Status s = timeline_views(grid, a.grid_views, grid_views); !s) return fail(s);
    nlohmann::json modes = nlohmann::json::object();
    std::printf("grid %ux%u, %zu views x %u repetitions, %ux%u:\n", a.grid, a.grid, grid_views.size(), a.repetitions,
                options.width, options.height);
    double portal_wall = 0.0;
    for (auto [mode, name] :
         {std::pair{render::CameraCull::Portal, "portal"}, std::pair{render::CameraCull::PortalHiz, "portal+hiz"},
          std::pair{render::CameraCull::Frustum, "frustum"}, std::pair{render::CameraCull::None, "none"}}) {
      std::fprintf(stderr, "  %s culling...\n", name);
      render::RenderOptions o = options;
      o.camera_cull = mode;
      std::unique_ptr<render::Renderer> r;
      if (Status s = render::Renderer::create(*session.context, grid, o, r); !s) return fail(s);
      ModeTimes t;
      if (Status s = measure(*r, grid_views, a.repetitions, o.width, o.height, t); !s) return fail(s);
      modes[name] = times_json(t);
      const double wall = median_of(t.wall_ms);
      if (mode == render::CameraCull::Portal) portal_wall = wall;
      std::printf("  %-10s %9.2f ms wall %9.2f ms GPU  cells drawn %5.0f  lights %4.0f  (%.2fx portal)\n", name, wall,
                  median_of(t.gpu_ms), median_of(t.cells), median_of(t.lights),
                  portal_wall > 0 ? wall / portal_wall : 0.0);
    }
    result["grid"] = {{"size", a.grid}, {"views", grid_views.size()}, {"modes", modes}};
  }

#ifdef LINTEL_HAVE_PATHTRACE
  if (a.quality) {
    nlohmann::json q;
    if (Status s = bench_render_quality(world, views, *session.context, options, a.quality_args, a.out, q); !s)
      return fail(s);
    result["quality"] = q;
  }
#else
  if (a.quality) warn("--quality needs the path tracer (built with LINTEL_BUILD_TESTS=ON); skipped");
#endif

  const std::string json_path = a.out + "/render_bench.json";
  if (Status s = commit_file(json_path, result.dump(2) + "\n"); !s) return fail(s);
  std::printf("results: %s\n", json_path.c_str());
  return kExitOk;
}

}  // namespace

void add_bench_render_command(CLI::App& bench, Command& run) {
  auto* cmd =
      bench.add_subcommand("render", "Renderer frame time per pass, portal vs frustum vs no culling, quality vs cost");
  auto a = std::make_shared<BenchRenderArgs>();
  cmd->add_option("--scene", a->scene, "Scene for the per-pass breakdown (its doorway timeline gives the views)")
      ->capture_default_str();
  add_load_options(cmd, a->load);
  cmd->add_option("--views", a->views, "Views along the timeline")->capture_default_str()->check(CLI::Range(1, 1000));
  cmd->add_option("--repetitions", a->repetitions, "Timed renders per view (after one warm-up)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--grid", a->grid, "Grid size for the culling comparison")
      ->capture_default_str()
      ->check(CLI::Range(2, 64));
  cmd->add_option("--grid-views", a->grid_views, "Views of the grid comparison")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  cmd->add_flag("--skip-grid", a->skip_grid, "Leave out the grid comparison");
  cmd->add_flag("--gi-persist", a->gi_persist,
                "Keep the GI probes between renders, as a walk does: each view's warm-up runs every GI iteration, "
                "its timed renders --gi-amortize of them");
  cmd->add_flag("--quality", a->quality, "Also chart GI image error against a path-traced reference vs frame time");
  cmd->add_flag("--quality-default-only", a->quality_args.default_only,
                "With --quality: only the default GI setting (a quick check of a GI change)");
  cmd->add_option("--ref-spp", a->quality_args.ref_spp, "Path-traced reference samples per pixel")
      ->capture_default_str()
      ->check(CLI::Range(1, 65536));
  cmd->add_option("--ref-bounces", a->quality_args.ref_bounces,
                  "Path-traced reference's diffuse bounces (the realtime default runs 8 GI iterations)")
      ->capture_default_str()
      ->check(CLI::Range(0, 64));
  cmd->add_option("--out", a->out, "Output directory")->capture_default_str();
  add_render_options(cmd, a->render);
  cmd->callback([&run, a] { run = [a] { return run_bench_render(*a); }; });
}

}  // namespace lintel::cli
