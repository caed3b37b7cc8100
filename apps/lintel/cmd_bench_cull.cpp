// `lintel bench cull`: instances culled per second, GPU pass against the CPU reference (1 and 2
// threads) on the same synthetic frames, for 10k..4M instances. JSON to --out, a table on stdout.
#include "cli_common.h"

#include <lintel/tools/cull_bench.h>

#include <cstdio>
#include <lintel/file_commit.h>

namespace lintel::cli {
namespace {

struct BenchCullArgs {
  gpu::CullBenchOptions options;
  bool no_gpu = false;
  std::string out;
};

int run_bench_cull(BenchCullArgs a) {
  a.options.gpu = !a.no_gpu;
  if (!a.out.empty())
    if (std::string why = output_refusal(a.out); !why.empty()) return fail(a.out + ": " + why);
  std::fprintf(stderr, "lintel: bench cull: %zu sizes x (%s%zu CPU thread counts), %u repetitions each\n",
               a.options.instance_counts.size(), a.options.gpu ? "GPU + " : "", a.options.cpu_threads.size(),
               a.options.repetitions);
  gpu::CullBenchResult result;
  if (Status s = gpu::run_cull_benchmark(a.options, result); !s) return fail(s);
  std::printf("device: %s%s\n", result.device.empty() ? "(none)" : result.device.c_str(),
              result.device_is_cpu ? " (CPU device: wall clock only)" : "");
  std::printf("%-6s %7s %10s %9s %12s %12s %14s\n", "method", "threads", "instances", "drawn", "wall ms (med)",
              "gpu ms (med)", "instances/s");
  for (const gpu::CullBenchRow& r : result.rows)
    std::printf("%-6s %7u %10u %9u %12.3f %12.4f %14.3e\n", r.method.c_str(), r.threads, r.instances, r.visible,
                r.wall_ms_median, r.gpu_ms_median, r.instances_per_second);
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
                  "Instance counts to measure, comma-separated (1..67108864)")
      ->delimiter(',')
      ->check(CLI::Range(1u, 1u << 26))
      ->capture_default_str();
  cmd->add_option("--threads", a->options.cpu_threads, "CPU reference thread counts, comma-separated")
      ->delimiter(',')
      ->check(thread_count())
      ->capture_default_str();
  cmd->add_option("--repetitions", a->options.repetitions, "Timed runs per size and method (median reported)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->add_option("--device", a->options.device, "Vulkan device: index or name substring")->envname("LINTEL_VK_DEVICE");
  cmd->add_flag("--no-gpu", a->no_gpu, "CPU reference only");
  cmd->add_flag("--validation", a->options.validation, "Run under the Khronos validation layers (slow)");
  cmd->add_option("--out", a->out, "Write the results as JSON to this file");
  cmd->callback([&run, a] { run = [a] { return run_bench_cull(*a); }; });
}

}  // namespace lintel::cli
