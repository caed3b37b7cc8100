// Where the GPU cull's time goes as the instance count grows (issue: a cliff between 2M and 3M
// instances on the H100). One synthetic frame (make_bench_frame) per size, culled with GPU
// timestamps, in variants that each remove one suspect:
//   base        the frame as `lintel bench cull` runs it
//   no_visible  no cell visible: every instance read, none written (pure read + early-out)
//   by_cell     instances sorted by cell: region reads coherent within a subgroup
//   rect_only   regions tested as rects (CullPassOptions::test_regions = false)
//   no_ballot   one atomic per survivor (CullPassOptions::subgroup_aggregate = false)
//   window_256k 256Ki instances per dispatch instead of 1Mi
//   groups      1, 16, 256 or 4096 draw groups (counters the survivors' atomics spread over)
// Manual time = each run's GPU time from timestamps (Google Benchmark reports the mean over its
// iterations; run with --benchmark_repetitions for medians). Rerun: docs/perf.md.
#include <lintel/gpu/context.h>
#include <lintel/tools/cull_bench.h>
#include <lintel/gpu/cull_pass.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <numeric>
#include <string>

namespace {

enum Variant : int { kBase, kNoVisible, kByCell, kRectOnly, kNoBallot, kWindow256k };
const char* const kVariantNames[] = {"base", "no_visible", "by_cell", "rect_only", "no_ballot", "window_256k"};

lintel::gpu::Context* shared_context() {
  static std::unique_ptr<lintel::gpu::Context> ctx = [] {
    std::unique_ptr<lintel::gpu::Context> c;
    lintel::gpu::ContextOptions options;  // the library reads no environment; the benchmark does
    if (const char* selector = std::getenv("LINTEL_VK_DEVICE")) options.device = selector;
    if (!lintel::gpu::Context::create(options, c).ok()) c.reset();
    return c;
  }();
  return ctx.get();
}

void BM_GpuCullShape(benchmark::State& state) {
  const uint32_t n = uint32_t(state.range(0));
  const Variant variant = Variant(state.range(1));
  const uint32_t groups = uint32_t(state.range(2));
  lintel::gpu::Context* ctx = shared_context();
  if (!ctx) {
    state.SkipWithError("no Vulkan device");
    return;
  }
  if (!ctx->info().timestamps) {
    state.SkipWithError("the device has no timestamps");
    return;
  }
  lintel::gpu::BenchFrame frame;
  lintel::gpu::make_bench_frame(n, 64, groups, 1, frame);
  if (variant == kNoVisible)
    frame.gpu_frame.cell_region.assign(frame.gpu_frame.cell_region.size(), lintel::gpu::kNoRegion);
  if (variant == kByCell)
    std::stable_sort(
        frame.gpu_scene.instances.begin(), frame.gpu_scene.instances.end(),
        [](const lintel::gpu::GpuInstance& a, const lintel::gpu::GpuInstance& b) { return a.cell < b.cell; });
  lintel::gpu::CullPassOptions options;
  options.timestamps = true;
  options.test_regions = variant != kRectOnly;
  options.subgroup_aggregate = variant != kNoBallot;
  if (variant == kWindow256k) options.instances_per_dispatch = 1u << 18;
  std::unique_ptr<lintel::gpu::CullPass> pass;
  lintel::Status s = lintel::gpu::CullPass::create(*ctx, options, pass);
  if (s) s = pass->set_scene(frame.gpu_scene);
  if (s) s = pass->set_frame(frame.gpu_frame);
  if (!s) {
    state.SkipWithError(s.message().c_str());
    return;
  }
  double gpu_ms_sum = 0.0;
  for (auto _ : state) {
    lintel::gpu::CullTimings t;
    if (s = pass->run(nullptr, &t); !s) {
      state.SkipWithError(s.message().c_str());
      break;
    }
    gpu_ms_sum += t.gpu_ms;
    state.SetIterationTime(t.gpu_ms * 1e-3);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * n);
  state.SetBytesProcessed(int64_t(state.iterations()) * n * int64_t(sizeof(lintel::gpu::GpuInstance)));
  state.SetLabel(std::string(kVariantNames[variant]) + " groups=" + std::to_string(groups) + " " + ctx->info().name);
  state.counters["gpu_us"] =
      benchmark::Counter(gpu_ms_sum * 1e3 / double(std::max<benchmark::IterationCount>(1, state.iterations())));
}

// Sizes around both cliffs seen (H100: 2M -> 3M; H200: 4M -> 8M), each suspect at 256 groups,
// then the base frame with fewer and more draw groups (atomics spread over more counters).
BENCHMARK(BM_GpuCullShape)
    ->ArgsProduct({{1'000'000, 2'000'000, 3'000'000, 4'000'000, 5'000'000, 6'000'000, 8'000'000, 16'000'000},
                   {kBase, kNoVisible, kByCell, kRectOnly, kNoBallot, kWindow256k},
                   {256}})
    ->ArgsProduct({{1'000'000, 2'000'000, 3'000'000, 4'000'000, 5'000'000, 6'000'000, 8'000'000, 16'000'000},
                   {kBase},
                   {1, 16, 4096}})
    ->UseManualTime()
    ->Iterations(15)
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
