// What `lintel optimize`, `import doom --optimize` and `bench levels --optimize` share: the merge
// options on a command line, the merge-validate-save step and the one-line summary.
#pragma once

#include "cli_common.h"

#include <lintel/optimize.h>

#include <string>

namespace lintel::cli {

// --min-open-fraction, --sliver-volume, --sliver-thickness, --max-extent.
void add_optimize_options(CLI::App* cmd, OptimizeOptions& options);

// Merges `scene`'s cells, checks the result with the loader in memory, then writes it to `output`.
Status optimize_and_save(const SceneDesc& scene, const std::string& label, const OptimizeOptions& options,
                         const std::string& output, OptimizeReport& report);

// What `import doom` and `bench levels` share: --sectors whole|convex (DoomImportOptions::convex_cells)
// --convex-hull-excess and --convex-min-sector-excess.
void add_doom_sector_options(CLI::App* cmd, std::string& sectors, double& hull_excess, double& min_sector_excess);

// "124 cells -> 80 (30 open-wall merges, 14 slivers), 412 portals -> 300, 0 closable portals kept"
std::string optimize_summary(const OptimizeReport& report);

}  // namespace lintel::cli
