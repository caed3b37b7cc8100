// CPU instance culling: the cell rule, the region rule, the near plane, and real mesh extents.
#include "test_worlds.h"

#include <lintel/instance_cull.h>
#include <lintel/instance_reach.h>
#include <lintel/visibility_builder.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace lintel {
namespace {

using testing::WorldBuilder;

bool has(const std::vector<uint32_t>& v, uint32_t x) { return std::find(v.begin(), v.end(), x) != v.end(); }

glm::mat4 at(const glm::vec3& p) { return glm::translate(glm::mat4(1.0f), p); }

// Rooms A | B | C along x (4 m each, non-identity frames). Door A|B at z in [-0.6, 0.6]; door
// B|C at z in [1.5, 1.9], just out of sight from the eye in A at (1, 1.2, 0) looking down +x.
struct CullScene {
  World world;
  glm::mat4 layout_to_world;
  uint32_t in_b_through_door, in_b_beside_door, in_c_in_frustum, straddles_near, contains_eye, before_near, behind_eye,
      baked_extent;
  View view() const {
    View v;
    v.eye_world = glm::vec3(layout_to_world * glm::vec4(1.0f, 1.2f, 0.0f, 1.0f));
    v.target_world = glm::vec3(layout_to_world * glm::vec4(10.0f, 1.2f, 0.0f, 1.0f));
    v.up_world = glm::mat3(layout_to_world) * glm::vec3(0.0f, 1.0f, 0.0f);
    return v;
  }
};

CullScene make_cull_scene(const glm::mat4& layout_to_world) {
  testing::WorldOptions o;
  o.layout_to_world = layout_to_world;
  WorldBuilder b(layout_to_world, o);
  const uint32_t a = b.add_box_cell("A", {0, 0, -2}, {4, 3, 2});
  const uint32_t bc = b.add_box_cell("B", {4, 0, -2}, {8, 3, 2});
  const uint32_t c = b.add_box_cell("C", {8, 0, -2}, {12, 3, 2});
  b.add_portal(a, bc, {{4, 0, -0.6f}, {4, 0, 0.6f}, {4, 2.2f, 0.6f}, {4, 2.2f, -0.6f}}, {2, 1, 0}, true);
  b.add_portal(bc, c, {{8, 0, 1.5f}, {8, 0, 1.9f}, {8, 2.2f, 1.9f}, {8, 2.2f, 1.5f}}, {6, 1, 0}, true);
  const uint32_t small = b.add_box_mesh({-0.2f, -0.2f, -0.2f}, {0.2f, 0.2f, 0.2f});
  const uint32_t tiny = b.add_box_mesh({-0.005f, -0.005f, -0.005f}, {0.005f, 0.005f, 0.005f});
  // A bench whose 2.5 m extent is baked into its vertices, far from the mesh origin.
  const uint32_t bench = b.add_box_mesh({5.0f, 0.0f, -0.3f}, {7.5f, 0.5f, 0.3f});
  CullScene s;
  s.in_b_through_door = b.add_instance(bc, small, at({6.0f, 1.2f, 0.0f}));
  s.in_b_beside_door = b.add_instance(bc, small, at({5.2f, 1.2f, 1.65f}));
  s.in_c_in_frustum = b.add_instance(c, small, at({10.0f, 1.2f, 0.0f}));
  s.straddles_near = b.add_instance(a, small, at({1.2f, 1.2f, 0.0f}));  // spans x in [1.0, 1.4]: around the near plane
  s.contains_eye = b.add_instance(a, tiny, at({1.0f, 1.2f, 0.0f}));     // 1 cm box around the eye
  s.before_near = b.add_instance(a, tiny, at({1.02f, 1.2f, 0.0f}));     // wholly between eye and near plane
  s.behind_eye = b.add_instance(a, small, at({0.5f, 1.2f, 0.0f}));
  s.baked_extent = b.add_instance(bc, bench, glm::inverse(layout_to_world));  // mesh_to_world = identity
  s.world = b.finish();
  s.layout_to_world = layout_to_world;
  return s;
}

TEST(InstanceCull, CellRegionNearPlaneAndRealExtentRules) {
  // The bench's mesh_to_world must be the identity: place the layout so that it is exactly.
  for (const glm::mat4& layout : {glm::mat4(1.0f), testing::default_layout_to_world()}) {
    const CullScene s = make_cull_scene(layout);
    VisibilityBuilder builder;
    VisibleSet v;
    ASSERT_TRUE(builder.build(s.world, s.view(), 0, {}, v).ok());
    ASSERT_TRUE(v.cell_visible(0) && v.cell_visible(1));
    EXPECT_FALSE(v.cell_visible(2)) << "C is behind B's wall";
    EXPECT_TRUE(has(v.instances, s.in_b_through_door));
    EXPECT_FALSE(has(v.instances, s.in_b_beside_door)) << "in a visible cell but outside its region";
    EXPECT_FALSE(has(v.instances, s.in_c_in_frustum)) << "in the frustum but its cell is not visible";
    EXPECT_TRUE(has(v.instances, s.straddles_near)) << "an AABB straddling the near plane is kept";
    EXPECT_TRUE(has(v.instances, s.contains_eye)) << "an AABB containing the eye is visible";
    EXPECT_FALSE(has(v.instances, s.before_near)) << "wholly before the near plane";
    EXPECT_FALSE(has(v.instances, s.behind_eye)) << "behind the eye";
    EXPECT_TRUE(std::is_sorted(v.instances.begin(), v.instances.end()));
    // The slots of A and B: their 7 instances, plus, in the rotated layout, the bench (B's),
    // whose identity mesh_to_world puts its world box across the A|B door: a slot in A too.
    CullData data;
    data.prepare(s.world);
    EXPECT_EQ(v.stats.instances_tested, uint64_t(data.cell_begin[2]));
    if (layout == glm::mat4(1.0f)) {
      EXPECT_EQ(v.stats.instances_tested, 7u);
    }
  }
}

// Lessons: "Cull bounds must use the real mesh extent, never a unit cube scaled by the instance
// matrix: identity-transform meshes otherwise cull against a 1 m box."
TEST(InstanceCull, IdentityTransformMeshWithBakedExtentIsNotCulledAsAUnitBox) {
  const CullScene s = make_cull_scene(glm::mat4(1.0f));
  const Instance& bench = s.world.instances[s.baked_extent];
  ASSERT_EQ(bench.mesh_to_world, glm::mat4(1.0f));
  VisibilityBuilder builder;
  VisibleSet v;
  ASSERT_TRUE(builder.build(s.world, s.view(), 0, {}, v).ok());
  EXPECT_TRUE(has(v.instances, s.baked_extent));
  // What a unit box would have said: the box around the origin lies behind the eye's near plane.
  const Aabb unit = transform_aabb(bench.mesh_to_world, Aabb{glm::vec3(-0.5f), glm::vec3(0.5f)});
  const ProjectedBox wrong = project_aabb(view_projection_d(s.view()), glm::dvec3(s.view().eye_world),
                                          glm::dvec3(unit.min), glm::dvec3(unit.max));
  EXPECT_FALSE(box_visible_in_region(wrong, v.region(*v.find(bench.cell))));
}

// Property (conservative projection): for random boxes and views, every point of the box between
// the near and far planes projects inside the box's NDC rect; boxes with no such point are not in
// the slab.
TEST(InstanceCull, ProjectedRectContainsEveryVisiblePointOfTheBox) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int in_slab = 0;
  for (int trial = 0; trial < 500; ++trial) {
    View v;
    v.eye_world = glm::vec3(u(rng), u(rng), u(rng));
    v.target_world = v.eye_world + glm::vec3(u(rng), 0.3 * u(rng), u(rng)) + glm::vec3(0.0f, 0.0f, 0.01f);
    v.far_m = 8.0f;
    const glm::dmat4 vp = view_projection_d(v);
    const glm::dvec3 c(2.0 * u(rng), 2.0 * u(rng), 2.0 * u(rng));
    const glm::dvec3 half(0.05 + std::abs(u(rng)), 0.05 + std::abs(u(rng)), 0.05 + std::abs(u(rng)));
    const ProjectedBox box = project_aabb(vp, glm::dvec3(v.eye_world), c - half, c + half);
    in_slab += box.in_slab;
    for (int i = 0; i < 300; ++i) {
      const glm::dvec3 p = c + half * glm::dvec3(u(rng), u(rng), u(rng));
      const glm::dvec4 q = vp * glm::dvec4(p, 1.0);
      if (q.z < 0.0 || q.z > q.w) continue;
      ASSERT_TRUE(box.in_slab) << "trial " << trial;
      const glm::dvec2 ndc(q.x / q.w, q.y / q.w);
      EXPECT_TRUE(ndc.x >= box.rect_ndc.min.x && ndc.x <= box.rect_ndc.max.x && ndc.y >= box.rect_ndc.min.y &&
                  ndc.y <= box.rect_ndc.max.y)
          << "trial " << trial;
    }
  }
  EXPECT_GT(in_slab, 100);
}

