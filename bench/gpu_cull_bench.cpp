// Google Benchmark of the cull (the same frames as `lintel bench cull`): the GPU pass and the CPU
// reference on 1 and 2 threads, items = instances culled. GPU iterations are timed by wall clock
// around record + submit + wait (lavapipe's timestamps are unreliable around compute).
//   build/bin/gpu_cull_bench --benchmark_filter=Gpu
// A GPU's clock governor may run a light load at a fraction of its clock; these iterations run
// back to back, as a game's frame loop keeps the GPU busy (scripts/device/cull-sustained.sh logs
// the clock beside them; docs/perf.md, "Under a sustained load").
#include <lintel/gpu/context.h>
#include <lintel/tools/cull_bench.h>
#include <lintel/gpu/cull_pass.h>

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <memory>

namespace {

constexpr uint32_t kCells = 64;
constexpr uint32_t kGroups = 256;

// One Vulkan context for the whole process, as a game has (the NVIDIA driver refused new
// instances after several were created and destroyed in one process: VK_ERROR_INCOMPATIBLE_DRIVER).
lintel::Status shared_context(lintel::gpu::Context*& out) {
  static std::unique_ptr<lintel::gpu::Context> ctx;
  static lintel::Status status;
  if (!ctx && status) {
    lintel::gpu::ContextOptions options;  // the library reads no environment; the benchmark does
    if (const char* selector = std::getenv("LINTEL_VK_DEVICE")) options.device = selector;
    status = lintel::gpu::Context::create(options, ctx);
  }
  out = ctx.get();
  return status;
}

void BM_GpuCull(benchmark::State& state) {
  const uint32_t n = uint32_t(state.range(0));
  lintel::gpu::Context* ctx = nullptr;
  lintel::Status s = shared_context(ctx);
  std::unique_ptr<lintel::gpu::CullPass> pass;
  lintel::gpu::CullPassOptions pass_options;
  // GPU timestamps where they are reliable (not on lavapipe, a CPU device).
  if (s) pass_options.timestamps = ctx->info().type != VK_PHYSICAL_DEVICE_TYPE_CPU;
  if (s) s = lintel::gpu::CullPass::create(*ctx, pass_options, pass);
  lintel::gpu::BenchFrame frame;
  lintel::gpu::make_bench_frame(n, kCells, kGroups, 1, frame);
  if (s) s = pass->set_scene(frame.gpu_scene);
  if (s) s = pass->set_frame(frame.gpu_frame);
  if (!s) {
    state.SkipWithError(s.message().c_str());
    return;
  }
  double gpu_ms = 0.0;
  for (auto _ : state) {
    lintel::gpu::CullTimings t;
    if (s = pass->run(nullptr, &t); !s) {
      state.SkipWithError(s.message().c_str());
      break;
    }
    state.SetIterationTime(t.wall_ms * 1e-3);
    gpu_ms += t.gpu_ms;
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * n);
  // The passes' own time by GPU timestamps, averaged over the iterations (negative where the
  // device has no usable timestamps, as on lavapipe). The iterations run back to back: a
  // sustained load, which is what a GPU's clock governor sees in a game's frame loop.
  state.counters["gpu_ms"] = benchmark::Counter(gpu_ms, benchmark::Counter::kAvgIterations);
  state.SetLabel(ctx->info().name);
}

void BM_CpuCull(benchmark::State& state) {
  const uint32_t n = uint32_t(state.range(0));
  const uint32_t threads = uint32_t(state.range(1));
  lintel::gpu::BenchFrame frame;
  lintel::gpu::make_bench_frame(n, kCells, kGroups, 1, frame);
  std::vector<lintel::VisibleSet> parts;
  for (auto _ : state) benchmark::DoNotOptimize(lintel::gpu::cull_reference_threaded(frame, threads, parts));
  state.SetItemsProcessed(int64_t(state.iterations()) * n);
}

BENCHMARK(BM_GpuCull)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Arg(1'000'000)
    ->Arg(2'000'000)
    ->Arg(3'000'000)
    ->Arg(4'000'000)
    ->Arg(8'000'000)
    ->Arg(16'000'000)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CpuCull)
    ->ArgsProduct({{10'000, 100'000, 1'000'000, 4'000'000}, {1, 2}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
