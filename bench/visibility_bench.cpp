// Visibility build time per frame against scene size (grids 4x4..64x64, rings 8..256, the
// cottage), time per traversed portal, and heap allocations per frame after warm-up; and, as
// build_cold/*, the same builds with every cache evicted before each one (a game's frame renders
// between two builds, so the builder and the World start cold), and as build_cold_data/* with
// the code warmed again after the eviction by a build of another small world (what of a cold
// build is its code and what its data).
// Views are the frames of each scene's "doorway" timeline, with the viewer cell tracked as a game
// would. Run: build/bin/visibility_bench (docs/perf.md has the figures and the exact command).
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>
#include <lintel/timeline.h>
#include <lintel/viewer_tracker.h>
#include <lintel/visibility_builder.h>

#include <benchmark/benchmark.h>

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <new>
#include <utility>
#include <vector>

namespace {

// Every heap allocation in this process, counted so that a frame's allocations can be measured.
std::atomic<uint64_t> g_allocations{0};

}  // namespace

// GCC pairs the inlined replacement delete's free() with new-expressions it cannot see through and
// warns; the pair below is consistent (malloc/free), so the warning is silenced here only.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace {

struct Frame {
  lintel::View view;
  uint32_t cell = 0;
};

struct BenchScene {
  lintel::World world;
  std::vector<Frame> frames;
};

// The scene and its doorway-timeline frames with tracked viewer cells, built once per name.
const BenchScene& scene(const std::string& kind, uint32_t size) {
  static std::map<std::string, BenchScene> cache;
  const std::string key = kind + std::to_string(size);
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  lintel::SceneDesc desc;
  if (kind == "grid")
    desc = lintel::generate_grid({size, size, false, 1});
  else if (kind == "ring")
    desc = lintel::generate_ring({size, 1});
  else
    desc = lintel::generate_cottage({1});
  BenchScene s;
  if (lintel::Status st = lintel::build_world(desc, key, s.world); !st) {
    std::fprintf(stderr, "%s\n", st.message().c_str());
    std::abort();
  }
  const lintel::Timeline& t = s.world.timelines[size_t(std::max(0, s.world.find_timeline("doorway")))];
  lintel::ViewerTracker tracker;
  for (size_t f = 0; f < lintel::timeline_frame_count(t); ++f) {
    Frame frame;
    frame.view = lintel::timeline_view(t, t.keys.front().t + double(f) / t.fps);
    const glm::vec3& eye = frame.view.eye_world;
    if (!(f == 0 ? tracker.reset(s.world, eye) : tracker.update(s.world, eye)).ok()) std::abort();
    frame.cell = tracker.cell();
    s.frames.push_back(frame);
  }
  return cache.emplace(key, std::move(s)).first->second;
}

// One build per iteration, cycling through the timeline's frames.
// cull_instances false: the portal flood alone, so the instance cull's share is the difference.
// Reads and writes every line of a buffer larger than the last-level cache (32 MB here), so that
// the next build finds nothing of its own data in any cache.
void evict_caches() {
  static std::vector<uint64_t> buffer(size_t(96) << 17);  // 96 MB
  uint64_t sum = 0;
  for (size_t i = 0; i < buffer.size(); i += 8) sum += buffer[i]++;
  benchmark::DoNotOptimize(sum);
}

enum class Caches { Warm, Cold, ColdData };

void run(benchmark::State& state, const std::string& kind, uint32_t size, bool cull_instances = true,
         Caches caches = Caches::Warm) {
  const BenchScene& s = scene(kind, size);
  lintel::VisibilityBuilder builder;
  lintel::VisibleSet visible;
  lintel::VisibilityOptions options;
  options.cull_instances = cull_instances;
  builder.prepare(s.world, options);
  for (const Frame& f : s.frames) {  // warm-up, and the only place a failed build is reported
    const lintel::Status status = builder.build(s.world, f.view, f.cell, options, visible);
    if (!status) {
      state.SkipWithError(status.message().c_str());
      return;
    }
  }
  // Allocations of one more pass over every frame, outside the timed loop (the benchmark library
  // allocates for itself while timing).
  const uint64_t allocations_before = g_allocations.load();
  for (const Frame& f : s.frames) (void)builder.build(s.world, f.view, f.cell, options, visible);
  const double allocations_per_frame = double(g_allocations.load() - allocations_before) / double(s.frames.size());
  uint64_t portals = 0, pops = 0, cells = 0, frames = 0;
  size_t next = 0;
  for (auto _ : state) {
    const Frame& f = s.frames[next];
    next = next + 1 == s.frames.size() ? 0 : next + 1;
    if (caches != Caches::Warm) {
      state.PauseTiming();
      evict_caches();
      if (caches == Caches::ColdData) {  // the same code on other data: a 4 x 4 grid, another builder
        static lintel::VisibilityBuilder other;
        static lintel::VisibleSet other_visible;
        const BenchScene& small = scene("grid", 4);
        const Frame& o = small.frames[next % small.frames.size()];
        (void)other.build(small.world, o.view, o.cell, options, other_visible);
      }
      state.ResumeTiming();
    }
    (void)builder.build(s.world, f.view, f.cell, options, visible);  // checked in the warm-up
    benchmark::DoNotOptimize(visible.cells.data());
    portals += visible.stats.portals_tested;
    pops += visible.stats.pops;
    cells += visible.cells.size();
    ++frames;
  }
  const double n = double(frames);
  state.counters["cells"] = double(s.world.cells.size());
  state.counters["visible_cells"] = double(cells) / n;
  state.counters["pops"] = double(pops) / n;
  state.counters["portals"] = double(portals) / n;
  state.counters["time_per_portal"] =
      benchmark::Counter(double(portals), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["allocs_per_frame"] = allocations_per_frame;
}

void register_all() {
  for (uint32_t n : {4u, 8u, 16u, 32u, 64u})
    benchmark::RegisterBenchmark(("build/grid" + std::to_string(n) + "x" + std::to_string(n)).c_str(),
                                 [n](benchmark::State& st) { run(st, "grid", n); })
        ->Unit(benchmark::kMicrosecond);
  for (uint32_t n : {8u, 32u, 64u, 128u, 256u})
    benchmark::RegisterBenchmark(("build/ring" + std::to_string(n)).c_str(), [n](benchmark::State& st) {
      run(st, "ring", n);
    })->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("build/cottage", [](benchmark::State& st) {
    run(st, "cottage", 0);
  })->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("build_without_instances/grid32x32", [](benchmark::State& st) {
    run(st, "grid", 32, false);
  })->Unit(benchmark::kMicrosecond);
  // Cold caches: each build after an eviction (the accuracy benchmark's small scenes).
  for (const auto& [prefix, caches] :
       {std::pair{"build_cold/", Caches::Cold}, {"build_cold_data/", Caches::ColdData}}) {
    const Caches c = caches;
    benchmark::RegisterBenchmark((std::string(prefix) + "cottage").c_str(),
                                 [c](benchmark::State& st) { run(st, "cottage", 0, true, c); })
        ->Unit(benchmark::kMicrosecond)
        ->Iterations(400);
    benchmark::RegisterBenchmark((std::string(prefix) + "grid16x16").c_str(),
                                 [c](benchmark::State& st) { run(st, "grid", 16, true, c); })
        ->Unit(benchmark::kMicrosecond)
        ->Iterations(400);
    benchmark::RegisterBenchmark((std::string(prefix) + "ring64").c_str(),
                                 [c](benchmark::State& st) { run(st, "ring", 64, true, c); })
        ->Unit(benchmark::kMicrosecond)
        ->Iterations(400);
  }
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