TEST(InstanceCull, CullDataGroupsInstancesByCellInSoA) {
  const CullScene s = make_cull_scene(testing::default_layout_to_world());
  CullData data;
  data.prepare(s.world);
  InstanceReach reach;
  reach.compute(s.world);
  ASSERT_EQ(data.size(), reach.total()) << "one slot per (instance, reached cell)";
  ASSERT_EQ(data.cell_begin.size(), s.world.cells.size() + 1);
  for (uint32_t c = 0; c < s.world.cells.size(); ++c) {
    std::vector<uint32_t> slots;
    for (uint32_t k = data.cell_begin[c]; k < data.cell_begin[c + 1]; ++k) slots.push_back(data.slots[k].instance);
    std::vector<uint32_t> expected;
    for (uint32_t i = 0; i < s.world.instances.size(); ++i)
      if (std::find(reach.begin(i), reach.end(i), c) != reach.end(i)) expected.push_back(i);
    EXPECT_EQ(slots, expected);
    for (uint32_t i : s.world.cells[c].instances)
      EXPECT_TRUE(has(slots, i)) << "an instance has a slot in its own cell";
    for (uint32_t k = data.cell_begin[c]; k < data.cell_begin[c + 1]; ++k) {
      const Aabb& b = s.world.instances[data.slots[k].instance].bounds_world;
      EXPECT_EQ(data.slots[k].min, b.min);
      EXPECT_EQ(data.slots[k].max, b.max);
      EXPECT_EQ(data.slots[k].cell, c);
    }
  }
}

