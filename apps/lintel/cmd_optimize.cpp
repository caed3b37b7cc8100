// `lintel optimize IN -o OUT`: cells merged where a finer split buys no culling (lintel/optimize.h,
// docs/levels.md). The result is validated by the loader in memory before anything is written.
#include "optimize_args.h"

#include <lintel/optimize.h>
#include <lintel/scene_io.h>

#include <cstdio>

namespace lintel::cli {

void add_optimize_options(CLI::App* cmd, OptimizeOptions& options) {
  cmd->add_option("--min-open-fraction", options.min_open_fraction,
                  "Merge two cells when their portals open at least this fraction of their shared wall")
      ->check(finite_range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--sliver-volume", options.sliver_volume_m3, "A cell below this volume (m^3) is a sliver")
      ->check(finite_range(0.0, 1e9))
      ->capture_default_str();
  cmd->add_option("--sliver-thickness", options.sliver_thickness_m,
                  "A cell whose 3 volume / surface is below this (m) is a sliver")
      ->check(finite_range(0.0, 1e9))
      ->capture_default_str();
  cmd->add_option("--max-extent", options.max_extent_m, "A merged cell's world bounds stay within this (m)")
      ->check(finite_range(0.0, 1e9))
      ->capture_default_str();
}

void add_doom_sector_options(CLI::App* cmd, std::string& sectors, double& hull_excess, double& min_sector_excess) {
  cmd->add_option("--sectors", sectors,
                  "Sectors as cells: whole (one cell per sector) or convex (non-convex sectors split into convex "
                  "cells joined by always-open portals)")
      ->check(CLI::IsMember({"whole", "convex"}))
      ->capture_default_str();
  cmd->add_option("--convex-hull-excess", hull_excess,
                  "With --sectors convex: a cell's convex hull may exceed its area by this fraction (cells kept "
                  "together so that no cut runs close to a thing excepted)")
      ->check(finite_range(0.0, 10.0))
      ->capture_default_str();
  cmd->add_option("--convex-min-sector-excess", min_sector_excess,
                  "With --sectors convex: a sector whose convex hull exceeds its area by at most this fraction "
                  "stays one cell")
      ->check(finite_range(0.0, 10.0))
      ->capture_default_str();
}

Status optimize_and_save(const SceneDesc& scene, const std::string& label, const OptimizeOptions& options,
                         const std::string& output, OptimizeReport& report) {
  SceneDesc merged;
  if (Status s = optimize_scene(scene, label, options, merged, &report); !s) return s;
  World check;
  if (Status s = build_world(merged, output, check); !s)
    return Status::internal("optimize: the merged scene does not load: " + s.message());
  return save_scene(merged, output);
}

std::string optimize_summary(const OptimizeReport& r) {
  char line[256];
  std::snprintf(line, sizeof line,
                "%u cells -> %u (%u open-wall merges, %u slivers), %u portals -> %u, %u closable portals kept",
                r.cells_before, r.cells_after, r.open_wall_merges, r.sliver_merges, r.portals_before, r.portals_after,
                r.closable_portals);
  return line;
}

namespace {

struct OptimizeArgs {
  std::string input, output;
  LoadOptions load;
  OptimizeOptions options;
};

int run_optimize(const OptimizeArgs& a) {
  World world;
  if (Status s = load_scene(a.input, a.load, world, nullptr); !s) return fail(s);
  SceneDesc merged;
  OptimizeReport report;
  if (Status s = optimize_world(world, a.options, merged, &report); !s) return fail(s);
  World check;
  if (Status s = build_world(merged, a.output, check); !s)
    return fail(Status::internal("optimize: the merged scene does not load: " + s.message()));
  if (Status s = save_scene(merged, a.output); !s) return fail(s);
  std::printf("wrote %s: %s\n", a.output.c_str(), optimize_summary(report).c_str());
  return kExitOk;
}

}  // namespace

void add_optimize_command(CLI::App& app, Command& run) {
  auto a = std::make_shared<OptimizeArgs>();
  auto* cmd = app.add_subcommand("optimize", "Merge cells where a finer split buys no culling (stairs, slivers, ...)");
  cmd->add_option("input", a->input, "The Lintel scene")->required();
  cmd->add_option("-o,--output", a->output, "Output file: .gltf (+ .bin) or .glb")->required();
  add_load_options(cmd, a->load);
  add_optimize_options(cmd, a->options);
  cmd->callback([&run, a] { run = [a] { return run_optimize(*a); }; });
}

}  // namespace lintel::cli
