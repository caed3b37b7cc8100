// Benchmark of the cull: instances culled per second by the GPU pass and by the CPU reference
// (lintel::cull_instances on 1 and 2 threads), on the same synthetic frame in one run. Used by
// `lintel bench cull` and by bench/gpu_cull_bench.cpp (Google Benchmark).
// Timing: wall clock around record + submit + wait on every device (lavapipe's timestamps are
// unreliable around compute); on real GPUs also timestamps around the cull dispatches.
#pragma once

#include <lintel/gpu/cull_data.h>
#include <lintel/gpu/cull_pass.h>
#include <lintel/instance_cull.h>
#include <lintel/status.h>
#include <lintel/view.h>
#include <lintel/visible_set.h>

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace lintel::gpu {

// One synthetic frame: `instances` boxes (0.2..2 m) spread through a 200 m cube around the eye
// over `cells` cells, three quarters of them visible with 1..4 convex regions of 6..12 vertices
// (portal-like shapes), groups interleaved. The same data for both sides: `cpu` (the reference's
// SoA) and `gpu_scene`/`gpu_frame` (packed as pack_scene/pack_visible_set would).
struct BenchFrame {
  View view;
  VisibleSet visible;  // regions; instances empty until culled
  CullData cpu;
  CullScene gpu_scene;
  CullFrame gpu_frame;
};
void make_bench_frame(uint32_t instances, uint32_t cells, uint32_t groups, uint64_t seed, BenchFrame& out);
// Sets a frame's instances on both sides: box i in cell cell_of[i] (< cells), group (i / 16) %
// groups (runs of 16, as a loader lists one mesh's instances); `cpu` laid out as CullData::prepare
// does, `gpu_scene` as pack_scene does. out.view and out.visible must be set: packs gpu_frame.
void set_bench_instances(std::span<const Aabb> boxes, std::span<const uint32_t> cell_of, uint32_t cells,
                         uint32_t groups, BenchFrame& out);

// A kind of benchmark frame: its name (the rows' `frame`) and how to make it for a size. Empty
// `make`: make_bench_frame with the options' cells, groups and seed ("synthetic"). Frames that need
// more than this library (the CLI's indoor frames use Lintel::scene's buildings) come from the caller.
struct BenchFrameKind {
  std::string name = "synthetic";
  std::function<Status(uint32_t instances, BenchFrame& out)> make;
};

// The CPU reference on `threads` threads: the visible cells split into shares of about equal
// instance counts, each culled by lintel::cull_instances on its own thread (threads == 1: the
// calling thread). Returns the instances drawn. `parts` is scratch holding the split: reuse it
// for repeated calls on the same frame and thread count, pass it empty for a new frame.
uint32_t cull_reference_threaded(const BenchFrame& frame, uint32_t threads, std::vector<VisibleSet>& parts);

struct CullBenchOptions {
  std::vector<uint32_t> instance_counts = {10'000, 100'000, 1'000'000, 4'000'000};
  std::vector<BenchFrameKind> frames = {BenchFrameKind{}};  // each size of each kind
  uint32_t cells = 64;
  uint32_t groups = 256;
  uint64_t seed = 1;
  uint32_t repetitions = 5;  // timed runs per size and method, after one warm-up run
  bool gpu = true;
  std::vector<uint32_t> cpu_threads = {1, 2};  // empty: no CPU rows
  std::string device;       // as ContextOptions::device ("": the first GPU; the CLI passes LINTEL_VK_DEVICE)
  bool validation = false;  // Khronos validation (slow; for checking the benchmark itself)
  CullPassOptions pass;     // the GPU pass's variant (append mode, cell order); timestamps are set here
};

struct CullBenchRow {
  std::string frame;     // the frame kind's name
  std::string method;    // "gpu" or "cpu"
  uint32_t threads = 0;  // CPU threads; 0 for the GPU
  uint32_t instances = 0;
  uint32_t visible = 0;  // instances drawn (the GPU's and the CPU's counts are checked equal)
  uint32_t visible_cells = 0;
  double wall_ms_median = 0.0;
  double wall_ms_min = 0.0;
  double gpu_ms_median = -1.0;  // timestamps; -1 where not taken (CPU rows, CPU Vulkan devices)
  // CPU time of the whole process (all threads; lavapipe's pass included): on a shared, loaded
  // machine closer to the work than wall time, which mostly measures waiting for a core.
  double cpu_ms_median = 0.0;
  double instances_per_second = 0.0;  // instances / median wall time
};

struct CullBenchResult {
  std::string device;                // the Vulkan device's name ("" when gpu was off)
  bool device_is_cpu = false;        // lavapipe & co: wall clock only
  uint32_t dispatch_cap = 0;         // kMaxInstancesPerDispatch
  std::string append;                // the GPU pass's slot mode in use: "atomic", "subgroup" or "workgroup"
  std::string cell_order;            // instances within a cell's range: "group" (then id) or "id"
  bool straddlers_deferred = false;  // boxes straddling the near or far plane tested by a second dispatch
  std::vector<CullBenchRow> rows;

  // {"device": ..., "rows": [{"frame": "synthetic", "method": "gpu", "threads": 0, "instances": ..., ...}, ...]}
  std::string to_json() const;
};

// Runs the benchmark. Errors: no usable Vulkan device (when gpu), the GPU and CPU visible counts
// disagreeing by more than the borderline allowance (0.1%), Vulkan failures.
Status run_cull_benchmark(const CullBenchOptions& options, CullBenchResult& out);

}  // namespace lintel::gpu
