// `lintel bench cull`: instances culled per second, GPU pass against the CPU reference (1 and 2
// threads) on the same frames, 10k..16M instances: the synthetic frame (random cells, most of them
// visible) and the indoor frame (a generated building seen from its doorway timeline: few visible
// cells, instances clustered by cell). JSON to --out, a table on stdout.
#include "cli_common.h"

#include <lintel/cell_locate.h>
#include <lintel/tools/cull_bench.h>
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>
#include <lintel/timeline.h>
#include <lintel/visibility_builder.h>

#include <algorithm>
#include <cstdio>
#include <lintel/file_commit.h>
#include <memory>
#include <random>

namespace lintel::cli {
namespace {

struct BenchCullArgs {
  gpu::CullBenchOptions options;
  std::vector<std::string> frames = {"synthetic", "indoor"};
  uint32_t indoor_grid = 32;
  std::string append = "auto";
  std::string cell_order = "group";
  std::string straddlers = "auto";
  bool no_gpu = false;
  std::string out;
};

// The indoor frame's building and view, made once for all sizes: a grid of rooms and the frame of
// its doorway timeline with the median number of visible cells (its viewer cell located).
struct IndoorView {
  World world;
  View view;
  VisibleSet visible;
  std::vector<Aabb> cell_bounds_world;
};

Status make_indoor_view(uint32_t grid, IndoorView& out) {
  GridOptions options;
  options.width = grid;
  options.height = grid;
  const std::string label = "grid " + std::to_string(grid) + "x" + std::to_string(grid);
  if (Status s = build_world(generate_grid(options), label, out.world); !s) return s;
  auto doorway = std::find_if(out.world.timelines.begin(), out.world.timelines.end(),
                              [](const Timeline& t) { return t.name == "doorway"; });
  if (doorway == out.world.timelines.end()) return Status::internal(label + ": no doorway timeline");
  VisibilityBuilder builder;
  std::vector<std::pair<size_t, size_t>> frames;  // (visible cells, frame)
  const size_t count = timeline_frame_count(*doorway);
  for (size_t f = 0; f < count; ++f) {
    const View view = timeline_view(*doorway, double(f) / doorway->fps);
    if (!validate_view(view).ok()) continue;
    const uint32_t start = locate_cell(out.world, glm::dvec3(view.eye_world)).cell;
    if (Status s = builder.build(out.world, view, start, {}, out.visible); !s) return s;
    frames.emplace_back(out.visible.cells.size(), f);
  }
  if (frames.empty()) return Status::internal(label + ": no valid doorway frame");
  std::nth_element(frames.begin(), frames.begin() + frames.size() / 2, frames.end());
  out.view = timeline_view(*doorway, double(frames[frames.size() / 2].second) / doorway->fps);
  const uint32_t start = locate_cell(out.world, glm::dvec3(out.view.eye_world)).cell;
  if (Status s = builder.build(out.world, out.view, start, {}, out.visible); !s) return s;
  for (const Cell& cell : out.world.cells) {
    Aabb box;
    for (int k = 0; k < 8; ++k) {
      const Aabb& b = cell.volume_box_cell;
      const glm::vec3 corner((k & 1) ? b.max.x : b.min.x, (k & 2) ? b.max.y : b.min.y, (k & 4) ? b.max.z : b.min.z);
      box.extend(glm::vec3(cell.cell_to_world * glm::vec4(corner, 1.0f)));
    }
    out.cell_bounds_world.push_back(box);
  }
  return {};
}

// `instances` boxes (0.1..1 m) inside the rooms, the same number per room and listed room by room
// (clustered by cell, as a level's objects are), seen from the view above.
void make_indoor_frame(const IndoorView& indoor, uint32_t instances, uint32_t groups, gpu::BenchFrame& out) {
  const uint32_t cells = uint32_t(indoor.world.cells.size());
  std::mt19937_64 engine(7);
  auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * (double(engine() >> 11) * 0x1.0p-53); };
  std::vector<Aabb> boxes(instances);
  std::vector<uint32_t> cell_of(instances);
  for (uint32_t i = 0; i < instances; ++i) {
    const uint32_t c = uint32_t(uint64_t(i) * cells / instances);
    const Aabb& room = indoor.cell_bounds_world[c];
    const glm::dvec3 half(uniform(0.05, 0.5), uniform(0.05, 0.5), uniform(0.05, 0.5));
    glm::dvec3 center;
    for (int a = 0; a < 3; ++a) {
      const double lo = double(room.min[a]) + half[a], hi = double(room.max[a]) - half[a];
      center[a] = lo < hi ? uniform(lo, hi) : 0.5 * (double(room.min[a]) + double(room.max[a]));
    }
    boxes[i].min = glm::vec3(center - half);
    boxes[i].max = glm::vec3(center + half);
    cell_of[i] = c;
  }
  out.view = indoor.view;
  out.visible = indoor.visible;
  gpu::set_bench_instances(boxes, cell_of, cells, groups, out);
}

int run_bench_cull(BenchCullArgs a) {
  a.options.gpu = !a.no_gpu;
  const char* const appends[] = {"atomic", "subgroup", "workgroup", "auto"};
  a.options.pass.append =
      gpu::CullAppend(std::find(std::begin(appends), std::end(appends), a.append) - std::begin(appends));
  a.options.pass.sort_by_group = a.cell_order == "group";
  a.options.pass.straddlers = a.straddlers == "inline"     ? gpu::CullStraddlers::Inline
                              : a.straddlers == "deferred" ? gpu::CullStraddlers::Deferred
                                                           : gpu::CullStraddlers::Auto;
  if (!a.out.empty())
    if (std::string why = output_refusal(a.out); !why.empty()) return fail(a.out + ": " + why);
  a.options.frames.clear();
  auto indoor = std::make_shared<IndoorView>();
  for (const std::string& name : a.frames) {
    if (name == "synthetic") {
      a.options.frames.push_back({});
    } else if (name == "indoor") {
      if (Status s = make_indoor_view(a.indoor_grid, *indoor); !s) return fail(s);
      const uint32_t groups = a.options.groups;
      a.options.frames.push_back({"indoor", [indoor, groups](uint32_t n, gpu::BenchFrame& out) {
                                    make_indoor_frame(*indoor, n, groups, out);
                                    return Status{};
                                  }});
    } else {
      return fail(Status::error("--frames: '" + name + "' is neither 'synthetic' nor 'indoor'"));
    }
  }
  std::fprintf(stderr,
               "lintel: bench cull: %zu frame kinds x %zu sizes x (%s%zu CPU thread counts), %u repetitions each\n",
               a.options.frames.size(), a.options.instance_counts.size(), a.options.gpu ? "GPU + " : "",
               a.options.cpu_threads.size(), a.options.repetitions);
  gpu::CullBenchResult result;
  if (Status s = gpu::run_cull_benchmark(a.options, result); !s) return fail(s);
  std::printf("device: %s%s\n", result.device.empty() ? "(none)" : result.device.c_str(),
              result.device_is_cpu ? " (CPU device: wall clock only)" : "");
  std::printf("%-9s %-6s %7s %10s %6s %9s %12s %12s %12s %14s\n", "frame", "method", "threads", "instances", "cells",
              "drawn", "wall ms (med)", "cpu ms (med)", "gpu ms (med)", "instances/s");
  for (const gpu::CullBenchRow& r : result.rows)
    std::printf("%-9s %-6s %7u %10u %6u %9u %12.3f %12.3f %12.4f %14.3e\n", r.frame.c_str(), r.method.c_str(),
                r.threads, r.instances, r.visible_cells, r.visible, r.wall_ms_median, r.cpu_ms_median, r.gpu_ms_median,
                r.instances_per_second);
  if (!a.out.empty()) {
    if (Status s = commit_file(a.out, result.to_json() + "\n"); !s) return fail(s);
    std::printf("results: %s\n", a.out.c_str());
  }
  return kExitOk;
}

}  // namespace

