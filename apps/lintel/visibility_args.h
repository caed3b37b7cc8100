// Command-line options shared by the subcommands that run a visibility query (vis, walk, cull):
// camera shape and traversal settings, parsed once into View / VisibilityOptions.
#pragma once

#include <lintel/view.h>
#include <lintel/visibility_builder.h>
#include <lintel/visible_set.h>
#include <lintel/world.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace lintel::cli {

struct VisibilityArgs {
  float fov_y_deg = 70.0f;
  float aspect = 16.0f / 9.0f;
  float near_m = 0.05f;
  VisibilityOptions options;
};

// --fov/--aspect/--near (camera_shape) and --snap/--cap/--max-polygons (traversal).
void add_visibility_options(CLI::App* cmd, VisibilityArgs& args, bool camera_shape);

// The visible set as JSON: cells with their region polygons and rects, instances, stats.
nlohmann::json visible_set_json(const World& world, const VisibleSet& visible, bool with_regions);
nlohmann::json stats_json(const VisibilityStats& stats);

}  // namespace lintel::cli