// Rooms D | A along z and a sliver B (0.5 m x 2 m) beside A along x, then C beyond B:
//   D: x [0,4] z [-4,0];  A: x [0,4] z [0,4];  B: x [4,4.5] z [1,3];  C: x [4.5,8.5] z [0,4].
// Doors: D|A at z = 0 over x [2,3]; A|B at x = 4 and B|C at x = 4.5, both over z [1,3].
// A 4 m box stands in B (x [2.25,6.25]) and reaches A and C through B's doors. The eye in D looks
// through the D|A door at the box's part in A; the A|B door lies outside that door's view, so B
// (the box's own cell) is not visible: only its neighbour A is. Identity layout: the expected
// reach is exact (a rotated layout widens world boxes, and reach is conservative).
struct SliverScene {
  World world;
  uint32_t a, b, c, d, big_box, boxed_in, poking_through_wall;
  View view() const {
    View v;
    v.eye_world = glm::vec3(2.5f, 1.6f, -3.0f);
    v.target_world = glm::vec3(2.5f, 0.5f, 2.0f);
    return v;
  }
};

SliverScene make_sliver_scene() {
  testing::WorldOptions o;
  o.layout_to_world = glm::mat4(1.0f);
  WorldBuilder b(o.layout_to_world, o);
  SliverScene s;
  s.d = b.add_box_cell("D", {0, 0, -4}, {4, 3, 0});
  s.a = b.add_box_cell("A", {0, 0, 0}, {4, 3, 4});
  s.b = b.add_box_cell("B", {4, 0, 1}, {4.5f, 3, 3});
  s.c = b.add_box_cell("C", {4.5f, 0, 0}, {8.5f, 3, 4});
  b.add_portal(s.d, s.a, {{2, 0, 0}, {3, 0, 0}, {3, 2.2f, 0}, {2, 2.2f, 0}}, {2.5f, 1, -1}, true);
  b.add_portal(s.a, s.b, {{4, 0, 1}, {4, 0, 3}, {4, 2.5f, 3}, {4, 2.5f, 1}}, {3, 1, 2}, true);
  b.add_portal(s.b, s.c, {{4.5f, 0, 1}, {4.5f, 0, 3}, {4.5f, 2.5f, 3}, {4.5f, 2.5f, 1}}, {4.25f, 1, 2}, true);
  const uint32_t long_box = b.add_box_mesh({-2.0f, 0.0f, -0.25f}, {2.0f, 1.0f, 0.25f});
  const uint32_t small = b.add_box_mesh({-0.1f, 0.0f, -0.1f}, {0.1f, 0.2f, 0.1f});
  const uint32_t slab = b.add_box_mesh({-0.1f, 0.0f, -1.5f}, {0.1f, 1.0f, 1.5f});
  s.big_box = b.add_instance(s.b, long_box, at({4.25f, 0.0f, 2.0f}));
  s.boxed_in = b.add_instance(s.b, small, at({4.25f, 0.0f, 2.0f}));            // wholly inside B
  s.poking_through_wall = b.add_instance(s.b, slab, at({4.25f, 0.0f, 2.0f}));  // z [0.5,3.5]: into B's side walls
  s.world = b.finish();
  return s;
}

