// `lintel validate <scene>`: exit 0 when the scene loads, 2 with a one-line reason when not.
#include "cli_common.h"

#include <cstdio>

namespace lintel::cli {

void add_validate_command(CLI::App& app, Command& run) {
  auto* cmd = app.add_subcommand("validate", "Check a scene against the Lintel scene format (exit 0 or 2)");
  auto path = std::make_shared<std::string>();
  auto quiet = std::make_shared<bool>(false);
  auto load = std::make_shared<LoadOptions>();
  cmd->add_option("scene", *path, "Scene file (.gltf or .glb)")->required();
  cmd->add_flag("-q,--quiet", *quiet, "Print nothing on success");
  add_load_options(cmd, *load);
  cmd->callback([&run, path, quiet, load] {
    run = [path, quiet, load] {
      World world;
      std::vector<std::string> warnings;
      if (Status s = load_scene(*path, *load, world, &warnings, *quiet); !s) return fail(s);
      if (!*quiet)
        std::printf("%s: valid (%zu cells, %zu portals, %zu instances, %zu warnings)\n", path->c_str(),
                    world.cells.size(), world.portals.size(), world.instances.size(), warnings.size());
      return kExitOk;
    };
  });
}

}  // namespace lintel::cli
