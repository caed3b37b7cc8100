// `teleport` and `mirror`: scenes with linked portals (docs/visibility.md, "Linked portals").
// teleport: N box rooms in a row along +X joined by doors; the last room's east wall is a
// teleport onto the first room's west wall and back (a ring closed by a link), and a teleporter
// pair joins room 1's north wall and the last room's south wall. mirror: a hall with two facing
// mirrors (the recursion test) and a door to a side room with one more mirror. Linked portals
// cut no hole: they lie on the room's inner wall face, one-way, each naming its target.
#include "generate/building_plan.h"
#include "generate/furniture_meshes.h"
#include "generate/scene_assembly.h"
#include "write/portable_math.h"
#include "generate/walk_timeline.h"

#include <lintel/scene_gen.h>

#include <cassert>
#include <string>

namespace lintel {
namespace {

constexpr double kFloorMid = -0.1;
constexpr double kCeilingMid = 2.6;
constexpr double kRoomLength = 6.0;  // along X
constexpr double kHalfDepth = 2.5;   // along Z
constexpr double kSill = kFloorMid + 0.5 * gen::kSlabThickness;
constexpr double kInset = 0.5 * gen::kWallThickness;  // mid-plane to the inner wall face

// A linked opening on the inner face of a wall: an x wall (face at x = `at`, spanning z in
// [a0, a1]) or a z wall (face at z = `at`, spanning x in [a0, a1]), heights [v0, v1]; `outward`
// is the face normal pointing out of the room.
gen::OpeningPlan linked_opening(std::string name, int from, int to, bool x_wall, double at, double a0, double a1,
                                double v0, double v1, const glm::dvec3& outward) {
  gen::OpeningPlan o;
  o.name = std::move(name);
  o.from = from;
  o.to = to;
  o.two_way = false;
  o.origin = x_wall ? glm::dvec3(at, 0.0, 0.0) : glm::dvec3(0.0, 0.0, at);
  o.u_axis = x_wall ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  o.u0 = a0;
  o.u1 = a1;
  o.v0 = v0;
  o.v1 = v1;
  o.normal = outward;
  return o;
}

void furnish(gen::BuildingPlan& plan, int room, const glm::dvec3& centre) {
  plan.instances.push_back(
      {plan.rooms[size_t(room)].name + "_table", room, 0, centre + glm::dvec3(0.8, 0, 0.9), gen::kNoRotation});
  plan.instances.push_back(
      {plan.rooms[size_t(room)].name + "_chair", room, 1, centre + glm::dvec3(0.8, 0, 0.2), gen::kNoRotation});
}

glm::dvec3 eye_at(const gen::BuildingPlan& plan, int room, double x, double z) {
  return {x, gen::eye_level(plan.rooms[size_t(room)]), z};
}

}  // namespace

SceneDesc generate_teleport(const TeleportOptions& options) {
  const uint32_t n = options.cells;
  assert(n >= 3);
  gen::BuildingPlan plan;
  plan.meshes = {gen::make_table({0.55f, 0.36f, 0.20f, 1}), gen::make_chair({0.62f, 0.42f, 0.26f, 1})};
  for (uint32_t i = 0; i < n; ++i) {
    const double x0 = kRoomLength * i;
    plan.rooms.push_back(gen::box_room("room_" + std::to_string(i), x0, x0 + kRoomLength, -kHalfDepth, kHalfDepth,
                                       kFloorMid, kCeilingMid));
    gen::RoomPlan& room = plan.rooms.back();
    room.frame.translation = {x0 + 0.5 * kRoomLength, 0.0, 0.0};
    room.frame.rotation = gen::rotation_about({0, 1, 0}, 0.3 * i);  // non-identity frames
    const float tint = float(i % 6) * 0.03f;
    room.color = {0.84f - tint, 0.80f, 0.76f + tint, 1.0f};
    furnish(plan, int(i), {x0 + 0.5 * kRoomLength, 0.0, 0.0});
  }
  const double top = kSill + gen::kDoorHeight;
  for (uint32_t i = 0; i + 1 < n; ++i) {
    plan.openings.push_back(gen::opening_x(int(i), int(i + 1), kRoomLength * (i + 1), -0.5 * gen::kDoorWidth,
                                           0.5 * gen::kDoorWidth, kSill, top, true));
    plan.openings.back().name = "door_" + std::to_string(i);
  }
  const int last = int(n - 1);
  const double east = kRoomLength * n - kInset, west = kInset, hw = 0.5 * gen::kDoorWidth;
  // The seam: walking east out of the last room comes out of the first room's west wall.
  plan.openings.push_back(linked_opening("seam_east", last, 0, true, east, -hw, hw, kSill, top, {1, 0, 0}));
  plan.openings.back().link = "seam_west";
  plan.openings.push_back(linked_opening("seam_west", 0, last, true, west, -hw, hw, kSill, top, {-1, 0, 0}));
  plan.openings.back().link = "seam_east";
  // The teleporter pair: room 1's north wall <-> the last room's south wall.
  const double x1 = kRoomLength * 1.5, xl = kRoomLength * (n - 0.5);
  const double north = kHalfDepth - kInset, south = -kHalfDepth + kInset;
  plan.openings.push_back(
      linked_opening("teleporter_a", 1, last, false, north, x1 - 0.6, x1 + 0.6, kSill, kSill + 2.2, {0, 0, 1}));
  plan.openings.back().link = "teleporter_b";
  plan.openings.push_back(
      linked_opening("teleporter_b", last, 1, false, south, xl - 0.6, xl + 0.6, kSill, kSill + 2.2, {0, 0, -1}));
  plan.openings.back().link = "teleporter_a";
  LightDesc lamp{"lamp_0", Light::Type::Point, {1.0f, 0.9f, 0.75f}, 20.0f, 8.0f};
  plan.lights.push_back({0, lamp, {0.5 * kRoomLength, 2.3, 0.0}, gen::kNoRotation});

  // "ring": east through every door and the seam, on into the first room (keys in the walk's own
  // frame: past the seam they lie beyond the last wall; `lintel walk` carries the camera through
  // the teleport, docs/visibility.md). "teleporter": north through teleporter_a.
  std::vector<glm::dvec3> ring{eye_at(plan, 0, 0.5 * kRoomLength, 0.0)};
  for (uint32_t i = 0; i + 1 < n; ++i) gen::add_crossing(plan, plan.openings[i], int(i), ring);
  ring.push_back(eye_at(plan, last, east - 1.0, 0.0));
  ring.push_back(eye_at(plan, last, east + 1.0, 0.0));
  ring.push_back(eye_at(plan, last, east + 3.0, 0.0));
  plan.timelines.push_back(gen::walk_timeline("ring", 60.0, ring));
  const std::vector<glm::dvec3> tele{eye_at(plan, 1, x1, 0.0), eye_at(plan, 1, x1, north - 1.0),
                                     eye_at(plan, 1, x1, north + 1.0), eye_at(plan, 1, x1, north + 2.5)};
  plan.timelines.push_back(gen::walk_timeline("teleporter", 60.0, tele));
  return gen::assemble_scene(plan);
}

SceneDesc generate_mirror(const MirrorOptions& options) {
  (void)options;
  gen::BuildingPlan plan;
  plan.meshes = {gen::make_table({0.55f, 0.36f, 0.20f, 1}), gen::make_chair({0.62f, 0.42f, 0.26f, 1})};
  plan.rooms.push_back(gen::box_room("hall", 0, kRoomLength, -kHalfDepth, kHalfDepth, kFloorMid, kCeilingMid));
  plan.rooms.push_back(gen::box_room("side", 1, 5, kHalfDepth, kHalfDepth + 4, kFloorMid, kCeilingMid));
  plan.rooms[0].frame.translation = {3.0, 0.0, 0.0};
  plan.rooms[1].frame.translation = {3.0, 0.0, kHalfDepth + 2};
  plan.rooms[1].frame.rotation = gen::rotation_about({0, 1, 0}, 0.7);
  furnish(plan, 0, {3.0, 0.0, -0.5});
  furnish(plan, 1, {3.0, 0.0, kHalfDepth + 2.0});
  const double top = kSill + gen::kDoorHeight;
  plan.openings.push_back(gen::opening_z(0, 1, kHalfDepth, 2.55, 3.45, kSill, top, true));
  plan.openings.back().name = "door";
  // Two facing mirrors on the hall's short walls, and one on the side room's back wall.
  plan.openings.push_back(
      linked_opening("mirror_west", 0, 0, true, kInset, -1.5, 1.5, kSill + 0.3, kSill + 2.2, {-1, 0, 0}));
  plan.openings.back().mirror = true;
  plan.openings.push_back(
      linked_opening("mirror_east", 0, 0, true, kRoomLength - kInset, -1.5, 1.5, kSill + 0.3, kSill + 2.2, {1, 0, 0}));
  plan.openings.back().mirror = true;
  plan.openings.push_back(linked_opening("mirror_side", 1, 1, false, kHalfDepth + 4 - kInset, 2.0, 4.0, kSill + 0.3,
                                         kSill + 2.0, {0, 0, 1}));
  plan.openings.back().mirror = true;
  LightDesc lamp{"lamp_hall", Light::Type::Point, {1.0f, 0.9f, 0.75f}, 20.0f, 8.0f};
  plan.lights.push_back({0, lamp, {3.0, 2.3, 0.0}, gen::kNoRotation});

  // Along the hall between the mirrors, then through the door towards the side room's mirror.
  std::vector<glm::dvec3> walk{eye_at(plan, 0, 1.5, -0.5), eye_at(plan, 0, 4.5, -0.5), eye_at(plan, 0, 3.0, -0.5)};
  gen::add_crossing(plan, plan.openings[0], 0, walk);
  walk.push_back(eye_at(plan, 1, 3.0, kHalfDepth + 2.5));
  plan.timelines.push_back(gen::walk_timeline("mirrors", 60.0, walk));
  return gen::assemble_scene(plan);
}

}  // namespace lintel
