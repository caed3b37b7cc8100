// `lintel gen <kind> [options] -o FILE`: writes a generated scene (deterministic per --seed).
#include "cli_common.h"

#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>

#include <cstdio>

namespace lintel::cli {
namespace {

struct GenArgs {
  std::string output;
  uint64_t seed = 1;
  uint32_t width = 4, height = 4, cells = 8;
  bool jitter = false;
};

int write(const SceneDesc& scene, const std::string& path) {
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
  auto* gen = app.add_subcommand("gen", "Generate a scene: cottage, grid, ring or random");
  gen->require_subcommand(1);
  auto args = std::make_shared<GenArgs>();

  add_kind(gen, "cottage", "The default scene: a ~7-cell house with cycles, windows, a cellar and lights", *args)
      ->callback([&run, args] { run = [args] { return write(generate_cottage({args->seed}), args->output); }; });

  auto* grid = add_kind(gen, "grid", "W x H rooms with doors to their neighbours", *args);
  grid->add_option("--width", args->width, "Rooms along X (1..64)")->check(CLI::Range(1, 64))->capture_default_str();
  grid->add_option("--height", args->height, "Rooms along Z (1..64)")->check(CLI::Range(1, 64))->capture_default_str();
  grid->add_flag("--jitter", args->jitter, "Rotate every cell's frame randomly (world geometry unchanged)");
  grid->callback([&run, args] {
    run = [args] { return write(generate_grid({args->width, args->height, args->jitter, args->seed}), args->output); };
  });

  auto* ring = add_kind(gen, "ring", "A loop of N rooms", *args);
  ring->add_option("--cells", args->cells, "Rooms in the loop (2..1024)")->check(CLI::Range(2, 1024))->capture_default_str();
  ring->callback([&run, args] { run = [args] { return write(generate_ring({args->cells, args->seed}), args->output); }; });

  auto* random = add_kind(gen, "random", "A random cyclic cell graph with non-identity transforms", *args);
  random->add_option("--cells", args->cells, "Cells (2..4096)")->check(CLI::Range(2, 4096))->capture_default_str();
  random->callback(
      [&run, args] { run = [args] { return write(generate_random({args->cells, args->seed}), args->output); }; });
}

}  // namespace lintel::cli
