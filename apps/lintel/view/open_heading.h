// Where `lintel view` looks first when the user gives no camera: the timeline's first eye, turned
// to the most open heading. A first key can face a wall a step away (an imported map's walk heads
// for a station round a corner: freedoom2 MAP12's start showed one grey wall), which tells a new
// user nothing about the level.
#pragma once

#include <lintel/view.h>
#include <lintel/world.h>

#include <cstdint>

namespace lintel::view {

// Headings tried, evenly round the vertical through the eye.
inline constexpr uint32_t kOpenHeadings = 16;

// `start` turned about the world's +Y through its eye (pitch and distance to the target kept) to
// the heading, of `start`'s own and kOpenHeadings round it, from which the portal flood of the
// eye's cell sees the most cells. Ties keep the earlier candidate, `start` first: a start that
// sees as much as any other heading is returned unchanged, bit for bit. A start looking straight
// up or down, or a world whose flood fails, is returned unchanged too.
View most_open_heading(const World& world, const View& start);

}  // namespace lintel::view
