// The cull benchmark: one synthetic frame per size, culled by the GPU pass and by the CPU
// reference on 1..n threads (visible cells split between threads, each running
// lintel::cull_instances on its share), timed by wall clock; GPU timestamps where they mean
// something (not on CPU Vulkan devices such as lavapipe).
#include <lintel/gpu/context.h>
#include <lintel/tools/cull_bench.h>
#include <lintel/gpu/cull_pass.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <thread>
#include <time.h>

namespace lintel::gpu {
namespace {

// Deterministic everywhere: no std:: distributions.
struct Rng {
  std::mt19937_64 engine;
  double uniform() { return double(engine() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  uint32_t below(uint32_t n) { return uint32_t(uniform() * n) % n; }
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// CPU time of the whole process (every thread: the reference's, and lavapipe's, which runs the
// "GPU" pass on the CPU), in ms. On a shared, loaded machine wall time mostly measures waiting.
double process_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

Status bench_cpu(const BenchFrame& frame, uint32_t threads, uint32_t repetitions, CullBenchRow& row) {
  std::vector<VisibleSet> parts;
  std::vector<double> times, cpu;
  for (uint32_t r = 0; r <= repetitions; ++r) {
    const Clock::time_point start = Clock::now();
    const double cpu_start = process_cpu_ms();
    row.visible = cull_reference_threaded(frame, threads, parts);
    if (r > 0) cpu.push_back(process_cpu_ms() - cpu_start);
    if (r > 0) times.push_back(ms_since(start));  // run 0 warms caches and sizes the scratch
  }
  row.cpu_ms_median = median(cpu);
  row.method = "cpu";
  row.threads = threads;
  row.wall_ms_median = median(times);
  row.wall_ms_min = *std::min_element(times.begin(), times.end());
  return {};
}

Status bench_gpu(Context& ctx, const BenchFrame& frame, const CullBenchOptions& bench, bool timestamps,
                 CullBenchRow& row, std::string& append, bool& straddlers_deferred) {
  const uint32_t repetitions = std::max(1u, bench.repetitions);
  CullPassOptions options = bench.pass;
  options.timestamps = timestamps;
  std::unique_ptr<CullPass> pass;
  if (Status s = CullPass::create(ctx, options, pass); !s) return s;
  const char* const append_names[] = {"atomic", "subgroup", "workgroup"};
  append = append_names[std::min(2u, uint32_t(pass->append_mode()))];
  straddlers_deferred = pass->defers_straddlers();
  if (Status s = pass->set_scene(frame.gpu_scene); !s) return s;
  if (Status s = pass->set_frame(frame.gpu_frame); !s) return s;
  CullReadback rb;
  if (Status s = pass->run(&rb); !s) return s;  // warm-up, and the visible count
  std::vector<double> wall, gpu, cpu;
  for (uint32_t r = 0; r < repetitions; ++r) {
    CullTimings t;
    const double cpu_start = process_cpu_ms();
    if (Status s = pass->run(nullptr, &t); !s) return s;
    cpu.push_back(process_cpu_ms() - cpu_start);
    wall.push_back(t.wall_ms);
    if (t.gpu_ms >= 0.0) gpu.push_back(t.gpu_ms);
  }
  row.method = "gpu";
  row.threads = 0;
  row.visible = rb.stats.visible_instances;
  row.wall_ms_median = median(wall);
  row.wall_ms_min = *std::min_element(wall.begin(), wall.end());
  row.gpu_ms_median = gpu.empty() ? -1.0 : median(gpu);
  row.cpu_ms_median = median(cpu);
  return {};
}

}  // namespace

uint32_t cull_reference_threaded(const BenchFrame& frame, uint32_t threads, std::vector<VisibleSet>& parts) {
  threads = std::max(1u, threads);
  if (parts.size() != threads) {
    // Split once per frame and thread count; later calls only clear the instance lists.
    parts.assign(threads, frame.visible);
    for (VisibleSet& p : parts) p.cells.clear();
    size_t total = 0;
    for (const VisibleCell& c : frame.visible.cells)
      total += frame.cpu.cell_begin[c.cell + 1] - frame.cpu.cell_begin[c.cell];
    size_t done = 0;
    for (const VisibleCell& c : frame.visible.cells) {
      const uint32_t part = uint32_t(std::min<size_t>(threads - 1, total ? done * threads / total : 0));
      parts[part].cells.push_back(c);
      done += frame.cpu.cell_begin[c.cell + 1] - frame.cpu.cell_begin[c.cell];
    }
    for (VisibleSet& p : parts) p.instances.reserve(frame.cpu.size());
  }
  const glm::dmat4 view_proj = view_projection_d(frame.view);
  const glm::dvec3 eye(frame.view.eye_world);
  for (VisibleSet& p : parts) p.instances.clear();
  if (threads == 1) {
    cull_instances(frame.cpu, view_proj, eye, parts[0]);
  } else {
    std::vector<std::thread> pool;
    for (uint32_t t = 0; t < threads; ++t)
      pool.emplace_back([&, t] { cull_instances(frame.cpu, view_proj, eye, parts[t]); });
    for (std::thread& th : pool) th.join();
  }
  uint32_t visible = 0;
  for (const VisibleSet& p : parts) visible += uint32_t(p.instances.size());
  return visible;
}

void make_bench_frame(uint32_t instances, uint32_t cells, uint32_t groups, uint64_t seed, BenchFrame& out) {
  Rng rng{std::mt19937_64(seed)};
  cells = std::max(1u, cells);
  groups = std::max(1u, groups);
  out.view = View{};
  out.view.eye_world = {3.0f, 1.6f, -2.0f};
  out.view.target_world = {3.5f, 1.5f, -12.0f};
  out.view.fov_y_deg = 70.0f;
  out.view.aspect = 16.0f / 9.0f;
  out.view.near_m = 0.05f;
  out.view.far_m = 300.0f;

  // Regions: three quarters of the cells, 1..4 convex polygons each, 6..12 vertices on an ellipse.
  VisibleSet& vs = out.visible;
  vs.clear();
  vs.slot_of_cell.assign(cells, -1);
  for (uint32_t c = 0; c < cells; ++c) {
    if (rng.uniform() >= 0.75) continue;
    VisibleCell vc;
    vc.cell = c;
    vc.first_polygon = uint32_t(vs.polygons.size());
    vc.polygon_count = 1 + rng.below(4);
    for (uint32_t p = 0; p < vc.polygon_count; ++p) {
      const uint32_t n = 6 + rng.below(7);
      const double rx = rng.uniform(0.05, 0.6), ry = rng.uniform(0.05, 0.6);
      const double cx = rng.uniform(-1.0 + rx, 1.0 - rx), cy = rng.uniform(-1.0 + ry, 1.0 - ry);
      vs.polygons.push_back({uint32_t(vs.vertices_ndc.size()), n});
      for (uint32_t k = 0; k < n; ++k) {
        const double a = 2.0 * std::numbers::pi * k / n;
        const glm::vec2 v(float(cx + rx * std::cos(a)), float(cy + ry * std::sin(a)));
        vs.vertices_ndc.push_back(v);
        vc.rect_ndc.extend(v);
      }
    }
    vs.slot_of_cell[c] = int32_t(vs.cells.size());
    vs.cells.push_back(vc);
  }

  // Instances: boxes in a 200 m cube around the eye, cells random.
  std::vector<uint32_t> cell_of(instances);
  std::vector<Aabb> boxes(instances);
  const glm::dvec3 eye(out.view.eye_world);
  for (uint32_t i = 0; i < instances; ++i) {
    const glm::dvec3 center = eye + glm::dvec3(rng.uniform(-100, 100), rng.uniform(-20, 20), rng.uniform(-100, 100));
    const glm::dvec3 half(rng.uniform(0.1, 1.0), rng.uniform(0.1, 1.0), rng.uniform(0.1, 1.0));
    boxes[i].min = glm::vec3(center - half);
    boxes[i].max = glm::vec3(center + half);
    cell_of[i] = rng.below(cells);
  }
  set_bench_instances(boxes, cell_of, cells, groups, out);
}

void set_bench_instances(std::span<const Aabb> boxes, std::span<const uint32_t> cell_of, uint32_t cells,
                         uint32_t groups, BenchFrame& out) {
  const uint32_t instances = uint32_t(boxes.size());
  groups = std::max(1u, groups);
  std::vector<uint32_t> per_cell(cells, 0), per_group(groups, 0);
  for (uint32_t i = 0; i < instances; ++i) {
    ++per_cell[cell_of[i]];
    ++per_group[(i / 16) % groups];
  }

  // The reference's slots, as CullData::prepare lays it out (cell by cell, ascending instance).
  CullData& cpu = out.cpu;
  cpu.cell_begin.assign(cells + 1, 0);
  for (uint32_t c = 0; c < cells; ++c) cpu.cell_begin[c + 1] = cpu.cell_begin[c] + per_cell[c];
  cpu.slots.assign(instances, CullSlot{});
  std::vector<uint32_t> next(cpu.cell_begin.begin(), cpu.cell_begin.end() - 1);
  for (uint32_t i = 0; i < instances; ++i) {
    const uint32_t s = next[cell_of[i]]++;
    cpu.slots[s] = CullSlot{boxes[i].min, boxes[i].max, i, cell_of[i]};
  }

  // The GPU's scene, as pack_scene lays it out (a 36-index box mesh per group).
  CullScene& scene = out.gpu_scene;
  scene = CullScene{};
  scene.cell_count = cells;
  uint32_t base = 0;
  for (uint32_t g = 0; g < groups; ++g) {
    scene.groups.push_back({36, 36 * g, int32_t(8 * g), base, per_group[g]});
    base += per_group[g];
  }
  scene.id_capacity = base;
  scene.instances.resize(instances);
  for (uint32_t i = 0; i < instances; ++i)
    scene.instances[i] = {boxes[i].min, cell_of[i], boxes[i].max, (i / 16) % groups};
  pack_visible_set(out.visible, out.view, cells, out.gpu_frame);
}

Status run_cull_benchmark(const CullBenchOptions& options, CullBenchResult& out) {
  out = CullBenchResult{};
  out.dispatch_cap = kMaxInstancesPerDispatch;
  out.cell_order = options.pass.sort_by_group ? "group" : "id";
  // The device is created once the first frame is made, not before: on the H100 the clock
  // governor runs this light load at 345-510 MHz and boosts to 1980 MHz only for a few seconds
  // after a process creates its device, so a one-size run (docs/perf.md) is timed inside that
  // window rather than after the frame's generation has used it up.
  std::unique_ptr<Context> ctx;
  auto create_context = [&]() -> Status {
    ContextOptions ctx_options;
    ctx_options.device = options.device;
    ctx_options.validation = options.validation;
    if (Status s = Context::create(ctx_options, ctx); !s) return s;
    out.device = ctx->info().name;
    out.device_is_cpu = ctx->info().type == VK_PHYSICAL_DEVICE_TYPE_CPU;
    return {};
  };
  const uint32_t repetitions = std::max(1u, options.repetitions);
  BenchFrame frame;
  for (const BenchFrameKind& kind : options.frames)
    for (uint32_t n : options.instance_counts) {
      if (n == 0 || n > kMaxInstances)
        return Status::error("bench cull: instance count " + std::to_string(n) + " outside 1.." +
                             std::to_string(kMaxInstances));
      if (kind.make) {
        if (Status s = kind.make(n, frame); !s) return s;
      } else {
        make_bench_frame(n, options.cells, options.groups, options.seed, frame);
      }
      std::vector<CullBenchRow> rows;
      if (options.gpu && !ctx)
        if (Status s = create_context(); !s) return s;
      if (ctx) {
        CullBenchRow row;
        if (Status s = bench_gpu(*ctx, frame, options, !out.device_is_cpu, row, out.append, out.straddlers_deferred);
            !s)
          return s;
        rows.push_back(row);
      }
      for (uint32_t threads : options.cpu_threads) {
        CullBenchRow row;
        if (Status s = bench_cpu(frame, std::max(1u, threads), repetitions, row); !s) return s;
        rows.push_back(row);
      }
      for (CullBenchRow& row : rows) {
        row.frame = kind.name;
        row.visible_cells = uint32_t(frame.visible.cells.size());
        row.instances = n;
        row.instances_per_second = row.wall_ms_median > 0.0 ? double(n) / (row.wall_ms_median * 1e-3) : 0.0;
        // The GPU works in float, the reference in double: a few borderline instances may differ.
        const uint32_t allowance = 1 + rows.front().visible / 1000;
        if (uint32_t(std::abs(int64_t(row.visible) - int64_t(rows.front().visible))) > allowance)
          return Status::internal("bench cull: " + row.method + " drew " + std::to_string(row.visible) + " of " +
                                  std::to_string(n) + " instances, " + rows.front().method + " " +
                                  std::to_string(rows.front().visible));
        out.rows.push_back(row);
      }
    }
  if (ctx) {
    std::vector<std::string> messages = ctx->take_validation_messages();
    if (!messages.empty()) return Status::internal("bench cull: validation: " + messages.front());
  }
  return {};
}

std::string CullBenchResult::to_json() const {
  std::string json = "{\"device\": \"";
  for (char c : device) {
    if (c == '"' || c == '\\') json += '\\';
    if (static_cast<unsigned char>(c) >= 0x20) json += c;
  }
  char buf[512];
  std::snprintf(buf, sizeof(buf),
                "\", \"device_is_cpu\": %s, \"dispatch_cap\": %u, \"append\": \"%s\", \"cell_order\": \"%s\", "
                "\"straddlers\": \"%s\", \"rows\": [",
                device_is_cpu ? "true" : "false", dispatch_cap, append.c_str(), cell_order.c_str(),
                straddlers_deferred ? "deferred" : "inline");
  json += buf;
  for (size_t i = 0; i < rows.size(); ++i) {
    const CullBenchRow& r = rows[i];
    std::snprintf(
        buf, sizeof(buf),
        "%s{\"frame\": \"%s\", \"method\": \"%s\", \"threads\": %u, \"instances\": %u, \"visible_cells\": %u, "
        "\"visible\": %u, \"wall_ms_median\": %.4f, \"wall_ms_min\": %.4f, \"gpu_ms_median\": %.4f, "
        "\"cpu_ms_median\": %.4f, \"instances_per_second\": %.1f}",
        i ? ", " : "", r.frame.c_str(), r.method.c_str(), r.threads, r.instances, r.visible_cells, r.visible,
        r.wall_ms_median, r.wall_ms_min, r.gpu_ms_median, r.cpu_ms_median, r.instances_per_second);
    json += buf;
  }
  return json + "]}";
}

}  // namespace lintel::gpu
