// `lintel gen <kind> [options] -o FILE`: writes a generated scene (deterministic per --seed).
#include "cli_common.h"

#include <lintel/rooms_import.h>
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>

#include <algorithm>
#include <cstdio>

namespace lintel::cli {
namespace {

struct GenArgs {
  std::string output;
  uint64_t seed = 1;
  uint32_t width = 4, height = 4, cells = 8;
  bool jitter = false;
  RandomOptions random;  // the random kind's tuning (cells and seed come from the fields above)
  bool no_global_rotation = false;
};

int write(const SceneDesc& scene, const std::string& path) {
  // save_scene checks the target (and a .gltf's .bin) again before writing.
  if (Status s = save_scene(scene, path); !s) return fail(s);
  std::printf("wrote %s (%zu nodes, %zu meshes)\n", path.c_str(), scene.nodes.size(), scene.meshes.size());
  return kExitOk;
}

CLI::App* add_kind(CLI::App* gen, const char* name, const char* help, GenArgs& args) {
  auto* sub = gen->add_subcommand(name, help);
  sub->add_option("-o,--output", args.output, "Output file: .gltf (+ .bin) or .glb")->required();
  sub->add_option("--seed", args.seed, "Random seed (same seed, same file)")->capture_default_str();
  return sub;
}

}  // namespace

void add_gen_command(CLI::App& app, Command& run) {
  auto* gen = app.add_subcommand(
      "gen", "Generate a scene: cottage, grid, ring, teleport, mirror, house, random or rooms-example");
  gen->require_subcommand(1);
  auto args = std::make_shared<GenArgs>();

  add_kind(gen, "cottage", "The default scene: a ~7-cell house with cycles, windows, a cellar and lights", *args)
      ->callback([&run, args] { run = [args] { return write(generate_cottage({args->seed}), args->output); }; });

  auto* rooms = gen->add_subcommand("rooms-example", "A small house in the rooms convention (input of 'import rooms')");
  rooms->add_option("-o,--output", args->output, "Output file: .gltf (+ .bin) or .glb")->required();
  rooms->callback([&run, args] { run = [args] { return write(generate_rooms_example(), args->output); }; });

  auto* grid = add_kind(gen, "grid", "W x H rooms with doors to their neighbours", *args);
  grid->add_option("--width", args->width, "Rooms along X (1..64)")->check(CLI::Range(1, 64))->capture_default_str();
  grid->add_option("--height", args->height, "Rooms along Z (1..64)")->check(CLI::Range(1, 64))->capture_default_str();
  grid->add_flag("--jitter", args->jitter, "Rotate every cell's frame randomly (world geometry unchanged)");
  grid->callback([&run, args] {
    run = [args] { return write(generate_grid({args->width, args->height, args->jitter, args->seed}), args->output); };
  });

  auto* ring = add_kind(gen, "ring", "A loop of N rooms", *args);
  ring->add_option("--cells", args->cells, "Rooms in the loop (2..1024)")
      ->check(CLI::Range(2, 1024))
      ->capture_default_str();
  ring->callback([&run, args] {
    run = [args] { return write(generate_ring({args->cells, args->seed}), args->output); };
  });

  auto* teleport =
      add_kind(gen, "teleport", "A row of rooms closed into a ring by a teleport, and a teleporter pair", *args);
  teleport->add_option("--cells", args->cells, "Rooms in the row (3..64)")->check(CLI::Range(3, 64));
  teleport->callback([&run, args] {
    run = [args] { return write(generate_teleport({std::max<uint32_t>(args->cells, 3)}), args->output); };
  });
  add_kind(gen, "mirror", "A hall with two facing mirrors and a side room with one more", *args)
      ->callback([&run, args] { run = [args] { return write(generate_mirror({}), args->output); }; });
  add_kind(gen, "house",
           "3 x 3 closed single-sided rooms, walls back to back, tilted, random cell frames, a lamp in most rooms",
           *args)
      ->callback([&run, args] { run = [args] { return write(generate_house({args->seed}), args->output); }; });

  auto* random = add_kind(gen, "random", "A random cyclic cell graph with non-identity transforms", *args);
  random->add_option("--cells", args->cells, "Cells (2..4096)")->check(CLI::Range(2, 4096))->capture_default_str();
  RandomOptions& r = args->random;
  random->add_option("--storeys", r.storeys, "Lattice levels joined by holes in the slabs")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  random
      ->add_option("--extra-portals", r.extra_portal_fraction,
                   "Share of other neighbour pairs given a cycle-making opening")
      ->check(finite_range(0.0, 1.0))
      ->capture_default_str();
  random->add_option("--windows", r.window_fraction, "Share of extra wall openings that are windows")
      ->check(finite_range(0.0, 1.0))
      ->capture_default_str();
  random->add_option("--one-way", r.one_way_fraction, "Share of extra openings that are one-way portals")
      ->check(finite_range(0.0, 1.0))
      ->capture_default_str();
  random->add_option("--volumes", r.volume_fraction, "Share of cells with a volume node")
      ->check(finite_range(0.0, 1.0))
      ->capture_default_str();
  random->add_option("--max-offset", r.max_offset_m, "Cell frame origins up to this far from their rooms (m, per axis)")
      ->check(finite_range(0.0, 1e5))
      ->capture_default_str();
  random->add_option("--min-scale", r.min_scale, "Smallest cell frame scale")
      ->check(finite_range(1e-3, 1e3))
      ->capture_default_str();
  random->add_option("--max-scale", r.max_scale, "Largest cell frame scale")
      ->check(finite_range(1e-3, 1e3))
      ->capture_default_str();
  random->add_option("--global-offset", r.max_global_offset_m, "Building translated up to this far (m, per axis)")
      ->check(finite_range(0.0, 1e5))
      ->capture_default_str();
  random->add_flag("--no-global-rotation", args->no_global_rotation,
                   "Keep the building upright (no random global rotation)");
  random->callback([&run, args] {
    run = [args] {
      RandomOptions options = args->random;
      options.cells = args->cells;
      options.seed = args->seed;
      options.global_rotation = !args->no_global_rotation;
      if (options.min_scale > options.max_scale) return fail("--min-scale is larger than --max-scale");
      return write(generate_random(options), args->output);
    };
  });
}

}  // namespace lintel::cli
