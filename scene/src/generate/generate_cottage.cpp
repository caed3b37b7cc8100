// The default scene: a one-storey cottage with a cellar, seven cells and many cycles.
//
//   z=8 +---------+------+-----------+      outside: ground, facade with 7 windows and 2 doors, roof
//       | kitchen |      |  bedroom  |      cellar: below hall and study, reached by a stair
//   4.5 +--door---+ hall +-----door--+ z=4     through a hole in the study floor
//       | living  |      |  study    |
//   z=0 +---------+-door-+-----------+      (building space, wall mid-planes, meters)
//      x=0       x=4    x=6.5       x=11
//
// The house is turned 17 degrees in the world and every cell has its own frame (rotations about
// tilted axes, non-uniform scales, offsets), drawn from the seed: the seed changes frames and
// colours only, never the world geometry, so visibility must not depend on it.
#include "generate/building_plan.h"
#include "generate/furniture_meshes.h"
#include "generate/gen_random.h"
#include "write/portable_math.h"
#include "generate/scene_assembly.h"
#include "generate/walk_timeline.h"

#include <lintel/scene_gen.h>

namespace lintel {
namespace {

using gen::BuildingPlan;
using gen::OpeningPlan;

enum Room { kOutside, kHall, kLiving, kKitchen, kStudy, kBedroom, kCellar };
enum Mesh { kTable, kChair, kBed, kShelf, kSofa, kCrate, kTree, kStair, kDoorLeaf };

constexpr double kGround = 0.0;      // floor level of the ground storey and of the garden
constexpr double kStoreyMid = 2.6;   // roof slab mid-plane
constexpr double kCellarMid = -2.8;  // cellar floor slab mid-plane
constexpr double kFloorMid = -0.1;   // ground storey floor slab mid-plane
constexpr double kCellarFloor = -2.7;
constexpr double kDoorTop = kGround + gen::kDoorHeight;
constexpr double kSill = kGround + gen::kWindowSill;
constexpr double kLintel = kSill + gen::kWindowSize;

glm::vec4 jitter(gen::GenRandom& rng, glm::vec4 c) {
  const float d = float(rng.uniform(-0.06, 0.06));
  return {glm::clamp(c.r + d, 0.0f, 1.0f), glm::clamp(c.g + d, 0.0f, 1.0f), glm::clamp(c.b + d, 0.0f, 1.0f), c.a};
}

void add_rooms(BuildingPlan& plan, gen::GenRandom& rng) {
  plan.rooms.push_back(gen::box_room("outside", 0, 11, 0, 8, kGround, kStoreyMid));
  plan.rooms.back().exterior = true;
  plan.rooms.back().ground_margin = 12.0;
  plan.rooms.back().color = {0.45f, 0.55f, 0.35f, 1.0f};
  plan.rooms.push_back(gen::box_room("hall", 4, 6.5, 0, 8, kFloorMid, kStoreyMid));
  plan.rooms.push_back(gen::box_room("living", 0, 4, 0, 4.5, kFloorMid, kStoreyMid));
  plan.rooms.push_back(gen::box_room("kitchen", 0, 4, 4.5, 8, kFloorMid, kStoreyMid));
  plan.rooms.push_back(gen::box_room("study", 6.5, 11, 0, 4, kFloorMid, kStoreyMid));
  plan.rooms.push_back(gen::box_room("bedroom", 6.5, 11, 4, 8, kFloorMid, kStoreyMid));
  plan.rooms.push_back(gen::box_room("cellar", 4, 11, 0, 4, kCellarMid, kFloorMid));
  const glm::vec4 wall_colors[] = {{0.45f, 0.55f, 0.35f, 1}, {0.86f, 0.84f, 0.78f, 1}, {0.92f, 0.86f, 0.74f, 1},
                                   {0.80f, 0.88f, 0.84f, 1}, {0.78f, 0.80f, 0.90f, 1}, {0.90f, 0.80f, 0.82f, 1},
                                   {0.60f, 0.58f, 0.55f, 1}};
  const glm::dquat house = plan.building_rotation;
  for (size_t i = 0; i < plan.rooms.size(); ++i) {
    gen::RoomPlan& room = plan.rooms[i];
    room.color = jitter(rng, wall_colors[i]);
    // Frame: the house's turn, then a seeded turn about a slightly tilted axis; scales alternate
    // between uniform and non-uniform; the origin is off the room's centre.
    const glm::dvec3 axis(rng.uniform(-0.3, 0.3), 1.0, rng.uniform(-0.3, 0.3));
    const glm::dquat extra = gen::rotation_about(axis, rng.uniform(0.0, 2.0 * gen::kPi));
    const double s = rng.log_uniform(0.5, 2.0);
    const glm::dvec3 scale =
        (i % 2 == 0) ? glm::dvec3(s) : glm::dvec3(s, rng.log_uniform(0.5, 2.0), rng.log_uniform(0.5, 2.0));
    const glm::dvec3 centre(0.5 * (room.footprint[0].x + room.footprint[2].x), room.floor_mid,
                            0.5 * (room.footprint[0].y + room.footprint[2].y));
    const glm::dvec3 offset(rng.uniform(-2, 2), rng.uniform(-1, 1), rng.uniform(-2, 2));
    room.frame.translation = glm::dvec3(gen::building_to_world(plan) * glm::dvec4(centre + offset, 1.0));
    room.frame.rotation = house * extra;
    room.frame.scale = scale;
  }
}

void add_openings(BuildingPlan& plan) {
  auto& o = plan.openings;
  // Doors.
  o.push_back(gen::opening_z(kOutside, kHall, 0, 4.8, 5.7, kGround, kDoorTop, true));
  o.back().name = "front_door";
  o.push_back(gen::opening_x(kHall, kLiving, 4, 1.8, 2.7, kGround, kDoorTop, false));
  o.back().name = "hall_living_door";
  o.push_back(gen::opening_x(kHall, kKitchen, 4, 5.8, 6.7, kGround, kDoorTop, false));
  o.back().name = "hall_kitchen_door";
  o.push_back(gen::opening_z(kLiving, kKitchen, 4.5, 2.6, 3.5, kGround, kDoorTop, true));
  o.back().name = "living_kitchen_door";
  o.push_back(gen::opening_x(kHall, kStudy, 6.5, 2.4, 3.3, kGround, kDoorTop, true));
  o.back().name = "hall_study_door";
  o.push_back(gen::opening_x(kHall, kBedroom, 6.5, 5.6, 6.5, kGround, kDoorTop, true));
  o.back().name = "hall_bedroom_door";
  o.push_back(gen::opening_z(kStudy, kBedroom, 4, 9.4, 10.3, kGround, kDoorTop, true));
  o.back().name = "study_bedroom_door";
  o.push_back(gen::opening_z(kKitchen, kOutside, 8, 2.8, 3.7, kGround, kDoorTop, true));
  o.back().name = "back_door";
  // Interior window and windows to the garden.
  o.push_back(gen::opening_z(kLiving, kKitchen, 4.5, 0.8, 1.8, kSill, kLintel, true));
  o.back().name = "living_kitchen_window";
  o.push_back(gen::opening_x(kLiving, kOutside, 0, 1.5, 2.5, kSill, kLintel, false));
  o.back().name = "living_west_window";
  o.push_back(gen::opening_z(kLiving, kOutside, 0, 1.5, 2.5, kSill, kLintel, false));
  o.back().name = "living_south_window";
  o.push_back(gen::opening_x(kKitchen, kOutside, 0, 5.75, 6.75, kSill, kLintel, false));
  o.back().name = "kitchen_window";
  o.push_back(gen::opening_z(kHall, kOutside, 8, 4.75, 5.75, kSill, kLintel, true));
  o.back().name = "hall_window";
  o.push_back(gen::opening_x(kBedroom, kOutside, 11, 5.5, 6.5, kSill, kLintel, true));
  o.back().name = "bedroom_east_window";
  o.push_back(gen::opening_z(kBedroom, kOutside, 8, 8.25, 9.25, kSill, kLintel, true));
  o.back().name = "bedroom_north_window";
  o.push_back(gen::opening_x(kStudy, kOutside, 11, 2.5, 3.5, kSill, kLintel, true));
  o.back().name = "study_window";
  // A mirror on the study's south wall, facing into the study over the stairwell: a linked portal
  // on the wall's inner face (it cuts no hole; docs/visibility.md, "Linked portals").
  o.push_back(gen::opening_z(kStudy, kStudy, 0.5 * gen::kWallThickness, 7.2, 9.6, kGround + 0.3, kDoorTop, false));
  o.back().name = "study_mirror";
  o.back().two_way = false;
  o.back().mirror = true;
  // The stairwell: a hole in the study floor over the cellar stair.
  o.push_back(gen::opening_slab(kStudy, kCellar, kFloorMid, 7.4, 10.4, 0.4, 1.4, false));
  o.back().name = "stairwell";
}

void add_furniture(BuildingPlan& plan, gen::GenRandom& rng) {
  plan.meshes = {gen::make_table(jitter(rng, {0.55f, 0.36f, 0.20f, 1})),
                 gen::make_chair(jitter(rng, {0.62f, 0.42f, 0.26f, 1})),
                 gen::make_bed(jitter(rng, {0.30f, 0.40f, 0.70f, 1})),
                 gen::make_shelf(jitter(rng, {0.45f, 0.30f, 0.18f, 1})),
                 gen::make_sofa(jitter(rng, {0.62f, 0.20f, 0.20f, 1})),
                 gen::make_crate(jitter(rng, {0.72f, 0.60f, 0.40f, 1})),
                 gen::make_tree(jitter(rng, {0.22f, 0.48f, 0.20f, 1})),
                 gen::make_stair(jitter(rng, {0.50f, 0.50f, 0.52f, 1}), 14, 3.58, 2.55, 0.9),
                 gen::make_door_leaf(jitter(rng, {0.58f, 0.40f, 0.24f, 1}))};
  struct Item {
    const char* name;
    Room room;
    Mesh mesh;
    double x, y, z, yaw_deg;
  };
  const Item items[] = {
      {"kitchen_table", kKitchen, kTable, 1.5, kGround, 6.5, 0},
      {"kitchen_chair_s", kKitchen, kChair, 1.5, kGround, 5.75, 180},
      {"kitchen_chair_n", kKitchen, kChair, 1.5, kGround, 7.25, 0},
      {"kitchen_chair_w", kKitchen, kChair, 0.6, kGround, 6.5, 90},
      {"kitchen_chair_e", kKitchen, kChair, 2.4, kGround, 6.5, -90},
      {"living_sofa", kLiving, kSofa, 0.6, kGround, 2.25, 90},
      {"living_table", kLiving, kTable, 1.8, kGround, 2.25, 90},
      {"living_shelf", kLiving, kShelf, 0.7, kGround, 0.3, 0},
      {"living_chair", kLiving, kChair, 2.9, kGround, 0.9, 200},
      {"bedroom_bed", kBedroom, kBed, 9.5, kGround, 6.9, -90},
      {"bedroom_chair", kBedroom, kChair, 7.2, kGround, 7.3, 150},
      {"bedroom_shelf", kBedroom, kShelf, 6.8, kGround, 4.6, 90},
      {"study_desk", kStudy, kTable, 8.6, kGround, 3.3, 0},
      {"study_shelf", kStudy, kShelf, 6.8, kGround, 0.8, 90},
      {"hall_shelf", kHall, kShelf, 6.2, kGround, 4.4, -90},
      {"cellar_shelf", kCellar, kShelf, 9.0, kCellarFloor, 3.7, 180},
      {"cellar_crate_a", kCellar, kCrate, 5.0, kCellarFloor, 3.2, 0},
      {"cellar_crate_b", kCellar, kCrate, 5.75, kCellarFloor, 3.3, 20},
      {"cellar_stair", kCellar, kStair, 6.8, kCellarFloor, 0.9, 0},
      {"garden_tree_a", kOutside, kTree, -4.0, kGround, -3.0, 0},
      {"garden_tree_b", kOutside, kTree, 14.5, kGround, 10.0, 30},
      // The living-room door's leaf, hinged at the hall side's north jamb, standing open into
      // the hall along the jamb; the `door` timeline swings it shut.
      {"hall_living_door_leaf", kHall, kDoorLeaf, 4 + 0.5 * gen::kWallThickness, kGround, 2.7, -90},
  };
  for (const Item& it : items)
    plan.instances.push_back(
        {it.name, it.room, it.mesh, {it.x, it.y, it.z}, gen::rotation_about({0, 1, 0}, gen::degrees(it.yaw_deg))});
}

void add_lights(BuildingPlan& plan) {
  LightDesc living{"living_lamp", Light::Type::Point, {1.0f, 0.85f, 0.65f}, 30.0f, 10.0f};
  plan.lights.push_back({kLiving, living, {2.0, 2.3, 2.2}, gen::kNoRotation});
  LightDesc kitchen{"kitchen_spot", Light::Type::Spot, {1.0f, 1.0f, 0.95f}, 60.0f, 8.0f, 0.3f, 0.6f};
  plan.lights.push_back({kKitchen, kitchen, {1.5, 2.4, 6.5}, gen::rotation_about({1, 0, 0}, gen::degrees(-90))});
  LightDesc cellar{"cellar_bulb", Light::Type::Point, {1.0f, 0.9f, 0.7f}, 15.0f, 8.0f};
  plan.lights.push_back({kCellar, cellar, {7.5, -0.6, 2.8}, gen::kNoRotation});
  LightDesc sun{"sun", Light::Type::Directional, {1.0f, 0.97f, 0.9f}, 3.0f};
  plan.lights.push_back({kOutside,
                         sun,
                         {5.0, 8.0, 4.0},
                         gen::rotation_between({0, 0, -1}, glm::normalize(glm::dvec3(-0.3, -1.0, -0.4)))});
}

// From the garden through the front door, the living room, the kitchen, back through the hall
// into the study and down the stair into the cellar: five doors and the stairwell. The stair's
// eye line runs 1.6 m above the treads' nosing line y = -2.7 + 0.75 (x - 6.8).
Timeline doorway_walk() {
  const double e = gen::kEyeHeight;
  auto stair_eye = [&](double x) { return glm::dvec3(x, kCellarFloor + 0.75 * (x - 6.8) + e, 0.9); };
  const std::vector<glm::dvec3> waypoints = {
      {5.25, e, -5.0},
      {5.25, e, -1.0},
      {5.25, e, 1.0},  // front door (z = 0)
      {5.0, e, 2.25},
      {3.0, e, 2.25},  // hall -> living (x = 4)
      {3.05, e, 3.5},
      {3.05, e, 5.5},  // living -> kitchen (z = 4.5)
      {3.0, e, 6.25},
      {5.0, e, 6.25},  // kitchen -> hall (x = 4)
      {5.5, e, 2.85},
      {7.5, e, 2.85},  // hall -> study (x = 6.5)
      {10.5, e, 2.6},
      {10.4, e, 0.9},  // round the stairwell to the top step
      stair_eye(9.0),
      stair_eye(7.2),
      stair_eye(6.8),  // down through the hole (y = -0.1)
      {5.0, kCellarFloor + e, 1.5},
  };
  return gen::walk_timeline("doorway", 30.0, waypoints);
}

// Standing in the hall facing the living-room door while the living-room chair is carried
// through it into the hall (in front of the camera); then the door closes in front of the camera
// (the living room and what lies behind it leave the visible set on that frame, and the living
// lamp no longer lights the hall), and the camera steps closer. Building space; keys 0.5 s apart.
Timeline door_walk() {
  const double e = gen::kEyeHeight;
  Timeline t;
  t.name = "door";
  t.fps = 30.0;
  t.fov_y_deg = 70.0;
  t.aspect = 16.0 / 9.0;
  for (int k = 0; k <= 8; ++k) {  // 4 s: from x = 6.2 to 5.6, looking through the door (x = 4)
    const double x = 6.2 - 0.075 * k;
    t.keys.push_back({0.5 * k, glm::vec3(float(x), float(e), 2.25f), glm::vec3(1.0f, float(e - 0.2), 2.25f)});
  }
  // The chair (origin on the floor) from its place through the door (z 1.8..2.7) into the hall.
  const glm::vec3 path[] = {{2.9f, 0.0f, 0.9f}, {3.2f, 0.0f, 2.25f}, {4.1f, 0.0f, 2.2f}, {4.6f, 0.0f, 1.6f}};
  for (int k = 0; k < 4; ++k) {
    TimelineInstanceKey key;
    key.t = 0.5 * k;
    key.instance = "living_chair";
    key.has_translation = true;
    key.translation_world = path[k];
    t.instance_keys.push_back(key);
  }
  // The door leaf swings shut in the last 0.1 s before the portal closes: a turn of the leaf as
  // placed (open) about its hinge, the instance origin, by 0 then +90 degrees.
  for (const auto& [time, yaw] : {std::pair{2.4, 0.0}, std::pair{2.5, 90.0}}) {
    TimelineInstanceKey key;
    key.t = time;
    key.instance = "hall_living_door_leaf";
    key.has_rotation = true;
    const glm::dquat q = gen::rotation_about({0, 1, 0}, gen::degrees(yaw));
    key.rotation_xyzw = glm::vec4(float(q.x), float(q.y), float(q.z), float(q.w));
    t.instance_keys.push_back(key);
  }
  t.events.push_back({2.5, "hall_living_door", false});
  return t;
}

}  // namespace

SceneDesc generate_cottage(const CottageOptions& options) {
  gen::GenRandom rng(options.seed);
  BuildingPlan plan;
  plan.building_rotation = gen::rotation_about({0, 1, 0}, gen::degrees(17.0));
  plan.building_translation = {3.0, 0.0, -2.0};
  add_rooms(plan, rng);
  add_openings(plan);
  add_furniture(plan, rng);
  add_lights(plan);
  plan.timelines.push_back(doorway_walk());
  plan.timelines.push_back(door_walk());
  return gen::assemble_scene(plan);
}

}  // namespace lintel
