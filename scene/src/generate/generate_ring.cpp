// `ring`: N rooms around a loop, consecutive rooms joined by a door, the last back to the first.
// For N >= 3 room i is a wedge between the radial walls at angles (i -+ 1/2) * 360/N, between an
// inner and an outer wall; its cell frame sits at its centre turned by i * 360/N. N = 2 is two
// rooms either side of one straight wall with two doors in it.
#include "generate/building_plan.h"
#include "generate/furniture_meshes.h"
#include "write/portable_math.h"
#include "generate/scene_assembly.h"
#include "generate/walk_timeline.h"

#include <lintel/scene_gen.h>

#include <algorithm>
#include <cassert>
#include <string>

namespace lintel {
namespace {

constexpr double kFloorMid = -0.1;
constexpr double kCeilingMid = 2.6;
constexpr double kDepth = 4.0;  // radial size of a room
constexpr uint32_t kTimelineDoors = 12;

glm::dvec2 on_ray(double angle, double distance) {
  return {distance * gen::portable_cos(angle), distance * gen::portable_sin(angle)};
}

void add_two_rooms(gen::BuildingPlan& plan) {
  plan.rooms.push_back(gen::box_room("ring_0", 0, kDepth, -3, 3, kFloorMid, kCeilingMid));
  plan.rooms.push_back(gen::box_room("ring_1", -kDepth, 0, -3, 3, kFloorMid, kCeilingMid));
  const double sill = kFloorMid + 0.5 * gen::kSlabThickness, top = sill + gen::kDoorHeight;
  plan.openings.push_back(gen::opening_x(0, 1, 0, 1.05, 1.95, sill, top, false));
  plan.openings.back().name = "door_0";
  plan.openings.push_back(gen::opening_x(1, 0, 0, -1.95, -1.05, sill, top, true));
  plan.openings.back().name = "door_1";
}

// Wedges: radial walls at angles phi_k = (k + 1/2) * 2 pi / N, shared exactly by both rooms.
void add_wedges(gen::BuildingPlan& plan, uint32_t n) {
  const double half = gen::kPi / n;
  const double cos_half = gen::portable_cos(half), tan_half = gen::portable_sin(half) / cos_half;
  // Wide enough at mid-depth for a 4 m room, and a central column of at least 1 m radius.
  const double r_mid = std::max(3.0, 2.0 / tan_half);
  const double inner = (r_mid - 0.5 * kDepth) / cos_half, outer = (r_mid + 0.5 * kDepth) / cos_half;
  std::vector<double> phi(n);
  for (uint32_t k = 0; k < n; ++k) phi[k] = (2.0 * k + 1.0) * half;
  for (uint32_t i = 0; i < n; ++i) {
    const double before = phi[(i + n - 1) % n], after = phi[i];
    gen::RoomPlan room;
    room.name = "ring_" + std::to_string(i);
    room.footprint = {on_ray(before, inner), on_ray(before, outer), on_ray(after, outer), on_ray(after, inner)};
    room.floor_mid = kFloorMid;
    room.ceiling_mid = kCeilingMid;
    plan.rooms.push_back(std::move(room));
  }
  const double door_mid = 0.5 * (inner + outer), sill = kFloorMid + 0.5 * gen::kSlabThickness;
  for (uint32_t k = 0; k < n; ++k) {
    gen::OpeningPlan o;
    o.name = "door_" + std::to_string(k);
    o.from = int(k);
    o.to = int((k + 1) % n);
    const glm::dvec2 radial = on_ray(phi[k], 1.0);
    o.u_axis = {radial.x, 0.0, radial.y};
    o.u0 = door_mid - 0.5 * gen::kDoorWidth;
    o.u1 = door_mid + 0.5 * gen::kDoorWidth;
    o.v0 = sill;
    o.v1 = sill + gen::kDoorHeight;
    o.normal = {-radial.y, 0.0, radial.x};  // towards growing angle: into the next room
    plan.openings.push_back(o);
  }
}

glm::dvec2 footprint_centre(const gen::RoomPlan& room) {
  glm::dvec2 c(0.0);
  for (const glm::dvec2& p : room.footprint) c += p;
  return c / double(room.footprint.size());
}

}  // namespace

SceneDesc generate_ring(const RingOptions& options) {
  const uint32_t n = options.cells;
  assert(n >= 2);
  gen::BuildingPlan plan;
  plan.meshes = {gen::make_table({0.55f, 0.36f, 0.20f, 1}), gen::make_chair({0.62f, 0.42f, 0.26f, 1})};
  if (n == 2)
    add_two_rooms(plan);
  else
    add_wedges(plan, n);

  for (uint32_t i = 0; i < n; ++i) {
    gen::RoomPlan& room = plan.rooms[i];
    const double theta = 2.0 * gen::kPi * i / n;
    const glm::dvec2 c = footprint_centre(room), out = on_ray(theta, 1.0);
    room.frame.translation = {c.x, 0.0, c.y};
    room.frame.rotation = gen::rotation_about({0, 1, 0}, -theta);  // local +X along the room's radial
    const float tint = float(i % 8) * 0.015f;
    room.color = {0.84f - tint, 0.82f, 0.78f + tint, 1.0f};
    // A table beyond the centre towards the outer wall, a chair on its inner side.
    const glm::dquat yaw = gen::rotation_about({0, 1, 0}, -theta + 0.5 * gen::kPi);
    const glm::dvec2 table = c + out * 0.9, chair = c + out * 0.2;
    plan.instances.push_back({room.name + "_table", int(i), 0, {table.x, 0.0, table.y}, yaw});
    plan.instances.push_back({room.name + "_chair", int(i), 1, {chair.x, 0.0, chair.y}, yaw});
    if (i % 4 == 0) {
      LightDesc lamp{"lamp_" + std::to_string(i), Light::Type::Point, {1.0f, 0.9f, 0.75f}, 20.0f, 8.0f};
      plan.lights.push_back({int(i), lamp, {c.x, 2.3, c.y}, gen::kNoRotation});
    }
  }

  std::vector<glm::dvec3> waypoints{gen::room_eye_point(plan.rooms[0])};
  const uint32_t doors = std::min(n, kTimelineDoors);
  for (uint32_t k = 0; k < doors; ++k) gen::add_crossing(plan, plan.openings[k], int(k), waypoints);
  waypoints.push_back(gen::room_eye_point(plan.rooms[doors % n]));
  plan.timelines.push_back(gen::walk_timeline("doorway", 60.0, waypoints));
  return gen::assemble_scene(plan);
}

}  // namespace lintel
