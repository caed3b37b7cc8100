// `lintel bench accuracy`: every visibility method (exact oracle, Lintel's polygon regions over a
// sweep of snap lattices and caps, rect, planes, frustum, none) on the views of a set of scenes,
// scored against the Embree ground truth. CSV, JSON and charts to --out; a table on stdout.
// What the figures mean: docs/accuracy.md.
#include "cli_common.h"

#include <lintel/reference/accuracy_bench.h>
#include <lintel/reference/exact_oracle.h>
#include <lintel/ndc_snap.h>
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>
#include <lintel/reference/stability_suite.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace lintel::cli {
namespace {

struct BenchAccuracyArgs {
  std::vector<std::string> scenes;
  uint32_t views = 200;
  uint32_t resolution = 512;
  uint32_t random_scenes = 20;
  uint64_t seed = 1;
  std::string out = "out/accuracy";
  bool quick = false;
};

// A scene argument: a .gltf/.glb path, a committed scene name (scenes/NAME.gltf, looked up from
// the working folder upwards), or "random:SEED[:CELLS]".
Status load_bench_scene(const std::string& arg, AccuracyScene& out) {
  out.label = arg;
  if (arg.rfind("random:", 0) == 0) {
    RandomOptions o;
    unsigned long long seed = 1;
    unsigned cells = 0;
    const int got = std::sscanf(arg.c_str() + 7, "%llu:%u", &seed, &cells);
    if (got < 1) return Status::error(arg + ": expected random:SEED[:CELLS]");
    o.seed = seed;
    o.cells = got == 2 ? cells : 12 + uint32_t(seed * 7 % 13);  // 12..24 cells
    if (o.cells < 2 || o.cells > 4096) return Status::error(arg + ": CELLS must be in [2, 4096]");
    out.label = "random-" + std::to_string(seed) + "-" + std::to_string(o.cells);
    return build_world(generate_random(o), out.label, out.world);
  }
  std::string path = arg;
  if (!std::filesystem::exists(path)) {
    for (std::filesystem::path dir = std::filesystem::current_path(); !dir.empty(); dir = dir.parent_path()) {
      const auto candidate = dir / "scenes" / (arg + ".gltf");
      if (std::filesystem::exists(candidate)) {
        path = candidate.string();
        break;
      }
      if (dir == dir.parent_path()) break;
    }
  }
  std::vector<std::string> warnings;
  if (Status s = load_world(path, out.world, &warnings); !s) return s;
  out.label = std::filesystem::path(path).stem().string();
  return {};
}

std::vector<std::unique_ptr<CullMethod>> all_methods(bool quick) {
  std::vector<std::unique_ptr<CullMethod>> m;
  m.push_back(make_exact_method());
  // The snap sweep at the default cap, one lattice per decade of snap size 2/N: 7.8e-3 (256),
  // 9.8e-4 (2048), 6.1e-5 (32768), 7.6e-6 (262144) and 9.5e-7 NDC (2^21, the finest Lintel allows),
  // plus the default 1024 (2.0e-3).
  const std::vector<uint32_t> lattices =
      quick ? std::vector<uint32_t>{256, 1024, kMaxSnapLatticeCells}
            : std::vector<uint32_t>{256, 1024, 2048, 32768, 262144, kMaxSnapLatticeCells};
  for (uint32_t n : lattices) m.push_back(make_polygon_method(n, 16));
  const std::vector<uint32_t> caps = quick ? std::vector<uint32_t>{1, 4} : std::vector<uint32_t>{1, 2, 4, 8, 32};
  for (uint32_t k : caps) m.push_back(make_polygon_method(1024, k));
  m.push_back(make_rect_method());
  m.push_back(make_planes_method(16));
  m.push_back(make_frustum_method());
  m.push_back(make_none_method());
  // Portal visibility plus two-phase hierarchical-Z occlusion: a camera at rest (the last frame
  // was this view) at four depth-buffer sizes, and a camera cut on every view (the last frame was
  // the previous, unrelated view).
  const std::vector<uint32_t> hiz_sizes = quick ? std::vector<uint32_t>{128} : std::vector<uint32_t>{64, 128, 256, 512};
  for (uint32_t size : hiz_sizes) m.push_back(make_portal_hiz_method(size, HizHistory::Still));
  m.push_back(make_portal_hiz_method(128, HizHistory::Cut));
  return m;
}

std::string fn_text(uint64_t all, uint64_t few) { return std::to_string(all) + "(" + std::to_string(few) + ")"; }

int run_bench_accuracy(BenchAccuracyArgs a) {
  if (a.quick) {
    a.views = std::min<uint32_t>(a.views, 40);
    a.resolution = std::min<uint32_t>(a.resolution, 256);
    a.random_scenes = std::min<uint32_t>(a.random_scenes, 4);
  }
  if (a.scenes.empty()) {
    a.scenes = {"cottage", "grid16", "ring64"};
    for (uint32_t i = 1; i <= a.random_scenes; ++i) a.scenes.push_back("random:" + std::to_string(i));
  }
  std::vector<AccuracyScene> scenes(a.scenes.size());
  for (size_t i = 0; i < a.scenes.size(); ++i)
    if (Status s = load_bench_scene(a.scenes[i], scenes[i]); !s) return fail(s);
  AccuracyBenchOptions o;
  o.views_per_scene = a.views;
  o.resolution = a.resolution;
  o.seed = a.seed;
  std::fprintf(stderr, "lintel: bench accuracy: %zu scenes x %u views, %u^2 rays per view\n", scenes.size(), a.views,
               a.resolution);
  AccuracyBenchResult result;
  const bool quick = a.quick;
  if (Status s = run_accuracy_bench(
          scenes, [quick] { return all_methods(quick); }, o, result);
      !s)
    return fail(s);

  // FN columns: all false negatives, and in brackets those only <= kFewRays rays saw. "past rim":
  // (view, cell) / (view, instance) pairs only rays within the scene's float error of a portal
  // edge saw, which the method culls: not judged (ray_ground_truth.h), shown so nothing is hidden.
  std::printf("%-10s %-24s %6s %12s %12s %10s %9s %9s %8s %9s %9s\n", "method", "settings", "views", "cell FN(few)",
              "inst FN(few)", "past rim", "over-incl", "area/ex", "pops", "med ms", "p99 ms");
  const std::vector<MethodScore> merged = merge_scores(result.scores);
  for (const MethodScore& s : merged)
    std::printf(
        "%-10s %-24s %6u %12s %12s %10s %9.3f %9.4f %8.1f %9.4f %9.4f%s\n", s.method.c_str(), s.settings.c_str(),
        s.views, fn_text(s.cell_false_negatives, s.cell_false_negatives_few_rays).c_str(),
        fn_text(s.instance_false_negatives, s.instance_false_negatives_few_rays).c_str(),
        (std::to_string(s.cell_past_rim_culled) + "/" + std::to_string(s.instance_past_rim_culled)).c_str(),
        s.over_inclusion(), s.area_ratio(), s.views ? double(s.pops) / s.views : 0.0, median_ms(s.times_ms),
        percentile_ms(s.times_ms, 0.99),
        (s.claims_conservative && s.cell_false_negatives + s.instance_false_negatives) ? "  <- NOT conservative" : "");
  // The yardsticks: polygon at its defaults against exact, by the median over views.
  const auto find = [&](const char* method, const char* settings) -> const MethodScore* {
    for (const MethodScore& s : merged)
      if (s.method == method && s.settings == settings) return &s;
    return nullptr;
  };
  if (const MethodScore* e = find("exact", ""), *p = find("polygon", "lattice=1024 cap=16"); e && p)
    std::printf(
        "polygon (defaults) vs exact: median over-inclusion %.4f vs %.4f (%.4fx), median time %.4f vs %.4f ms "
        "(%.1fx faster)\n",
        p->median_over_inclusion(), e->median_over_inclusion(), p->median_over_inclusion() / e->median_over_inclusion(),
        median_ms(p->times_ms), median_ms(e->times_ms), median_ms(e->times_ms) / median_ms(p->times_ms));
  // How far box-vs-depth occlusion could go: the ground truth's own depths as the depth buffer.
  for (const MethodScore& s : merged)
    if (s.method == "portal+hiz" || (s.method == "polygon" && s.settings == "lattice=1024 cap=16"))
      std::printf("%s %s: over-inclusion %.3f; with an ideal box occlusion test on the rays' own depths %.3f\n",
                  s.method.c_str(), s.settings.c_str(), s.over_inclusion(), s.ideal_box_over_inclusion());
  if (!merged.empty())
    std::printf("rim rays (within the scene's float error of a portal edge, not judged): %.4f%% of all rays\n",
                100.0 * merged.front().rim_ray_fraction());
  for (const MethodScore& s : merged)
    if (!s.false_negative_examples.empty())
      std::fprintf(stderr, "false negative, %s %s: %s\n", s.method.c_str(), s.settings.c_str(),
                   s.false_negative_examples.front().c_str());
  std::printf("wall time: %.1f s\n", result.wall_s);
  std::vector<std::string> warnings;
  if (Status s = write_accuracy_outputs(result, a.out, warnings); !s) return fail(s);
  for (const std::string& w : warnings) warn(w);
  std::printf("results: %s/accuracy.{csv,json}, charts %s/*.{png,svg}\n", a.out.c_str(), a.out.c_str());
  return kExitOk;
}

struct BenchStabilityArgs {
  StabilityOptions options;
  std::string out = "out/stability";
};

int run_bench_stability(BenchStabilityArgs a) {
  const MethodFactory factory = [] {
    std::vector<std::unique_ptr<CullMethod>> m;
    m.push_back(make_exact_method());
    m.push_back(make_polygon_method(1024, 16));
    m.push_back(make_polygon_method(65536, 16));
    m.push_back(make_polygon_method(kMaxSnapLatticeCells, 16));
    m.push_back(make_rect_method());
    m.push_back(make_rect_method(4096, true));
    m.push_back(make_planes_method(16));
    m.push_back(make_frustum_method());
    m.push_back(make_portal_hiz_method(128, HizHistory::Still));
    return m;
  };
  StabilityResult result;
  if (Status s = run_stability_suite(factory, a.options, result); !s) return fail(s);
  if (Status s = write_stability_outputs(result, a.out); !s) return fail(s);
  std::ifstream md(a.out + "/stability.md");
  std::printf("%s", std::string(std::istreambuf_iterator<char>(md), {}).c_str());
  std::printf("wall time: %.1f s\nresults: %s/stability.{md,json}\n", result.wall_s, a.out.c_str());
  return kExitOk;
}

}  // namespace

