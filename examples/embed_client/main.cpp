// The smallest useful Lintel client: load a scene, report errors the way a game would, and list
// its cells and where each portal leads. Usage: embed_client <scene.gltf>
#include <lintel/scene_io.h>
#include <lintel/version.h>
#include <lintel/world.h>

#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s <scene.gltf|.glb>\n", argv[0]);
    return 2;
  }
  lintel::World world;
  std::vector<std::string> warnings;
  if (lintel::Status status = lintel::load_world(argv[1], world, &warnings); !status) {
    std::fprintf(stderr, "embed_client: %s\n", status.message().c_str());
    return 2;
  }
  std::printf("Lintel %s: %zu cells\n", LINTEL_VERSION_STRING, world.cells.size());
  for (const lintel::Cell& cell : world.cells) {
    std::printf("cell %s:", cell.name.c_str());
    for (const lintel::PortalLink& link : cell.links) std::printf(" ->%s", world.cells[link.neighbour].name.c_str());
    std::printf("\n");
  }
  return 0;
}
