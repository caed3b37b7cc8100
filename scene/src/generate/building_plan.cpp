// Constructors for axis-aligned rooms and openings, shared by the cottage, grid and random plans.
#include "generate/building_plan.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cassert>

namespace lintel::gen {

RoomPlan box_room(std::string name, double x0, double x1, double z0, double z1, double y0, double y1) {
  assert(x0 < x1 && z0 < z1 && y0 < y1);
  RoomPlan room;
  room.name = std::move(name);
  room.footprint = {{x0, z0}, {x1, z0}, {x1, z1}, {x0, z1}};
  room.floor_mid = y0;
  room.ceiling_mid = y1;
  return room;
}

OpeningPlan opening_x(int from, int to, double x_mid, double z0, double z1, double y0, double y1, bool toward_plus_x) {
  OpeningPlan o;
  o.from = from;
  o.to = to;
  o.origin = {x_mid, 0.0, 0.0};
  o.u_axis = {0.0, 0.0, 1.0};
  o.v_axis = {0.0, 1.0, 0.0};
  o.u0 = z0, o.u1 = z1, o.v0 = y0, o.v1 = y1;
  o.normal = {toward_plus_x ? 1.0 : -1.0, 0.0, 0.0};
  return o;
}

OpeningPlan opening_z(int from, int to, double z_mid, double x0, double x1, double y0, double y1, bool toward_plus_z) {
  OpeningPlan o;
  o.from = from;
  o.to = to;
  o.origin = {0.0, 0.0, z_mid};
  o.u_axis = {1.0, 0.0, 0.0};
  o.v_axis = {0.0, 1.0, 0.0};
  o.u0 = x0, o.u1 = x1, o.v0 = y0, o.v1 = y1;
  o.normal = {0.0, 0.0, toward_plus_z ? 1.0 : -1.0};
  return o;
}

OpeningPlan opening_slab(int from, int to, double y_mid, double x0, double x1, double z0, double z1, bool upward) {
  OpeningPlan o;
  o.from = from;
  o.to = to;
  o.in_slab = true;
  o.origin = {0.0, y_mid, 0.0};
  o.u_axis = {1.0, 0.0, 0.0};
  o.v_axis = {0.0, 0.0, 1.0};
  o.u0 = x0, o.u1 = x1, o.v0 = z0, o.v1 = z1;
  o.normal = {0.0, upward ? 1.0 : -1.0, 0.0};
  return o;
}

glm::dmat4 building_to_world(const BuildingPlan& plan) {
  return glm::translate(glm::dmat4(1.0), plan.building_translation) * glm::mat4_cast(plan.building_rotation);
}

}  // namespace lintel::gen
