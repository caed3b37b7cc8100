// `lintel bench <what>`: the measurements the docs quote. Each kind lives in its own file and
// registers itself on the `bench` group here.
#include "cli_common.h"

namespace lintel::cli {

void add_bench_command(CLI::App& app, Command& run) {
  auto* bench = app.add_subcommand("bench", "Measure speed and accuracy (cull, render, accuracy, stability)");
  bench->require_subcommand(1);
  add_bench_cull_command(*bench, run);
  add_bench_render_command(*bench, run);
#ifdef LINTEL_HAVE_BENCH_ACCURACY
  add_bench_accuracy_command(*bench, run);
  add_bench_levels_command(*bench, run);
#endif
}

}  // namespace lintel::cli
