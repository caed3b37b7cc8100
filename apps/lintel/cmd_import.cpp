// `lintel import doom WAD MAP -o FILE`: a Doom-format map as a Lintel scene (docs/levels.md).
// The scene is validated by the loader before the command reports success.
#include "cli_common.h"

#include <lintel/doom_import.h>
#include <lintel/scene_io.h>

#include <cstdio>

namespace lintel::cli {
namespace {

struct ImportDoomArgs {
  std::string wad, map, output, doors = "open";
};

int import_doom_map(const ImportDoomArgs& args) {
  DoomImportOptions options;
  options.doors_open = args.doors == "open";
  SceneDesc scene;
  DoomImportStats stats;
  if (Status s = import_doom(args.wad, args.map, options, scene, &stats); !s) return fail(s);
  if (Status s = save_scene(scene, args.output); !s) return fail(s);
  std::printf("wrote %s: map %s, %u sectors -> %u cells (%u solid, %u doors opened), %u portals, %u instances, "
              "%u lights, doorway walk through %u portals\n",
              args.output.c_str(), args.map.c_str(), stats.sectors, stats.cells, stats.solid_sectors, stats.doors,
              stats.portals, stats.instances, stats.lights, stats.walk_crossings);
  return kExitOk;
}

}  // namespace

void add_import_command(CLI::App& app, Command& run) {
  auto* import = app.add_subcommand("import", "Convert a level from another format into a Lintel scene");
  import->require_subcommand(1);
  auto args = std::make_shared<ImportDoomArgs>();
  auto* doom = import->add_subcommand("doom", "A Doom-format map (e.g. Freedoom's freedoom1.wad, E1M1) -> scene");
  doom->add_option("wad", args->wad, "The WAD file (IWAD or PWAD)")->required();
  doom->add_option("map", args->map, "Map name: E1M1, MAP01, ...")->required();
  doom->add_option("-o,--output", args->output, "Output file: .gltf (+ .bin) or .glb")->required();
  doom->add_option("--doors", args->doors, "Closed doors: open (opened portals) or closed (portals marked open: false)")
      ->check(CLI::IsMember({"open", "closed"}))
      ->capture_default_str();
  doom->callback([&run, args] { run = [args] { return import_doom_map(*args); }; });
}

}  // namespace lintel::cli
