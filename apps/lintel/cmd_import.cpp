// `lintel import doom WAD MAP -o FILE`: a Doom-format map as a Lintel scene (docs/levels.md);
// `lintel import rooms IN -o FILE` and `lintel export rooms SCENE -o FILE`: the rooms convention
// (docs/rooms.md). Imported scenes are validated by the loader before the command reports success.
#include "optimize_args.h"

#include <lintel/doom_import.h>
#include <lintel/rooms_import.h>
#include <lintel/scene_io.h>

#include <cstdio>
#include <string>

namespace lintel::cli {
namespace {

// Writes an imported scene only if the loader accepts it: content the importer could not
// represent (freedoom2's MAP28 made a portal that missed its cell, before the importer read
// self-referencing lines from their segs) is refused here with the loader's line naming the
// element, instead of written and refused at the next load. Exit 2, nothing written.
Status save_if_it_loads(const SceneDesc& scene, const std::string& label, const std::string& output) {
  World check;
  if (Status s = build_world(scene, label, check); !s)
    return Status::error(s.message() + " (in the imported scene; nothing written)");
  return save_scene(scene, output);
}

struct ImportDoomArgs {
  std::string wad, map, output, doors = "open", sectors = "convex";
  double hull_excess = DoomImportOptions{}.convex_hull_excess;
  double min_sector_excess = DoomImportOptions{}.convex_min_sector_excess;
  bool optimize = false;
  OptimizeOptions optimize_options;
};

int import_doom_map(const ImportDoomArgs& args) {
  DoomImportOptions options;
  options.doors_open = args.doors == "open";
  options.convex_cells = args.sectors == "convex";
  options.convex_hull_excess = args.hull_excess;
  options.convex_min_sector_excess = args.min_sector_excess;
  SceneDesc scene;
  DoomImportStats stats;
  if (Status s = import_doom(args.wad, args.map, options, scene, &stats); !s) return fail(s);
  OptimizeReport report;
  if (Status s = args.optimize ? optimize_and_save(scene, args.wad + ": map " + args.map, args.optimize_options,
                                                   args.output, report)
                               : save_if_it_loads(scene, args.wad + ": map " + args.map, args.output);
      !s)
    return fail(s);
  std::printf(
      "wrote %s: map %s, %u sectors -> %u cells (%u solid, %u doors opened, %u platforms lowered), %u portals, "
      "%u instances, "
      "%u lights, doorway walk through %u portals%s\n",
      args.output.c_str(), args.map.c_str(), stats.sectors, stats.cells, stats.solid_sectors, stats.doors,
      stats.lowered_floors, stats.portals, stats.instances, stats.lights, stats.walk_crossings,
      stats.walk_teleports > 0 ? (" and " + std::to_string(stats.walk_teleports) + " teleporters").c_str() : "");
  if (options.convex_cells)
    std::printf("convex cells: %u sectors split, %u portals between cells of one sector\n", stats.split_sectors,
                stats.inner_portals);
  if (args.optimize) std::printf("optimized: %s\n", optimize_summary(report).c_str());
  return kExitOk;
}

struct RoomsArgs {
  std::string input, output;
  LoadOptions load;
};

int import_rooms_file(const RoomsArgs& args) {
  SceneDesc scene;
  std::vector<std::string> warnings;
  RoomsImportStats stats;
  if (Status s = import_rooms(args.input, scene, &warnings, &stats); !s) return fail(s);
  for (const std::string& w : warnings) std::fprintf(stderr, "lintel: warning: %s\n", w.c_str());
  if (Status s = save_if_it_loads(scene, args.input, args.output); !s) return fail(s);
  std::printf("wrote %s: %u rooms (%u with a bound), %u portals (%u one-way), %u instances, %u lights\n",
              args.output.c_str(), stats.rooms, stats.bounds, stats.portals, stats.one_way, stats.instances,
              stats.lights);
  return kExitOk;
}

int export_rooms_file(const RoomsArgs& args) {
  World world;
  if (Status s = load_scene(args.input, args.load, world, nullptr); !s) return fail(s);
  SceneDesc scene;
  if (Status s = export_rooms(world, scene); !s) return fail(s);
  if (Status s = save_scene(scene, args.output); !s) return fail(s);
  std::printf("wrote %s: %zu rooms, %zu portals in the rooms convention\n", args.output.c_str(), world.cells.size(),
              world.portals.size());
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
  add_doom_sector_options(doom, args->sectors, args->hull_excess, args->min_sector_excess);
  doom->add_flag("--optimize", args->optimize,
                 "Merge cells where a finer split buys no culling (as `lintel optimize`)");
  add_optimize_options(doom, args->optimize_options);
  doom->callback([&run, args] { run = [args] { return import_doom_map(*args); }; });

  auto rooms_args = std::make_shared<RoomsArgs>();
  auto* rooms = import->add_subcommand("rooms", "A plain glTF in the rooms convention ('*-room', '*-portal') -> scene");
  rooms->add_option("input", rooms_args->input, "The .gltf or .glb (docs/rooms.md)")->required();
  rooms->add_option("-o,--output", rooms_args->output, "Output file: .gltf (+ .bin) or .glb")->required();
  rooms->callback([&run, rooms_args] { run = [rooms_args] { return import_rooms_file(*rooms_args); }; });
}

void add_export_command(CLI::App& app, Command& run) {
  auto* exp = app.add_subcommand("export", "Write a Lintel scene in another convention");
  exp->require_subcommand(1);
  auto args = std::make_shared<RoomsArgs>();
  auto* rooms = exp->add_subcommand("rooms", "A Lintel scene -> plain glTF in the rooms convention (docs/rooms.md)");
  rooms->add_option("scene", args->input, "The Lintel scene")->required();
  rooms->add_option("-o,--output", args->output, "Output file: .gltf (+ .bin) or .glb")->required();
  add_load_options(rooms, args->load);
  rooms->callback([&run, args] { run = [args] { return export_rooms_file(*args); }; });
}

}  // namespace lintel::cli
