// Every generator's output passes the validating loader without a warning, over a range of sizes
// and seeds, and has the cycles it promises.
#include "gen_test_support.h"

#include <lintel/scene_gen.h>

#include <gtest/gtest.h>

#include <algorithm>

namespace lintel {
namespace {

TEST(GeneratorsLoad, Grid) {
  for (uint32_t w = 1; w <= 8; ++w)
    for (uint32_t h = 1; h <= 8; ++h)
      for (bool jitter : {false, true}) {
        const std::string label = "grid " + std::to_string(w) + "x" + std::to_string(h) + (jitter ? " jitter" : "");
        World world;
        ASSERT_TRUE(gen_test::load(generate_grid({w, h, jitter, w * 100 + h}), label, world, w * h == 1)) << label;
        EXPECT_EQ(world.cells.size(), size_t(w) * h) << label;
        EXPECT_EQ(world.portals.size(), size_t(w - 1) * h + size_t(h - 1) * w) << label;
        EXPECT_EQ(world.portal_graph_cycles(), size_t(w - 1) * (h - 1)) << label;
        for (const Cell& c : world.cells) {
          EXPECT_NE(c.cell_to_world, glm::mat4(1.0f)) << label << " " << c.name;
          if (jitter) {
            EXPECT_TRUE(gen_test::has_odd_rotation(c.cell_to_world)) << label << " " << c.name;
          }
        }
      }
}

// The stability suite's tiny portals: the grid's openings as 1 mm windows 1.2 m above the floor
// load without a warning, and every portal is exactly that square, at that height.
TEST(GeneratorsLoad, GridWithTinyWindows) {
  GridOptions o;
  o.width = o.height = 3;
  o.jitter = true;
  o.door_width_m = o.door_height_m = 1e-3;
  o.door_sill_m = 1.2;
  World world;
  ASSERT_TRUE(gen_test::load(generate_grid(o), "grid 3x3 tiny windows", world));
  ASSERT_EQ(world.portals.size(), 12u);
  for (const Portal& p : world.portals) {
    Aabb box;
    for (const glm::vec3& v : p.polygon_world) box.extend(v);
    const glm::vec3 e = box.extent();
    EXPECT_NEAR(e.y, 1e-3, 1e-6) << p.name;
    EXPECT_NEAR(std::max(e.x, e.z), 1e-3, 1e-6) << p.name;  // across the wall
    EXPECT_NEAR(std::min(e.x, e.z), 0.0, 1e-6) << p.name;   // the wall's mid-plane
    EXPECT_NEAR(box.min.y, 1.2, 1e-6) << p.name;            // the floor is at y = 0
  }
}

TEST(GeneratorsLoad, Ring) {
  for (uint32_t n = 2; n <= 64; ++n) {
    const std::string label = "ring " + std::to_string(n);
    World world;
    ASSERT_TRUE(gen_test::load(generate_ring({n, 1}), label, world)) << label;
    EXPECT_EQ(world.cells.size(), n) << label;
    EXPECT_EQ(world.portals.size(), n) << label;
    EXPECT_EQ(world.portal_graph_cycles(), 1u) << label;
  }
}

TEST(GeneratorsLoad, RandomSeeds) {
  for (uint64_t seed = 1; seed <= 30; ++seed) {
    RandomOptions o;
    o.seed = seed;
    o.cells = uint32_t(2 + (seed * 13) % 60);
    o.storeys = uint32_t(1 + seed % 3);
    const std::string label = "random seed " + std::to_string(seed) + " cells " + std::to_string(o.cells);
    World world;
    ASSERT_TRUE(gen_test::load(generate_random(o), label, world)) << label;
    EXPECT_EQ(world.cells.size(), o.cells) << label;
    EXPECT_GE(world.portal_graph_cycles(), 1u) << label;
    for (const Cell& c : world.cells)
      EXPECT_TRUE(gen_test::has_odd_rotation(c.cell_to_world)) << label << " " << c.name;
  }
}

TEST(GeneratorsLoad, RandomOptionExtremes) {
  RandomOptions o;
  o.cells = 30;
  o.storeys = 3;
  o.extra_portal_fraction = 1.0;
  o.one_way_fraction = 1.0;
  o.window_fraction = 1.0;
  o.volume_fraction = 0.0;
  World world;
  ASSERT_TRUE(gen_test::load(generate_random(o), "random, all extras one-way windows", world));
  size_t one_way = 0;
  for (const Portal& p : world.portals) one_way += !p.two_way;
  EXPECT_GT(one_way, 0u);

  o = {};
  o.cells = 25;
  o.min_scale = o.max_scale = 1.0;
  o.max_offset_m = 0.0;
  o.global_rotation = false;
  o.max_global_offset_m = 0.0;
  o.volume_fraction = 1.0;
  ASSERT_TRUE(gen_test::load(generate_random(o), "random, plain frames", world));
}

TEST(GeneratorsLoad, LargeScenes) {
  World world;
  ASSERT_TRUE(gen_test::load(generate_grid({32, 32, true, 1}), "grid 32x32", world));
  ASSERT_TRUE(gen_test::load(generate_ring({1024, 1}), "ring 1024", world));
  RandomOptions o;
  o.cells = 1000;
  ASSERT_TRUE(gen_test::load(generate_random(o), "random 1000", world));
}

}  // namespace
}  // namespace lintel
