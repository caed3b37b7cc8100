// Same options and seed, same bytes; another seed, another random scene; and the cottage's seed
// moves only frames and colours, never the world geometry.
#include "gen_test_support.h"

#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace lintel {
namespace {

std::vector<uint8_t> glb(const SceneDesc& scene) {
  std::vector<uint8_t> out;
  const Status s = scene_to_glb(scene, out);
  EXPECT_TRUE(s.ok()) << s.message();
  return out;
}

TEST(Determinism, SameSeedSameBytes) {
  EXPECT_EQ(glb(generate_cottage({7})), glb(generate_cottage({7})));
  EXPECT_EQ(glb(generate_grid({6, 5, true, 3})), glb(generate_grid({6, 5, true, 3})));
  EXPECT_EQ(glb(generate_ring({9, 2})), glb(generate_ring({9, 2})));
  RandomOptions r;
  r.cells = 40;
  r.seed = 11;
  EXPECT_EQ(glb(generate_random(r)), glb(generate_random(r)));
}

TEST(Determinism, OtherSeedOtherRandomScene) {
  RandomOptions a, b;
  a.cells = b.cells = 20;
  a.seed = 1;
  b.seed = 2;
  EXPECT_NE(glb(generate_random(a)), glb(generate_random(b)));
  EXPECT_NE(glb(generate_grid({4, 4, true, 1})), glb(generate_grid({4, 4, true, 2})));
}

// Cell frames differ between seeds, portals in the world stay put (to float precision).
TEST(Determinism, CottageSeedKeepsWorldGeometry) {
  World w1, w2;
  ASSERT_TRUE(gen_test::load(generate_cottage({1}), "cottage-1", w1));
  ASSERT_TRUE(gen_test::load(generate_cottage({2}), "cottage-2", w2));
  ASSERT_EQ(w1.portals.size(), w2.portals.size());
  bool frames_differ = false;
  for (size_t c = 0; c < w1.cells.size(); ++c) frames_differ |= w1.cells[c].cell_to_world != w2.cells[c].cell_to_world;
  EXPECT_TRUE(frames_differ);
  // The loader may start a polygon at another corner: compare corners as sets.
  for (size_t i = 0; i < w1.portals.size(); ++i) {
    ASSERT_EQ(w1.portals[i].polygon_world.size(), w2.portals[i].polygon_world.size());
    for (const glm::vec3& v : w1.portals[i].polygon_world) {
      float nearest = INFINITY;
      for (const glm::vec3& u : w2.portals[i].polygon_world) nearest = std::min(nearest, glm::length(v - u));
      EXPECT_LT(nearest, 1e-4f) << w1.portals[i].name;
    }
  }
  const auto t1 = gen_test::world_triangles(w1, true), t2 = gen_test::world_triangles(w2, true);
  ASSERT_EQ(t1.size(), t2.size());
  for (size_t i = 0; i < t1.size(); ++i) EXPECT_LT(glm::length(t1[i].a - t2[i].a), 1e-4) << "triangle " << i;
}

}  // namespace
}  // namespace lintel
