// `lintel bench levels --wad freedoom1.wad`: every map (or --maps) imported with `import doom`,
// loaded, walked along its doorway timeline and scored on random views against the Embree ray
// cast. Per map: cells, portals, import and load time, build per frame (median, p99) on the walk
// and on the views, cap hits, over-inclusion, false negatives, flaps. JSON and a gnuplot chart of
// build time and over-inclusion against cell count to --out (docs/levels.md). With --optimize every
// map runs a second time after `lintel optimize`, and the chart shows both.
#include "optimize_args.h"

#include <lintel/reference/accuracy_bench.h>
#include <lintel/reference/bench_views.h>
#include <lintel/cell_locate.h>
#include <lintel/reference/chart_plot.h>
#include <lintel/reference/cull_method.h>
#include <lintel/doom_import.h>
#include <lintel/file_commit.h>
#include <lintel/reference/ray_ground_truth.h>
#include <lintel/scene_io.h>
#include <lintel/timeline.h>
#include <lintel/viewer_tracker.h>
#include <lintel/visibility_builder.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace lintel::cli {
namespace {

struct BenchLevelsArgs {
  std::string wad = "/usr/share/games/doom/freedoom1.wad";
  std::vector<std::string> maps;
  uint32_t views = 100;
  uint32_t resolution = 128;
  uint32_t flap_window = 3;
  std::string out = "out/levels";
  bool optimize = false;
  bool keep_going = false;  // a map that fails is listed in the report and the others still run
  OptimizeOptions optimize_options;
  std::string sectors = "convex";
  double hull_excess = DoomImportOptions{}.convex_hull_excess;
  double min_sector_excess = DoomImportOptions{}.convex_min_sector_excess;
};

struct MapResult {
  std::string map;
  bool optimized = false;
  OptimizeReport merge;
  double optimize_ms = 0.0;
  DoomImportStats stats;
  size_t cells = 0, portals = 0, instances = 0;
  double import_ms = 0.0, load_ms = 0.0;
  size_t walk_frames = 0, flaps = 0, crossings = 0;
  size_t jumps = 0;           // frames whose eye moved beyond the tracker's jump distance (teleporters)
  size_t views_rerooted = 0;  // portal views whose eye lay beyond a thin start cell (see below)
  uint64_t walk_cap_hits = 0, view_cap_hits = 0;
  std::vector<double> walk_us;
  MethodScore score;
  // Imported rows: the same views scored in sectors (a sector is drawn / seen when any of its cells
  // is), so that --sectors whole and convex compare on one scale.
  uint64_t true_sectors = 0, drawn_sectors = 0;
  double sector_over_inclusion() const { return true_sectors ? double(drawn_sectors) / double(true_sectors) : 0.0; }
};

// "sector_12" and "sector_12_3" (a cell of a split sector) -> 12; -1 for other names.
long sector_of_cell_name(const std::string& name) {
  if (name.rfind("sector_", 0) != 0) return -1;
  const char* digits = name.c_str() + 7;
  char* end = nullptr;
  const long s = std::strtol(digits, &end, 10);
  return end != digits && (*end == '\0' || *end == '_') ? s : -1;
}

// Drawn and ray-cast visible sectors summed over the views (imported maps: cells named by sector).
Status score_sectors(const World& world, const RayGroundTruth& rays, const std::vector<BenchView>& views,
                     uint32_t resolution, MapResult& r) {
  std::vector<long> sector(world.cells.size());
  long sectors = 0;
  for (size_t c = 0; c < world.cells.size(); ++c) {
    sector[c] = sector_of_cell_name(world.cells[c].name);
    if (sector[c] < 0) return Status::error(r.map + ": cell '" + world.cells[c].name + "' names no sector");
    sectors = std::max(sectors, sector[c] + 1);
  }
  std::unique_ptr<CullMethod> method = make_polygon_method(kDefaultSnapLatticeCells, 16);
  MethodResult result;
  GroundTruth gt;
  std::vector<uint8_t> seen, drawn;
  for (const BenchView& v : views) {
    rays.cast(ray_camera_of(v.view), resolution, gt);
    if (Status s = method->run(world, v.view, v.start_cell, result); !s) return s;
    seen.assign(size_t(sectors), 0);
    drawn.assign(size_t(sectors), 0);
    for (size_t c = 0; c < world.cells.size(); ++c) {
      seen[size_t(sector[c])] |= gt.cell_visible[c];
      drawn[size_t(sector[c])] |= result.cell_visible[c];
    }
    for (long s = 0; s < sectors; ++s) r.true_sectors += seen[size_t(s)], r.drawn_sectors += drawn[size_t(s)];
  }
  return {};
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

Status walk(const World& world, uint32_t flap_window, MapResult& r) {
  const Timeline& timeline = world.timelines.at(0);
  ViewerTracker tracker;
  VisibilityBuilder builder;
  VisibleSet visible;
  builder.prepare(world, {}, visible);  // as a game at load: the first frame allocates nothing either
  std::vector<CellTransition> history;
  std::vector<size_t> frame_of;
  r.walk_frames = timeline_frame_count(timeline);
  const double jump_distance_m = double(TrackerOptions{}.jump_distance_m);
  glm::vec3 previous_eye(0.0f);
  for (size_t f = 0; f < r.walk_frames; ++f) {
    const View view = timeline_view(timeline, timeline.keys.front().t + double(f) / timeline.fps);
    if (Status s = f == 0 ? tracker.reset(world, view.eye_world) : tracker.update(world, view.eye_world); !s) return s;
    if (f > 0 && glm::length(glm::dvec3(view.eye_world - previous_eye)) > jump_distance_m) ++r.jumps;
    previous_eye = view.eye_world;
    for (const CellTransition& tr : tracker.transitions()) {
      if (f == 0) continue;
      if (!history.empty() && history.back().to == tr.from && history.back().from == tr.to &&
          f - frame_of.back() <= flap_window)
        ++r.flaps;
      r.crossings += tr.reason == TransitionReason::PortalCrossing;
      history.push_back(tr);
      frame_of.push_back(f);
    }
    const auto t0 = std::chrono::steady_clock::now();
    if (Status s = builder.build(world, view, tracker.cell(), {}, visible); !s) return s;
    r.walk_us.push_back(ms_since(t0) * 1e3);
    r.walk_cap_hits += visible.stats.cap_hits;
  }
  return {};
}

// `s` of the same kind, its message replaced.
Status reworded(const Status& s, std::string message) {
  switch (s.kind()) {
    case StatusKind::BadInput:
      return Status::error(std::move(message));
    case StatusKind::Unsupported:
      return Status::unsupported(std::move(message));
    default:
      return Status::internal(std::move(message));
  }
}

Status bench_map(const BenchLevelsArgs& a, const std::string& map, bool optimized, MapResult& r) {
  r.map = map;
  r.optimized = optimized;
  SceneDesc scene;
  auto t0 = std::chrono::steady_clock::now();
  DoomImportOptions import_options;
  import_options.convex_cells = a.sectors == "convex";
  import_options.convex_hull_excess = a.hull_excess;
  import_options.convex_min_sector_excess = a.min_sector_excess;
  if (Status s = import_doom(a.wad, map, import_options, scene, &r.stats); !s) return s;
  r.import_ms = ms_since(t0);
  const std::string label = a.wad + ": map " + map;  // what a message past the import names
  if (optimized) {
    SceneDesc merged;
    t0 = std::chrono::steady_clock::now();
    if (Status s = optimize_scene(scene, label, a.optimize_options, merged, &r.merge); !s) return s;
    r.optimize_ms = ms_since(t0);
    scene = std::move(merged);
  }
  std::vector<uint8_t> glb;
  if (Status s = scene_to_glb(scene, glb); !s) return s;
  AccuracyScene level;
  level.label = map;
  t0 = std::chrono::steady_clock::now();
  if (Status s = load_world_from_memory(glb.data(), glb.size(), label, "", level.world); !s)
    return reworded(s, s.message() + " (in the imported" + (optimized ? " and optimized" : "") + " scene)");
  r.load_ms = ms_since(t0);
  r.cells = level.world.cells.size();
  r.portals = level.world.portals.size();
  r.instances = level.world.instances.size();
  if (Status s = walk(level.world, a.flap_window, r); !s) return reworded(s, label + ": walk: " + s.message());
  RayGroundTruth rays;
  if (Status s = rays.build(level.world); !s) return reworded(s, label + ": " + s.message());
  std::vector<BenchView> views = make_bench_views(level.world, rays, a.views, 1);
  // The views at portals put the eye up to 0.3 m off the plane and root it in the cell on that
  // side; a Doom door sector is 8 units (0.25 m) deep, so the eye may already stand in the next
  // cell. Such a view asks from the wrong cell (what it misses is not a false negative of the
  // method): root it where the eye is, by containment, and count it.
  const std::vector<double> volumes = cell_volumes_m3(level.world);
  for (BenchView& v : views)
    if (!cell_volume_contains(level.world, v.start_cell, glm::dvec3(v.view.eye_world))) {
      v.start_cell = locate_cell(level.world, glm::dvec3(v.view.eye_world), volumes).cell;
      ++r.views_rerooted;
    }
  std::vector<std::unique_ptr<CullMethod>> methods;
  methods.push_back(make_polygon_method(kDefaultSnapLatticeCells, 16));
  std::vector<MethodScore> scores;
  if (Status s = score_scene(level, rays, views, methods, a.resolution, scores); !s)
    return reworded(s, label + ": " + s.message());
  r.score = scores.at(0);
  if (!optimized) return score_sectors(level.world, rays, views, a.resolution, r);
  return {};
}

nlohmann::json to_json(const MapResult& r) {
  const MethodScore& s = r.score;
  std::vector<double> view_us;
  for (double ms : s.times_ms) view_us.push_back(ms * 1e3);
  return {{"map", r.map},
          {"optimized", r.optimized},
          {"optimize_ms", r.optimize_ms},
          {"open_wall_merges", r.merge.open_wall_merges},
          {"sliver_merges", r.merge.sliver_merges},
          {"sectors", r.stats.sectors},
          {"cells", r.cells},
          {"portals", r.portals},
          {"instances", r.instances},
          {"doors_opened", r.stats.doors},
          {"platforms_lowered", r.stats.lowered_floors},
          {"import_ms", r.import_ms},
          {"load_ms", r.load_ms},
          {"walk_frames", r.walk_frames},
          {"walk_crossings", r.crossings},
          {"walk_jumps", r.jumps},
          {"walk_build_us_median", median_ms(r.walk_us)},
          {"walk_build_us_p99", percentile_ms(r.walk_us, 0.99)},
          {"walk_cap_hits", r.walk_cap_hits},
          {"flaps", r.flaps},
          {"views", s.views},
          {"views_rerooted", r.views_rerooted},
          {"view_build_us_median", median_ms(view_us)},
          {"view_build_us_p99", percentile_ms(view_us, 0.99)},
          {"view_bound_hits", s.bound_hits},
          {"true_cells", s.true_cells},
          {"drawn_cells", s.drawn_cells},
          {"cell_over_inclusion", s.cell_over_inclusion()},
          {"true_sectors", r.true_sectors},
          {"drawn_sectors", r.drawn_sectors},
          {"sector_over_inclusion", r.sector_over_inclusion()},
          {"split_sectors", r.stats.split_sectors},
          {"inner_portals", r.stats.inner_portals},
          {"outline_failures", r.stats.outline_failures},
          {"instance_over_inclusion", s.over_inclusion()},
          {"cell_false_negatives", s.cell_false_negatives},
          {"instance_false_negatives", s.instance_false_negatives},
          {"cells_past_rim_culled", s.cell_past_rim_culled},
          {"false_negative_examples", s.false_negative_examples}};
}

std::string chart_data(const std::vector<MapResult>& results, bool optimized) {
  std::ostringstream dat;
  dat << "# map cells walk_build_us_median walk_build_us_p99 cell_over_inclusion\n";
  for (const MapResult& r : results)
    if (r.optimized == optimized)
      dat << r.map << ' ' << r.cells << ' ' << median_ms(r.walk_us) << ' ' << percentile_ms(r.walk_us, 0.99) << ' '
          << r.score.cell_over_inclusion() << '\n';
  return dat.str();
}

Status write_chart(const std::string& dir, const std::vector<MapResult>& results, bool optimized,
                   std::vector<std::string>& warnings) {
  // Without --optimize the second file is empty and its series plot nothing (gnuplot warns only).
  const std::string plot_median =
      optimized ? "plot 'levels.dat' using 2:3 with points pt 7 title 'median', '' using 2:4 with points pt 6 title "
                  "'p99', 'levels_optimized.dat' using 2:3 with points pt 5 title 'median, optimized', '' using 2:4 "
                  "with points pt 4 title 'p99, optimized'\n"
                : "plot 'levels.dat' using 2:3 with points pt 7 title 'median', '' using 2:4 with points pt 6 title "
                  "'p99'\n";
  const std::string plot_over = optimized
                                    ? "plot 'levels.dat' using 2:5 with points pt 7 title 'cells', "
                                      "'levels_optimized.dat' using 2:5 with points pt 5 title 'cells, optimized', "
                                      "1.3 with lines dt 2 title 'goal 1.3'\n"
                                    : "plot 'levels.dat' using 2:5 with points pt 7 title 'cells', 1.3 with lines "
                                      "dt 2 title 'goal 1.3'\n";
  std::string gp = kChartScriptPrologue;
  gp +=
      "set terminal pngcairo size 1100,450\nset output outdir.'levels.png'\nset multiplot layout 1,2\n"
      "set logscale x\nset xlabel 'cells'\nset grid\nset key top left\n"
      "set logscale y\nset ylabel 'build per frame (us)'\nset title 'Doorway walk: build per frame'\n" +
      plot_median + "set ylabel 'drawn / ray-cast visible cells'\nset title 'Over-inclusion (random views)'\n" +
      "unset logscale y\n" + plot_over + "unset multiplot\n";
  if (Status s = commit_file(dir + "/levels.dat", chart_data(results, false)); !s) return s;
  if (optimized)
    if (Status s = commit_file(dir + "/levels_optimized.dat", chart_data(results, true)); !s) return s;
  if (Status s = commit_file(dir + "/levels.gp", gp); !s) return s;
  return plot_charts(dir, "levels.gp", {"levels.png"}, warnings);
}

int run_bench_levels(const BenchLevelsArgs& a) {
  std::vector<std::string> maps = a.maps;
  if (maps.empty())
    if (Status s = doom_map_names(a.wad, maps); !s) return fail(s);
  std::error_code ec;
  std::filesystem::create_directories(a.out, ec);
  if (ec) return fail(a.out + ": cannot create the output folder: " + ec.message());
  std::vector<MapResult> results;
  nlohmann::json all = nlohmann::json::array();
  // caps: cap hits on the walk; view med/p99: the accuracy harness's time per view (build, instance
  // cull and its own bookkeeping); over: drawn / ray-cast visible cells; max/v: the worst view.
  std::printf("%-8s %6s %7s %8s %8s %9s %9s %9s %9s %5s %6s %6s %6s %4s %5s\n", "map", "cells", "portals", "import",
              "load", "walk med", "walk p99", "view med", "view p99", "caps", "over", "sector", "max/v", "FN", "flaps");
  nlohmann::json failed = nlohmann::json::array();
  std::string first_failure;
  for (const std::string& map : maps)
    for (bool optimized : {false, true}) {
      if (optimized && !a.optimize) continue;
      MapResult r;
      if (Status s = bench_map(a, map, optimized, r); !s) {
        if (!a.keep_going) return fail(s);
        // Listed, not fatal: one unreadable map of a PWAD should not void the rest of the run. Its
        // optimized run would fail the same way (or measure a map whose import failed): skipped.
        std::fprintf(stderr, "lintel: %s (map skipped: --keep-going)\n", s.message().c_str());
        std::printf("%-8s failed (stderr says why)\n", (map + (optimized ? "+o" : "")).c_str());
        std::fflush(stdout);
        failed.push_back({{"map", map}, {"optimized", optimized}, {"error", s.message()}});
        if (first_failure.empty()) first_failure = s.message();
        break;
      }
      std::vector<double> view_us;
      for (double ms : r.score.times_ms) view_us.push_back(ms * 1e3);
      double worst_view = 0.0;
      for (double v : r.score.view_over_inclusion) worst_view = std::max(worst_view, v);
      std::printf("%-8s %6zu %7zu %6.1fms %6.1fms %7.1fus %7.1fus %7.1fus %7.1fus %5llu %6.3f %6.3f %6.2f %4llu %5zu\n",
                  (map + (optimized ? "+o" : "")).c_str(), r.cells, r.portals, r.import_ms, r.load_ms,
                  median_ms(r.walk_us), percentile_ms(r.walk_us, 0.99), median_ms(view_us),
                  percentile_ms(view_us, 0.99), (unsigned long long)r.walk_cap_hits, r.score.cell_over_inclusion(),
                  r.sector_over_inclusion(), worst_view,
                  (unsigned long long)(r.score.cell_false_negatives + r.score.instance_false_negatives), r.flaps);
      std::fflush(stdout);
      all.push_back(to_json(r));
      results.push_back(std::move(r));
    }
  if (results.empty() && !failed.empty())
    return fail("every map failed (nothing written); the first: " + first_failure);
  const std::string json_text = nlohmann::json{{"wad", a.wad},
                                               {"views_per_map", a.views},
                                               {"resolution", a.resolution},
                                               {"maps", all},
                                               {"failed_maps", failed}}
                                    .dump(1) +
                                "\n";
  if (Status s = commit_file(a.out + "/levels.json", json_text); !s) return fail(s);
  std::vector<std::string> warnings;
  if (Status s = write_chart(a.out, results, a.optimize, warnings); !s) return fail(s);
  for (const std::string& w : warnings) std::fprintf(stderr, "lintel: warning: %s\n", w.c_str());
  std::printf("wrote %s/levels.json and %s/levels.png\n", a.out.c_str(), a.out.c_str());
  return kExitOk;
}

}  // namespace

void add_bench_levels_command(CLI::App& bench, Command& run) {
  auto a = std::make_shared<BenchLevelsArgs>();
  auto* cmd =
      bench.add_subcommand("levels", "Doom-format maps (Freedoom) imported, walked and scored against the ray cast");
  cmd->add_option("--wad", a->wad, "The WAD file")->capture_default_str();
  cmd->add_option("--maps", a->maps, "Maps to run (default: every map in the WAD)");
  cmd->add_option("--views", a->views, "Random views per map scored against the ray cast")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  cmd->add_option("--resolution", a->resolution, "Ground-truth rays per axis")
      ->check(CLI::Range(8, 4096))
      ->capture_default_str();
  cmd->add_option("--flap-window", a->flap_window, "Frames within which A->B->A counts as a flap")
      ->capture_default_str();
  cmd->add_flag("--optimize", a->optimize, "Run every map a second time after `lintel optimize` (rows marked +o)");
  cmd->add_flag("--keep-going", a->keep_going,
                "A map that fails (import, load or walk) is listed under failed_maps in levels.json and the "
                "run goes on (default: the first failure ends the run, exit 2, nothing written)");
  add_optimize_options(cmd, a->optimize_options);
  add_doom_sector_options(cmd, a->sectors, a->hull_excess, a->min_sector_excess);
  cmd->add_option("--out", a->out, "Output folder (levels.json, levels.png)")->capture_default_str();
  cmd->callback([&run, a] { run = [a] { return run_bench_levels(*a); }; });
}

}  // namespace lintel::cli
