// Camera walks for the "doorway" timelines: key frames at walking speed through given waypoints,
// looking ahead along the path. Helpers place waypoints one metre before and after an opening,
// so that the eye crosses each portal plane well inside its polygon.
#pragma once

#include "generate/building_plan.h"

#include <lintel/world.h>

#include <vector>

namespace lintel::gen {

inline constexpr double kWalkSpeed = 1.4;  // m/s

// Keys at the waypoints (building space), timed by distance at kWalkSpeed and rounded to the
// millisecond; consecutive duplicates are dropped. Targets look 2 m ahead along the path, never
// straight up or down (a look-at with +Y up must stay defined).
Timeline walk_timeline(const std::string& name, double fps, const std::vector<glm::dvec3>& waypoints);

// Eye height above the floor of room `room`.
double eye_level(const RoomPlan& room);
// Centre of a room's footprint at eye level.
glm::dvec3 room_eye_point(const RoomPlan& room);

// The two waypoints of walking through opening `o` from room `from_room` into the other room:
// for a wall, 1 m before and after the mid-plane at the opening's centre, at eye level; for a
// slab, straight up or down through the hole's centre from eye level to eye level.
void add_crossing(const BuildingPlan& plan, const OpeningPlan& o, int from_room, std::vector<glm::dvec3>& waypoints);

}  // namespace lintel::gen