void add_bench_accuracy_command(CLI::App& bench, Command& run) {
  auto* cmd = bench.add_subcommand("accuracy", "Visibility methods against ray-cast ground truth and the exact oracle");
  auto a = std::make_shared<BenchAccuracyArgs>();
  cmd->add_option("--scenes", a->scenes,
                  "Scenes: paths, committed names (cottage, grid16, ring64) or random:SEED[:CELLS]; "
                  "default: cottage, grid16, ring64 and --random-scenes random seeds")
      ->delimiter(',');
  cmd->add_option("--random-scenes", a->random_scenes, "Random scenes in the default list")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000));
  cmd->add_option("--views", a->views, "Views per scene")->check(CLI::Range(1, 100000))->capture_default_str();
  cmd->add_option("--resolution", a->resolution, "Ground-truth rays per axis")
      ->check(CLI::Range(1, 8192))
      ->capture_default_str();
  cmd->add_option("--seed", a->seed, "Seed of the view sampling")->capture_default_str();
  cmd->add_option("--out", a->out, "Output folder")->capture_default_str();
  cmd->add_flag("--quick", a->quick, "A short run: 4 random scenes, 40 views, 256^2 rays, fewer settings");
  cmd->callback([&run, a] { run = [a] { return run_bench_accuracy(*a); }; });

  auto* stab = bench.add_subcommand("stability", "Where methods fail: generated hard cases x every method");
  auto b = std::make_shared<BenchStabilityArgs>();
  stab->add_option("--views", b->options.views_per_case, "Views per case")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  stab->add_option("--resolution", b->options.resolution, "Ground-truth rays per axis")
      ->check(CLI::Range(1, 8192))
      ->capture_default_str();
  stab->add_option("--out", b->out, "Output folder (stability.md, stability.json)")->capture_default_str();
  stab->callback([&run, b] { run = [b] { return run_bench_stability(*b); }; });
}

}  // namespace lintel::cli
