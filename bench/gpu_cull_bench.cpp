// Google Benchmark of the cull (the same frames as `lintel bench cull`): the GPU pass and the CPU
// reference on 1 and 2 threads, items = instances culled. GPU iterations are timed by wall clock
// around record + submit + wait (lavapipe's timestamps are unreliable around compute).
//   build/bin/gpu_cull_bench --benchmark_filter=Gpu
#include <lintel/gpu/context.h>
#include <lintel/tools/cull_bench.h>
#include <lintel/gpu/cull_pass.h>

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <memory>

namespace {

constexpr uint32_t kCells = 64;
constexpr uint32_t kGroups = 256;

void BM_GpuCull(benchmark::State& state) {
  const uint32_t n = uint32_t(state.range(0));
  std::unique_ptr<lintel::gpu::Context> ctx;
  lintel::gpu::ContextOptions options;  // the library reads no environment; the benchmark does
  if (const char* selector = std::getenv("LINTEL_VK_DEVICE")) options.device = selector;
  lintel::Status s = lintel::gpu::Context::create(options, ctx);
  std::unique_ptr<lintel::gpu::CullPass> pass;
  if (s) s = lintel::gpu::CullPass::create(*ctx, {}, pass);
  lintel::gpu::BenchFrame frame;
  lintel::gpu::make_bench_frame(n, kCells, kGroups, 1, frame);
  if (s) s = pass->set_scene(frame.gpu_scene);
  if (s) s = pass->set_frame(frame.gpu_frame);
  if (!s) {
    state.SkipWithError(s.message().c_str());
    return;
  }
  for (auto _ : state) {
    lintel::gpu::CullTimings t;
    if (s = pass->run(nullptr, &t); !s) {
      state.SkipWithError(s.message().c_str());
      break;
    }
    state.SetIterationTime(t.wall_ms * 1e-3);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * n);
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
    ->Arg(4'000'000)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CpuCull)
    ->ArgsProduct({{10'000, 100'000, 1'000'000, 4'000'000}, {1, 2}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