TEST(InstanceReach, ABoxLargerThanItsCellReachesTheCellsBehindItsPortals) {
  const SliverScene s = make_sliver_scene();
  InstanceReach reach;
  reach.compute(s.world);
  auto cells_of = [&](uint32_t i) { return std::vector<uint32_t>(reach.begin(i), reach.end(i)); };
  std::vector<uint32_t> expected{s.b, s.a, s.c};
  std::sort(expected.begin() + 1, expected.end());
  EXPECT_EQ(cells_of(s.big_box), expected) << "own cell first, then the cells behind B's two doors";
  EXPECT_EQ(cells_of(s.boxed_in), std::vector<uint32_t>{s.b});
  // Its box pokes through B's side walls (z = 1 and 3) but meets neither door's plane.
  EXPECT_EQ(cells_of(s.poking_through_wall), std::vector<uint32_t>{s.b});
  CullData data;
  data.prepare(s.world);
  EXPECT_EQ(data.size(), s.world.instances.size() + 2) << "the big box has a slot in A and in C too";
  for (uint32_t cell : {s.a, s.c}) {
    std::vector<uint32_t> slots;
    for (uint32_t k = data.cell_begin[cell]; k < data.cell_begin[cell + 1]; ++k)
      slots.push_back(data.slots[k].instance);
    EXPECT_EQ(slots, std::vector<uint32_t>{s.big_box}) << "cell " << cell;
  }
}

// Issue 14: a large object seen only through a neighbour of its cell must be listed.
TEST(InstanceReach, AnInstanceVisibleOnlyThroughANeighbourCellIsListed) {
  const SliverScene s = make_sliver_scene();
  VisibilityBuilder builder;
  VisibleSet v;
  ASSERT_TRUE(builder.build(s.world, s.view(), s.d, {}, v).ok());
  ASSERT_TRUE(v.cell_visible(s.a));
  ASSERT_FALSE(v.cell_visible(s.b)) << "the premise: the box's own cell is out of sight";
  EXPECT_TRUE(has(v.instances, s.big_box));
  EXPECT_FALSE(has(v.instances, s.boxed_in)) << "wholly inside B, which is not visible";
  EXPECT_EQ(std::count(v.instances.begin(), v.instances.end(), s.big_box), 1);
  EXPECT_TRUE(std::is_sorted(v.instances.begin(), v.instances.end()));
}

// Listed once even when several reached cells are visible (here B and A and C from inside B).
TEST(InstanceReach, AnInstanceReachingSeveralVisibleCellsIsListedOnce) {
  const SliverScene s = make_sliver_scene();
  View v = s.view();
  v.eye_world = glm::vec3(1.0f, 1.6f, 2.0f);
  v.target_world = glm::vec3(8.0f, 1.0f, 2.0f);
  VisibilityBuilder builder;
  VisibleSet out;
  ASSERT_TRUE(builder.build(s.world, v, s.a, {}, out).ok());
  ASSERT_TRUE(out.cell_visible(s.a) && out.cell_visible(s.b) && out.cell_visible(s.c));
  EXPECT_EQ(std::count(out.instances.begin(), out.instances.end(), s.big_box), 1);
  EXPECT_TRUE(has(out.instances, s.boxed_in));
}

}  // namespace
}  // namespace lintel
