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

// Waypoints in runs: the eye walks each run as above and jumps (a teleport) from the last waypoint
// of one run to the first of the next, so no eye between the two places is ever sampled. The two
// keys of a jump are 1 ms apart, at a millisecond that no frame time t0 + i / fps comes within
// kJumpMarginMs of (t0 = the first key's time; the eye waits at the jump's start for the few
// milliseconds that takes, one extra key): sampled at fps, or at any rate dividing it, a frame
// shows one place or the other, never a point between. Needs fps < 1000 / (1 + 2 kJumpMarginMs).
// A last run of one waypoint is held for one frame period, so a frame shows where the jump lands.
// Looking ahead stays within a run: the last key of a run looks along its last stretch, the first
// key of the next along its first (a run of one waypoint keeps the previous run's heading). With
// one run this is walk_timeline above, key for key.
inline constexpr double kJumpMarginMs = 0.25;
Timeline walk_timeline(const std::string& name, double fps, const std::vector<std::vector<glm::dvec3>>& runs);

// Eye height above the floor of room `room`.
double eye_level(const RoomPlan& room);
// Centre of a room's footprint at eye level.
glm::dvec3 room_eye_point(const RoomPlan& room);

// The two waypoints of walking through opening `o` from room `from_room` into the other room:
// for a wall, 1 m before and after the mid-plane at the opening's centre, at eye level; for a
// slab, straight up or down through the hole's centre from eye level to eye level.
void add_crossing(const BuildingPlan& plan, const OpeningPlan& o, int from_room, std::vector<glm::dvec3>& waypoints);

}  // namespace lintel::gen
