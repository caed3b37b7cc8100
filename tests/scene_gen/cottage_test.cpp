// The default scene has what the visibility tests need: enough cells and cycles, only
// non-identity cell frames (one turned by an angle that is not a multiple of 90 degrees), shared
// meshes, lights of several kinds and a doorway timeline through portals.
#include "gen_test_support.h"

#include <lintel/scene_gen.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace lintel {
namespace {

class Cottage : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    desc_ = new SceneDesc(generate_cottage({}));
    world_ = new World;
    ASSERT_TRUE(gen_test::load(*desc_, "cottage", *world_));
  }
  static void TearDownTestSuite() {
    delete desc_;
    delete world_;
  }
  static SceneDesc* desc_;
  static World* world_;
};
SceneDesc* Cottage::desc_ = nullptr;
World* Cottage::world_ = nullptr;

// The description before writing: cells are roots with their own (non-uniform in places) frames,
// portals are quads below their `from` cell, furniture shares meshes.
TEST_F(Cottage, SceneDescStructure) {
  size_t cells = 0, portals = 0, volumes = 0, non_uniform = 0;
  std::vector<int> uses(desc_->meshes.size(), 0);
  for (const NodeDesc& n : desc_->nodes) {
    switch (n.kind) {
      case NodeDesc::Kind::Cell:
        ++cells;
        EXPECT_EQ(n.parent, -1) << n.name;
        EXPECT_GE(n.mesh, 0) << n.name;
        EXPECT_NE(n.translation, glm::vec3(0.0f)) << n.name;
        non_uniform += n.scale.x != n.scale.y || n.scale.y != n.scale.z;
        break;
      case NodeDesc::Kind::Portal:
        ++portals;
        ASSERT_GE(n.parent, 0);
        EXPECT_EQ(desc_->nodes[size_t(n.parent)].cell_name, n.portal_from) << n.name;
        EXPECT_EQ(desc_->meshes[size_t(n.mesh)].positions.size(), 4u) << n.name;
        break;
      case NodeDesc::Kind::Volume:
        ++volumes;
        break;
      case NodeDesc::Kind::Plain:
        if (n.mesh >= 0) ++uses[size_t(n.mesh)];
        break;
    }
  }
  EXPECT_EQ(cells, 7u);
  EXPECT_EQ(volumes, cells);
  EXPECT_GE(portals, 15u);
  EXPECT_GE(non_uniform, 1u);
  EXPECT_GE(std::count_if(uses.begin(), uses.end(), [](int u) { return u >= 2; }), 3);
  ASSERT_EQ(desc_->timelines.size(), 2u);
  EXPECT_EQ(desc_->timelines[0].name, "doorway");
  // The door timeline: a carried chair and one door event (docs/rendering.md).
  EXPECT_EQ(desc_->timelines[1].name, "door");
  EXPECT_EQ(desc_->timelines[1].events.size(), 1u);
  EXPECT_FALSE(desc_->timelines[1].instance_keys.empty());
}

TEST_F(Cottage, CellsAndCycles) {
  EXPECT_GE(world_->cells.size(), 7u);
  EXPECT_GE(world_->portal_graph_cycles(), 2u);
  std::set<std::string> names;
  for (const Cell& c : world_->cells) names.insert(c.name);
  for (const char* n : {"outside", "hall", "kitchen", "living", "bedroom", "study", "cellar"})
    EXPECT_TRUE(names.count(n)) << n;
}

TEST_F(Cottage, EveryCellFrameIsNonIdentityAndOneIsOddlyTurned) {
  bool odd = false;
  for (const Cell& c : world_->cells) {
    EXPECT_NE(c.cell_to_world, glm::mat4(1.0f)) << c.name;
    odd |= gen_test::has_odd_rotation(c.cell_to_world);
  }
  EXPECT_TRUE(odd);
}

TEST_F(Cottage, SharedMeshesLightsAndVolumes) {
  size_t shared = 0;
  for (const DrawGroup& g : world_->groups) shared += g.instances.size() >= 2;
  EXPECT_GE(shared, 3u);
  EXPECT_GE(world_->lights.size(), 2u);
  std::set<Light::Type> types;
  for (const Light& l : world_->lights) types.insert(l.type);
  EXPECT_EQ(types.size(), 3u);
  for (const Cell& c : world_->cells) EXPECT_FALSE(c.volume_triangles_cell.empty()) << c.name;
}

TEST_F(Cottage, HorizontalStairwellPortal) {
  bool found = false;
  for (const Portal& p : world_->portals)
    if (world_->cells[p.from].name == "study" && world_->cells[p.to].name == "cellar") {
      found = true;
      // The house is only turned about +Y, so the stairwell's normal is vertical, pointing down.
      EXPECT_LT(p.normal_world.y, -0.999f);
    }
  EXPECT_TRUE(found);
}

TEST_F(Cottage, DoorwayTimelineCrossesAtLeastFourDoorsInsideTheirPolygons) {
  const int t = world_->find_timeline("doorway");
  ASSERT_GE(t, 0);
  const Timeline& tl = world_->timelines[size_t(t)];
  EXPECT_GE(tl.fps, 30.0);
  EXPECT_LE(tl.fps, 60.0);
  EXPECT_DOUBLE_EQ(tl.fov_y_deg, 70.0);
  size_t crossings = 0;
  std::set<uint32_t> crossed;
  for (size_t k = 1; k < tl.keys.size(); ++k)
    for (uint32_t p = 0; p < world_->portals.size(); ++p) {
      const double margin = gen_test::portal_crossing_margin(world_->portals[p], glm::dvec3(tl.keys[k - 1].eye_world),
                                                             glm::dvec3(tl.keys[k].eye_world));
      if (margin < 0.0) continue;
      EXPECT_GT(margin, 0.3) << "crosses " << world_->portals[p].name << " near its edge";
      ++crossings;
      crossed.insert(p);
    }
  EXPECT_GE(crossings, 5u);  // five doors and the stairwell
  EXPECT_GE(crossed.size(), 5u);
}

}  // namespace
}  // namespace lintel
