// The smallest useful Lintel client: load a scene, report errors the way a game would, list its
// cells and where each portal leads, then walk the first timeline the way a game loop would —
// track the viewer cell by portal crossings and ask which cells are visible each frame.
// Usage: embed_client <scene.gltf|.glb>
#include <lintel/scene_io.h>
#include <lintel/timeline.h>
#include <lintel/version.h>
#include <lintel/viewer_tracker.h>
#include <lintel/visibility_builder.h>
#include <lintel/world.h>

#include <algorithm>
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
  if (world.timelines.empty()) return 0;

  // The per-frame loop: one tracker and one builder for the whole session; the VisibleSet is
  // reused, and prepare() sizes both at load, so no frame allocates, the first included.
  const lintel::Timeline& timeline = world.timelines.front();
  lintel::ViewerTracker tracker;
  lintel::VisibilityBuilder builder;
  lintel::VisibleSet visible;
  builder.prepare(world, {}, visible);
  size_t most_cells = 0, transitions = 0;
  const size_t frames = lintel::timeline_frame_count(timeline);
  for (size_t f = 0; f < frames; ++f) {
    const lintel::View view = lintel::timeline_view(timeline, timeline.keys.front().t + double(f) / timeline.fps);
    lintel::Status s = f == 0 ? tracker.reset(world, view.eye_world) : tracker.update(world, view.eye_world);
    if (s) s = builder.build(world, view, tracker.cell(), {}, visible);
    if (!s) {
      std::fprintf(stderr, "embed_client: frame %zu: %s\n", f, s.message().c_str());
      return 2;
    }
    if (f > 0) transitions += tracker.transitions().size();
    most_cells = std::max(most_cells, visible.cells.size());
  }
  std::printf("timeline %s: %zu frames, %zu cell transitions, at most %zu cells visible\n", timeline.name.c_str(),
              frames, transitions, most_cells);
  return 0;
}
