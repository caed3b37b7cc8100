// The building of the "large object" case, shared by the CPU and GPU tests: rooms D, A, B, C
// in a row, B a 0.5 x 2 m sliver with doors to A and C, and a 4 m long box standing in B that
// reaches A and C through those doors (x from 2.25 to 6.25). D looks into A through the D|A door.
// Header-only; needs the generator's internal plan headers (scene/src on the include path).
#pragma once

#include "generate/building_plan.h"
#include "generate/furniture_meshes.h"

#include <glm/glm.hpp>

namespace lintel::test {

// Rooms 0..3 are D, A, B, C; mesh 0 is the long box, instance 0 ("long-box") stands in B.
inline gen::BuildingPlan sliver_building_plan() {
  gen::BuildingPlan plan;
  plan.rooms.push_back(gen::box_room("D", 0, 4, -4, 0, 0, 3));
  plan.rooms.push_back(gen::box_room("A", 0, 4, 0, 4, 0, 3));
  plan.rooms.push_back(gen::box_room("B", 4, 4.5, 1, 3, 0, 3));
  plan.rooms.push_back(gen::box_room("C", 4.5, 8.5, 0, 4, 0, 3));
  // Openings narrower than the walls they cut: the generator keeps a wall strip on each side.
  plan.openings.push_back(gen::opening_z(0, 1, 0.0, 2.0, 3.0, 0.1, 2.2, true));
  plan.openings.push_back(gen::opening_x(1, 2, 4.0, 1.2, 2.8, 0.1, 2.5, true));
  plan.openings.push_back(gen::opening_x(2, 3, 4.5, 1.2, 2.8, 0.1, 2.5, true));
  plan.meshes.push_back(gen::make_stair(glm::vec4(0.6f, 0.3f, 0.2f, 1.0f), 1, 4.0, 1.0, 0.5));
  gen::InstancePlan box;
  box.name = "long-box";
  box.room = 2;
  box.mesh = 0;
  box.position = {2.25, 0.1, 2.0};
  plan.instances.push_back(box);
  return plan;
}

}  // namespace lintel::test
