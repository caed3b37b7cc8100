// `grid`: W x H rooms of 4 x 4 m with a door in every shared wall, so every inner square of four
// rooms is a cycle. Cells sit at their room's centre; --jitter turns every cell frame by a random
// rotation (the world geometry does not move). A few shared furniture meshes per room.
#include "generate/building_plan.h"
#include "generate/furniture_meshes.h"
#include "generate/gen_random.h"
#include "write/portable_math.h"
#include "generate/scene_assembly.h"
#include "generate/walk_timeline.h"

#include <lintel/scene_gen.h>

#include <algorithm>
#include <cassert>
#include <string>

namespace lintel {
namespace {

constexpr double kPitch = 4.0;       // mid-plane to mid-plane
constexpr double kFloorMid = -0.1;   // floor at y = 0
constexpr double kCeilingMid = 2.6;  // ceiling at 2.5
constexpr uint32_t kTimelineDoors = 12;

std::string room_name(uint32_t i, uint32_t j) { return "room_" + std::to_string(i) + "_" + std::to_string(j); }

void add_furniture(gen::BuildingPlan& plan, gen::GenRandom& rng, int room, double cx, double cz) {
  int corners[4] = {0, 1, 2, 3};
  for (int k = 3; k > 0; --k) std::swap(corners[k], corners[rng.below(uint32_t(k + 1))]);
  const uint32_t count = 2 + rng.below(2);
  for (uint32_t k = 0; k < count; ++k) {
    const int c = corners[k];
    const glm::dvec3 p(cx + ((c & 1) ? 1.2 : -1.2), 0.0, cz + ((c & 2) ? 1.2 : -1.2));
    const int mesh = int(rng.below(uint32_t(plan.meshes.size())));
    const glm::dquat yaw = gen::rotation_about({0, 1, 0}, 0.5 * gen::kPi * rng.below(4));
    plan.instances.push_back(
        {plan.rooms[size_t(room)].name + "_" + plan.meshes[size_t(mesh)].name, room, mesh, p, yaw});
  }
}

}  // namespace

SceneDesc generate_grid(const GridOptions& options) {
  assert(options.width >= 1 && options.height >= 1);
  assert(options.door_width_m > 0.0 && options.door_width_m <= kPitch - 2 * gen::kWallThickness - 0.2);
  assert(options.door_sill_m >= 0.0 && options.door_height_m > 0.0 &&
         options.door_sill_m + options.door_height_m <= kCeilingMid - kFloorMid - gen::kSlabThickness - 0.1);
  const uint32_t w = options.width, h = options.height;
  gen::GenRandom rng(options.seed);
  gen::BuildingPlan plan;
  plan.meshes = {gen::make_table({0.55f, 0.36f, 0.20f, 1}), gen::make_chair({0.62f, 0.42f, 0.26f, 1}),
                 gen::make_crate({0.72f, 0.60f, 0.40f, 1}), gen::make_shelf({0.45f, 0.30f, 0.18f, 1})};
  auto index = [w](uint32_t i, uint32_t j) { return int(j * w + i); };
  for (uint32_t j = 0; j < h; ++j)
    for (uint32_t i = 0; i < w; ++i) {
      const double x0 = i * kPitch, z0 = j * kPitch;
      gen::RoomPlan room = gen::box_room(room_name(i, j), x0, x0 + kPitch, z0, z0 + kPitch, kFloorMid, kCeilingMid);
      const float tint = float((i * 7 + j * 13) % 10) * 0.01f;
      room.color = {0.80f + tint, 0.82f, 0.86f - tint, 1.0f};
      room.frame.translation = {x0 + 0.5 * kPitch, 0.0, z0 + 0.5 * kPitch};
      if (options.jitter) room.frame.rotation = rng.rotation();
      plan.rooms.push_back(std::move(room));
      add_furniture(plan, rng, index(i, j), x0 + 0.5 * kPitch, z0 + 0.5 * kPitch);
      if ((i + 2 * j) % 5 == 0) {
        LightDesc lamp{"lamp_" + std::to_string(i) + "_" + std::to_string(j),
                       Light::Type::Point,
                       {1.0f, 0.9f, 0.75f},
                       20.0f,
                       8.0f};
        plan.lights.push_back({index(i, j), lamp, {x0 + 0.5 * kPitch, 2.3, z0 + 0.5 * kPitch}, gen::kNoRotation});
      }
    }

  const double d0 = 0.5 * (kPitch - options.door_width_m), d1 = 0.5 * (kPitch + options.door_width_m);
  const double sill = kFloorMid + 0.5 * gen::kSlabThickness + options.door_sill_m;
  const double door_top = sill + options.door_height_m;
  std::vector<int> door_east(plan.rooms.size(), -1), door_north(plan.rooms.size(), -1);
  for (uint32_t j = 0; j < h; ++j)
    for (uint32_t i = 0; i < w; ++i) {
      const double x0 = i * kPitch, z0 = j * kPitch;
      if (i + 1 < w) {
        door_east[size_t(index(i, j))] = int(plan.openings.size());
        plan.openings.push_back(
            gen::opening_x(index(i, j), index(i + 1, j), x0 + kPitch, z0 + d0, z0 + d1, sill, door_top, true));
        plan.openings.back().name = "door_" + room_name(i, j) + "_east";
      }
      if (j + 1 < h) {
        door_north[size_t(index(i, j))] = int(plan.openings.size());
        plan.openings.push_back(
            gen::opening_z(index(i, j), index(i, j + 1), z0 + kPitch, x0 + d0, x0 + d1, sill, door_top, true));
        plan.openings.back().name = "door_" + room_name(i, j) + "_north";
      }
    }

  // Along the first row, then up the last column, through at most kTimelineDoors doors.
  std::vector<glm::dvec3> waypoints{gen::room_eye_point(plan.rooms[0])};
  uint32_t i = 0, j = 0;
  for (uint32_t doors = 0; doors < kTimelineDoors; ++doors) {
    const int here = index(i, j);
    if (i + 1 < w) {
      gen::add_crossing(plan, plan.openings[size_t(door_east[size_t(here)])], here, waypoints);
      ++i;
    } else if (j + 1 < h) {
      gen::add_crossing(plan, plan.openings[size_t(door_north[size_t(here)])], here, waypoints);
      ++j;
    } else {
      break;
    }
  }
  const glm::dvec3 end = gen::room_eye_point(plan.rooms[size_t(index(i, j))]);
  waypoints.push_back(waypoints.size() == 1 ? end + glm::dvec3(1.0, 0.0, 0.0) : end);
  if (waypoints.size() == 2) waypoints.front() -= glm::dvec3(1.0, 0.0, 0.0);  // one room: walk across it
  plan.timelines.push_back(gen::walk_timeline("doorway", 60.0, waypoints));
  return gen::assemble_scene(plan);
}

}  // namespace lintel
