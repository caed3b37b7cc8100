// Valid scenes whose cell frames sit 1e4 m from their rooms, with small portals: float32 rounding
// of such coordinates (about 0.5 mm) must not make the loader refuse them, and the
// portals it keeps must still be the planned rectangles, oriented from `from` into `to`.
#include "gen_test_support.h"
#include "generate/scene_assembly.h"

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <string>

namespace lintel {
namespace {

// Two 4 m rooms side by side joined by a square window of `window_m`, each frame 1e4 m away from
// its room along every axis and turned about a skew axis (so every coordinate carries rounding).
SceneDesc far_two_rooms(double window_m, double offset_m) {
  gen::BuildingPlan plan;
  for (int r = 0; r < 2; ++r) {
    gen::RoomPlan room = gen::box_room("room" + std::to_string(r), 4.0 * r, 4.0 * r + 4.0, 0.0, 4.0, 0.0, 3.0);
    const double sign = r == 0 ? 1.0 : -1.0;
    room.frame.translation = glm::dvec3(offset_m * sign, -offset_m, offset_m);
    room.frame.rotation = glm::angleAxis(0.7 + r, glm::normalize(glm::dvec3(1.0, 2.0, 3.0)));
    plan.rooms.push_back(std::move(room));
  }
  const double z0 = 2.0 - 0.5 * window_m, y0 = 1.2;
  plan.openings.push_back(gen::opening_x(0, 1, 4.0, z0, z0 + window_m, y0, y0 + window_m, true));
  plan.openings.back().name = "window";
  return gen::assemble_scene(plan);
}

// Property: for windows from 0.7 m down to 0.1 m (where the relative planarity tolerance of
// 1e-3 x size is far below the rounding of 1e4 m coordinates), the scene loads without warnings
// and the portal is the planned square (corners within 1 cm), its normal along +X (room0 -> room1).
TEST(FarFrames, SmallPortalsOnFramesTenKilometresAwayLoadAndKeepTheirShape) {
  for (double window_m : {0.7, 0.5, 0.3, 0.1}) {
    SCOPED_TRACE("window " + std::to_string(window_m) + " m");
    World world;
    ASSERT_TRUE(gen_test::load(far_two_rooms(window_m, 1e4), "far_frames", world));
    ASSERT_EQ(world.portals.size(), 1u);
    const Portal& portal = world.portals[0];
    EXPECT_GT(portal.normal_world.x, 0.999f);
    ASSERT_EQ(portal.polygon_world.size(), 4u);
    for (const glm::vec3& v : portal.polygon_world) {
      EXPECT_NEAR(v.x, 4.0, 1e-2);
      const double dz = std::fabs(v.z - 2.0) - 0.5 * window_m,
                   dy = std::min(std::fabs(v.y - 1.2), std::fabs(v.y - 1.2 - window_m));
      EXPECT_LT(std::fabs(dz), 1e-2);
      EXPECT_LT(dy, 1e-2);
    }
  }
}

// The same rooms with frames at the origin load too (the floor only ever widens a tolerance), so
// the test above measures the far frames, not the plan.
TEST(FarFrames, TheSameRoomsNearTheirFramesLoad) {
  World world;
  ASSERT_TRUE(gen_test::load(far_two_rooms(0.1, 0.0), "near_frames", world));
  EXPECT_EQ(world.portals.size(), 1u);
}

}  // namespace
}  // namespace lintel
