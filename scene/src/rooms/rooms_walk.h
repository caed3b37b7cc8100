// A "doorways" timeline for an imported rooms scene, so that `lintel walk` runs on it as it is:
// depth first through the two-way portals from the first room, through each tree portal and back.
#pragma once

#include <lintel/world.h>

namespace lintel::rooms {

inline constexpr size_t kMaxWalkCrossings = 256;  // keeps the walk a few minutes long at most

// Fills `out` (named "doorways", 60 fps) and returns true, or returns false when the scene has no
// two-way portal. Each crossing goes from min(0.5 m, half the portal's size) before the polygon's
// centre to as far behind it; between crossings the eye walks straight, so in a non-convex room it
// may cut a corner through a wall.
bool doorway_walk(const World& world, Timeline& out);

}  // namespace lintel::rooms
