// A large object: a 4 m box standing in a 2 x 0.5 m cell, reaching into the cells beside it, seen only
// through one of those neighbours. The ray cast (Embree ground truth) sees it; every conservative
// method, Lintel's builder included, must list it.
#include "generate/scene_assembly.h"
#include "sliver_building.h"

#include <lintel/reference/bench_views.h>
#include <lintel/reference/cull_method.h>
#include <lintel/reference/exact_oracle.h>
#include <lintel/reference/ray_ground_truth.h>
#include <lintel/scene_io.h>
#include <lintel/visibility_builder.h>

#include <gtest/gtest.h>

#include <algorithm>

namespace lintel {
namespace {

// Rooms (wall mid-planes, building space = world): D x [0,4] z [-4,0]; A x [0,4] z [0,4];
// the sliver B x [4,4.5] z [1,3]; C x [4.5,8.5] z [0,4]. Doors: D|A at z = 0 over x [2,3];
// A|B and B|C over B's whole 2 m side. The box (a one-step "stair", 4 x 1 x 0.5 m) stands in B
// from x = 2.25 to 6.25. The eye in D looks through the D|A door at the box's part in A; the A|B
// door is outside that door's view, so B itself is not visible.
struct SliverWorld {
  World world;
  uint32_t box = 0, cell_a = 0, cell_b = 0, cell_d = 0;
};

SliverWorld make_sliver_world() {
  const gen::BuildingPlan plan = test::sliver_building_plan();
  SliverWorld s;
  EXPECT_TRUE(build_world(gen::assemble_scene(plan), "sliver", s.world).ok());
  s.box = 0;
  EXPECT_EQ(s.world.instances.size(), 1u);
  for (uint32_t c = 0; c < s.world.cells.size(); ++c) {
    if (s.world.cells[c].name == "A") s.cell_a = c;
    if (s.world.cells[c].name == "B") s.cell_b = c;
    if (s.world.cells[c].name == "D") s.cell_d = c;
  }
  return s;
}

TEST(LargeInstance, FourMetreBoxInASliverCellIsListedWhenOnlyItsNeighbourIsVisible) {
  const SliverWorld s = make_sliver_world();
  ASSERT_EQ(s.world.cells[s.cell_b].name, "B");
  const Aabb& b = s.world.instances[s.box].bounds_world;
  ASSERT_GE(b.max.x - b.min.x, 3.99f) << "the box is 4 m long";
  View view;
  view.eye_world = glm::vec3(2.5f, 1.6f, -3.0f);
  view.target_world = glm::vec3(2.5f, 0.5f, 2.0f);
  view.aspect = 1.0f;

  RayGroundTruth rays;
  ASSERT_TRUE(rays.build(s.world).ok());
  GroundTruth gt;
  rays.cast(ray_camera_of(view), 256, gt);
  uint32_t box_rays = 0;
  for (const RayHitId& h : gt.pixels) box_rays += h.instance == s.box;
  ASSERT_TRUE(gt.instance_visible[s.box]) << "the premise: rays see the box";
  EXPECT_GT(box_rays, 100u);

  VisibilityBuilder builder;
  VisibleSet visible;
  ASSERT_TRUE(builder.build(s.world, view, s.cell_d, {}, visible).ok());
  ASSERT_TRUE(visible.cell_visible(s.cell_a));
  ASSERT_FALSE(visible.cell_visible(s.cell_b)) << "the premise: the box's own cell is out of sight";
  EXPECT_TRUE(std::binary_search(visible.instances.begin(), visible.instances.end(), s.box))
      << "seen by " << box_rays << " rays but culled";

  // The accuracy benchmark's conservative methods agree (they list by the same reach).
  std::vector<std::unique_ptr<CullMethod>> methods;
  methods.push_back(make_polygon_method(1024, 16));
  methods.push_back(make_rect_method());
  methods.push_back(make_exact_method());
  for (const auto& method : methods) {
    MethodResult r;
    ASSERT_TRUE(method->run(s.world, view, s.cell_d, r).ok());
    EXPECT_TRUE(r.instance_visible[s.box]) << method->name();
  }
}

}  // namespace
}  // namespace lintel