void add_bench_cull_command(CLI::App& bench, Command& run) {
  auto* cmd = bench.add_subcommand("cull", "Instances culled per second: GPU pass vs CPU reference (1, 2 threads)");
  auto a = std::make_shared<BenchCullArgs>();
  cmd->add_option("--instances", a->options.instance_counts,
                  "Instance counts to measure, comma-separated (1..16777216)")
      ->delimiter(',')
      ->check(CLI::Range(1u, 1u << 24))
      ->capture_default_str();
  cmd->add_option("--frames", a->frames,
                  "Frame kinds, comma-separated: synthetic (random cells, 3/4 visible), indoor (a generated "
                  "building from its doorway timeline, few cells visible)")
      ->delimiter(',')
      ->check(CLI::IsMember({"synthetic", "indoor"}))
      ->capture_default_str();
  cmd->add_option("--indoor-grid", a->indoor_grid, "Rooms per side of the indoor frame's grid building")
      ->check(CLI::Range(2u, 64u))
      ->capture_default_str();
  cmd->add_option("--threads", a->options.cpu_threads, "CPU reference thread counts, comma-separated")
      ->delimiter(',')
      ->check(thread_count())
      ->capture_default_str();
  cmd->add_option("--repetitions", a->options.repetitions, "Timed runs per size and method (median reported)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->add_option("--device", a->options.device, "Vulkan device: index or name substring")->envname("LINTEL_VK_DEVICE");
  cmd->add_option("--append", a->append,
                  "How the GPU pass's survivors take their slots: atomic (one atomic each), subgroup, workgroup "
                  "(one atomic per draw group per subgroup / workgroup), auto (atomic on CPU devices, else subgroup)")
      ->check(CLI::IsMember({"atomic", "subgroup", "workgroup", "auto"}))
      ->capture_default_str();
  cmd->add_option("--cell-order", a->cell_order,
                  "Order of the GPU pass's instances within a cell: group (by draw group, then id) or id")
      ->check(CLI::IsMember({"group", "id"}))
      ->capture_default_str();
  cmd->add_option("--straddlers", a->straddlers,
                  "Boxes straddling the near or far plane: inline (clipped by every thread), deferred (a second, "
                  "indirect dispatch), auto (deferred on CPU devices)")
      ->check(CLI::IsMember({"inline", "deferred", "auto"}))
      ->capture_default_str();
  cmd->add_flag("--no-gpu", a->no_gpu, "CPU reference only");
  cmd->add_flag("--validation", a->options.validation, "Run under the Khronos validation layers (slow)");
  cmd->add_option("--out", a->out, "Write the results as JSON to this file");
  cmd->callback([&run, a] { run = [a] { return run_bench_cull(*a); }; });
}

}  // namespace lintel::cli
