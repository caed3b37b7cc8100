// The core alone, as a game with its own level format would use it: two box rooms joined by a
// doorway, filled in by hand, finalized, and asked what the eye in the first room sees.
#include <lintel/visibility_builder.h>
#include <lintel/world.h>

#include <cstdio>

int main() {
  lintel::World world;
  for (float x0 : {0.0f, 4.0f}) {
    lintel::Cell cell;
    cell.name = x0 == 0.0f ? "west" : "east";
    cell.volume_box_cell = {{x0, 0.0f, 0.0f}, {x0 + 4.0f, 3.0f, 4.0f}};  // cell space = world space
    world.cells.push_back(cell);
  }
  lintel::Portal door;
  door.name = "door";
  door.from = 0;
  door.to = 1;
  // Counter-clockwise seen from the east room: the normal points from west (from) into east (to).
  door.polygon_world = {{4, 0, 1}, {4, 2, 1}, {4, 2, 3}, {4, 0, 3}};
  door.polygon_from_cell = door.polygon_to_cell = door.polygon_world;
  door.normal_world = {1, 0, 0};
  door.plane_d_world = 4.0f;
  door.centroid_world = {4, 1, 2};
  world.portals.push_back(door);
  if (lintel::Status s = lintel::finalize_world(world); !s) {
    std::fprintf(stderr, "visibility_consumer: %s\n", s.message().c_str());
    return 1;
  }

  lintel::View view;
  view.eye_world = {2.0f, 1.5f, 2.0f};
  view.target_world = {6.0f, 1.5f, 2.0f};
  lintel::VisibilityBuilder builder;
  lintel::VisibleSet visible;
  if (lintel::Status s = builder.build(world, view, 0, {}, visible); !s) {
    std::fprintf(stderr, "visibility_consumer: %s\n", s.message().c_str());
    return 1;
  }
  std::printf("visible cells: %zu\n", visible.cells.size());
  return visible.cells.size() == 2 && visible.cell_visible(1) ? 0 : 1;
}
