// Where the GPU cull's time goes as the instance count grows (issue 10: a cliff between 2M and 4M
// instances on the H100, and a fixed cost of about 50 us per run). One synthetic frame
// (make_bench_frame) per size, culled in variants that each change one thing:
//   base        the pass as `lintel bench cull` runs it (CullAppend::Auto: subgroup slots on GPUs,
//               one atomic each on CPU devices; cells' ranges by draw group)
//   workgroup   one atomic per draw group per workgroup (CullAppend::Workgroup)
//   atomic_id   one atomic per survivor, cells' ranges in id order (sort_by_group = false)
//   rect_only   regions tested as rects (CullPassOptions::test_regions = false)
//   no_visible  no cell visible: no work item at all, only the pass's fixed cost (counter reset,
//               barriers, finalize)
//   one_cell    one cell visible (1/64 of the instances tested)
//   window_256k 256Ki instances per dispatch instead of 1Mi (4x the dispatches and barriers)
//   split4      each window's items in 4 dispatches (the dispatch count alone, same windows)
// Manual time = each run's GPU time from timestamps; on a CPU device (lavapipe) the wall time of
// run() (record + submit + wait). Google Benchmark reports the mean over its iterations; run with
// --benchmark_repetitions for medians. Rerun: docs/perf.md.
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

enum Variant : int { kBase, kWorkgroup, kAtomicById, kRectOnly, kNoVisible, kOneCell, kWindow256k, kSplit4 };
const char* const kVariantNames[] = {"base",       "workgroup", "atomic_id",   "rect_only",
                                     "no_visible", "one_cell",  "window_256k", "split4"};

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
  const bool timestamps = ctx->info().timestamps && ctx->info().type != VK_PHYSICAL_DEVICE_TYPE_CPU;
  lintel::gpu::BenchFrame frame;
  lintel::gpu::make_bench_frame(n, 64, groups, 1, frame);
  if (variant == kNoVisible || variant == kOneCell) {
    const uint32_t keep = frame.visible.cells.front().cell;
    for (uint32_t c = 0; c < frame.gpu_frame.cell_region.size(); ++c)
      if (variant == kNoVisible || c != keep) frame.gpu_frame.cell_region[c] = lintel::gpu::kNoRegion;
  }
  lintel::gpu::CullPassOptions options;
  options.timestamps = timestamps;
  options.test_regions = variant != kRectOnly;
  if (variant == kWorkgroup) options.append = lintel::gpu::CullAppend::Workgroup;
  if (variant == kAtomicById) options.append = lintel::gpu::CullAppend::Atomic;
  options.sort_by_group = variant != kAtomicById;
  if (variant == kWindow256k) options.instances_per_dispatch = 1u << 18;
  if (variant == kSplit4) options.work_per_dispatch = lintel::gpu::kMaxWorkPerDispatch / 4;
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
    const double ms = timestamps ? t.gpu_ms : t.wall_ms;
    gpu_ms_sum += ms;
    state.SetIterationTime(ms * 1e-3);
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * n);
  state.SetBytesProcessed(int64_t(state.iterations()) * n * int64_t(sizeof(lintel::gpu::GpuInstance)));
  state.SetLabel(std::string(kVariantNames[variant]) + " groups=" + std::to_string(groups) + " " + ctx->info().name);
  state.counters["gpu_us"] =
      benchmark::Counter(gpu_ms_sum * 1e3 / double(std::max<benchmark::IterationCount>(1, state.iterations())));
}

// The curve from 1M to 16M instances (1, 2, 4, 16M), each variant at 256 groups. LINTEL_SHAPE_SMALL=1 (lavapipe): 100k and 1M only.
void shape_args(benchmark::internal::Benchmark* b) {
  const bool small = std::getenv("LINTEL_SHAPE_SMALL") != nullptr;
  const std::vector<int64_t> sizes = small ? std::vector<int64_t>{100'000, 1'000'000}
                                           : std::vector<int64_t>{1'000'000, 2'000'000, 4'000'000, 16'000'000};
  std::vector<int64_t> variants;
  for (int v = kBase; v <= kSplit4; ++v) variants.push_back(v);
  b->ArgsProduct({sizes, variants, {256}});
}
BENCHMARK(BM_GpuCullShape)->Apply(shape_args)->UseManualTime()->Iterations(15)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
