// The cull pass on hand-made data with known answers: identity camera (clip = world, w = 1), so a
// box's NDC rect is its x/y extent. Covers group bases and capacities, the cell and region tests,
// the dispatch split, both append variants and capacity overflow -- all under validation.
#include <lintel/gpu/cull_pass.h>

#include "gpu_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace lintel::gpu {
namespace {

using test::HandScene;
using test::ids_by_group;
using test::ValidatedGpu;

Status cull(Context& ctx, const CullScene& scene, const CullFrame& frame, CullReadback& rb,
            CullPassOptions options = {}) {
  std::unique_ptr<CullPass> pass;
  if (Status s = CullPass::create(ctx, options, pass); !s) return s;
  if (Status s = pass->set_scene(scene); !s) return s;
  if (Status s = pass->set_frame(frame); !s) return s;
  return pass->run(&rb);
}

class CullPassTest : public ValidatedGpu {};

TEST_F(CullPassTest, CommandsCarryGroupBasesAndOnlyVisibleCellsSurvive) {
  HandScene h;
  h.scene.cell_count = 3;
  h.add_group(3);
  h.add_group(2);
  h.add_group(4);
  h.add(0, 0, 0.0f, 0.0f);                // 0: visible
  h.add(1, 0, 0.5f, 0.5f);                // 1: cell 1 not visible
  h.add(0, 1, -0.5f, 0.2f);               // 2: visible
  h.add(2, 2, 0.3f, -0.3f);               // 3: visible
  h.add(0, 2, 3.0f, 0.0f);                // 4: right of the frustum
  h.add(2, 2, 0.0f, 0.0f, 0.01f, -0.5f);  // 5: behind the near plane (z < 0)
  h.add(0, 0, 0.1f, 0.1f);                // 6: visible
  h.add(0, 1, 0.0f, 0.0f, 0.01f, 2.0f);   // 7: beyond the far plane
  CullFrame frame;
  frame.clear(3, glm::dmat4(1.0));
  frame.add_region(0, {-1, -1, 1, 1}, {});
  frame.add_region(2, {-1, -1, 1, 1}, {});
  CullReadback rb;
  ASSERT_TRUE(cull(ctx(), h.scene, frame, rb).ok());
  ASSERT_EQ(rb.commands.size(), 3u);
  EXPECT_EQ(rb.commands[0].first_instance, 0u);
  EXPECT_EQ(rb.commands[1].first_instance, 3u);
  EXPECT_EQ(rb.commands[2].first_instance, 5u);
  for (const DrawIndexedCommand& c : rb.commands) EXPECT_EQ(c.index_count, 36u);
  auto ids = ids_by_group(rb);
  EXPECT_EQ(ids[0], (std::vector<uint32_t>{0, 6}));
  EXPECT_EQ(ids[1], (std::vector<uint32_t>{2}));
  EXPECT_EQ(ids[2], (std::vector<uint32_t>{3}));
  EXPECT_EQ(rb.stats.visible_instances, 4u);
  EXPECT_EQ(rb.stats.draw_count, 3u);
  EXPECT_EQ(rb.stats.overflow_instances, 0u);
}

TEST_F(CullPassTest, RegionRectAndPolygonsCull) {
  HandScene h;
  h.scene.cell_count = 2;
  h.add_group(8);
  h.add(0, 0, -0.5f, 0.0f);         // 0: left half: in cell 0's rect
  h.add(0, 0, 0.5f, 0.0f);          // 1: right half: outside cell 0's rect
  h.add(1, 0, 0.2f, 0.2f);          // 2: inside cell 1's triangle
  h.add(1, 0, 0.8f, 0.8f);          // 3: in cell 1's rect, beyond the triangle's hypotenuse
  h.add(1, 0, -0.8f, -0.8f);        // 4: inside the second polygon (a small square)
  h.add(1, 0, -0.8f, 0.8f);         // 5: in the rect, in neither polygon
  h.add(0, 0, 0.0f, 0.0f, 0.005f);  // 6: straddles cell 0's rect edge at x = 0
  CullFrame frame;
  frame.clear(2, glm::dmat4(1.0));
  frame.add_region(0, {-1, -1, 0, 1}, {});
  std::vector<std::vector<glm::vec2>> polys = {{{0, 0}, {1, 0}, {0, 1}},
                                               {{-0.9f, -0.9f}, {-0.7f, -0.9f}, {-0.7f, -0.7f}, {-0.9f, -0.7f}}};
  frame.add_region(1, {-1, -1, 1, 1}, polys);
  CullReadback rb;
  ASSERT_TRUE(cull(ctx(), h.scene, frame, rb).ok());
  EXPECT_EQ(ids_by_group(rb)[0], (std::vector<uint32_t>{0, 2, 4, 6}));
}

TEST_F(CullPassTest, RegionOverPolygonLimitFallsBackToItsRect) {
  HandScene h;
  h.scene.cell_count = 1;
  h.add_group(2);
  h.add(0, 0, 0.5f, 0.5f);  // outside every (tiny) polygon, inside the rect
  CullFrame frame;
  frame.clear(1, glm::dmat4(1.0));
  std::vector<std::vector<glm::vec2>> polys(kMaxRegionPolygons + 1, {{-0.9f, -0.9f}, {-0.8f, -0.9f}, {-0.8f, -0.8f}});
  frame.add_region(0, {-1, -1, 1, 1}, polys);
  EXPECT_EQ(frame.rect_fallbacks, 1u);
  CullReadback rb;
  ASSERT_TRUE(cull(ctx(), h.scene, frame, rb).ok());
  EXPECT_EQ(rb.commands[0].instance_count, 1u) << "conservative: the rect alone keeps it";
  polys.resize(kMaxRegionPolygons);
  frame.clear(1, glm::dmat4(1.0));
  frame.add_region(0, {-1, -1, 1, 1}, polys);
  EXPECT_EQ(frame.rect_fallbacks, 0u);
  ASSERT_TRUE(cull(ctx(), h.scene, frame, rb).ok());
  EXPECT_EQ(rb.commands[0].instance_count, 0u);
}

// Many instances over many groups, every variant (dispatch split, aggregation on/off) gives the
// same id sets. 300 to 2,000 of the 5,000 boxes survive (checked below), so subgroups with few
// survivors (one atomic each) and with many (the per-group ballot loop) both occur in the
// subgroup append.
TEST_F(CullPassTest, DispatchSplitAndAppendVariantsAgree) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> pos(-1.5f, 1.5f);
  std::uniform_int_distribution<uint32_t> cell(0, 9), group(0, 40);
  HandScene h;
  h.scene.cell_count = 10;
  std::vector<uint32_t> group_of(5000);
  std::vector<uint32_t> per_group(41, 0);
  for (uint32_t& g : group_of) ++per_group[g = group(rng)];
  for (uint32_t n : per_group) h.add_group(n);
  for (uint32_t i = 0; i < group_of.size(); ++i) h.add(cell(rng), group_of[i], pos(rng), pos(rng), 0.02f);
  CullFrame frame;
  frame.clear(10, glm::dmat4(1.0));
  for (uint32_t c = 0; c < 10; c += 2) frame.add_region(c, {-0.8f, -0.6f, 0.7f, 0.9f}, {});

  CullReadback base;
  CullPassOptions plain;
  plain.append = CullAppend::Atomic;
  plain.sort_by_group = false;
  ASSERT_TRUE(cull(ctx(), h.scene, frame, base, plain).ok());
  EXPECT_GT(base.stats.visible_instances, 300u);
  EXPECT_LT(base.stats.visible_instances, 2000u);
  for (uint32_t per_dispatch : {64u, 320u, 4096u}) {
    for (CullAppend append : {CullAppend::Atomic, CullAppend::Subgroup, CullAppend::Workgroup}) {
      for (bool by_group : {false, true}) {
        for (CullStraddlers straddlers : {CullStraddlers::Inline, CullStraddlers::Deferred}) {
          CullPassOptions options;
          options.instances_per_dispatch = per_dispatch;
          options.append = append;
          options.sort_by_group = by_group;
          options.straddlers = straddlers;
          CullReadback rb;
          ASSERT_TRUE(cull(ctx(), h.scene, frame, rb, options).ok());
          EXPECT_EQ(ids_by_group(rb), ids_by_group(base))
              << per_dispatch << " per dispatch, append " << uint32_t(append) << ", by group " << by_group
              << ", straddlers " << uint32_t(straddlers);
        }
      }
    }
  }
}

// Capacity below the survivors: detected, reported, and nothing written outside the group's range.
TEST_F(CullPassTest, CapacityOverflowIsReportedAndStaysInBounds) {
  HandScene h;
  h.scene.cell_count = 1;
  h.add_group(2);  // 5 survivors, room for 2
  h.add_group(3);
  for (int i = 0; i < 5; ++i) h.add(0, 0, 0.1f * float(i), 0.0f);
  h.add(0, 1, 0.0f, 0.5f);
  CullFrame frame;
  frame.clear(1, glm::dmat4(1.0));
  frame.add_region(0, {-1, -1, 1, 1}, {});
  CullReadback rb;
  Status s = cull(ctx(), h.scene, frame, rb);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("overflow"), std::string::npos) << s.message();
  EXPECT_EQ(rb.stats.overflow_instances, 3u);
  EXPECT_EQ(rb.stats.overflow_groups, 1u);
  EXPECT_EQ(rb.commands[0].instance_count, 2u);
  EXPECT_EQ(ids_by_group(rb)[1], (std::vector<uint32_t>{5}));
  EXPECT_EQ(rb.instance_ids[2], 5u);
  EXPECT_EQ(rb.instance_ids[3], 0xffffffffu) << "the neighbour's unused slots stay untouched";
  EXPECT_EQ(rb.instance_ids[4], 0xffffffffu);
}

TEST_F(CullPassTest, BadSceneAndFrameDataAreStatuses) {
  std::unique_ptr<CullPass> pass;
  ASSERT_TRUE(CullPass::create(ctx(), {}, pass).ok());
  HandScene h;
  h.scene.cell_count = 1;
  h.add_group(2);
  h.add_group(2);
  h.scene.groups[1].base = 1;  // overlaps group 0
  Status s = pass->set_scene(h.scene);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("overlap"), std::string::npos) << s.message();
  h.scene.groups[1].base = 2;
  h.add(0, 5, 0, 0);  // group 5 does not exist
  s = pass->set_scene(h.scene);
  EXPECT_NE(s.message().find("draw group 5"), std::string::npos) << s.message();
  h.scene.instances.back().group = 1;
  ASSERT_TRUE(pass->set_scene(h.scene).ok());
  CullFrame frame;
  frame.clear(2, glm::dmat4(1.0));
  EXPECT_FALSE(pass->set_frame(frame).ok()) << "cell count mismatch";
  frame.clear(1, glm::dmat4(1.0));
  frame.cell_region[0] = 3;
  EXPECT_FALSE(pass->set_frame(frame).ok()) << "region index out of range";
}

TEST_F(CullPassTest, EmptySceneAndNoVisibleCellRun) {
  CullScene empty;
  CullFrame frame;
  frame.clear(0, glm::dmat4(1.0));
  CullReadback rb;
  ASSERT_TRUE(cull(ctx(), empty, frame, rb).ok());
  EXPECT_TRUE(rb.commands.empty());
  HandScene h;
  h.scene.cell_count = 1;
  h.add_group(1);
  h.add(0, 0, 0, 0);
  frame.clear(1, glm::dmat4(1.0));
  ASSERT_TRUE(cull(ctx(), h.scene, frame, rb).ok());
  EXPECT_EQ(rb.commands[0].instance_count, 0u);
  EXPECT_EQ(rb.stats.draw_count, 0u);
}

// One pass, many frames: buffers are reused and grow; results follow the frame.
TEST_F(CullPassTest, ReusedAcrossFrames) {
  HandScene h;
  h.scene.cell_count = 2;
  h.add_group(2);
  h.add(0, 0, 0, 0);
  h.add(1, 0, 0, 0);
  std::unique_ptr<CullPass> pass;
  ASSERT_TRUE(CullPass::create(ctx(), {}, pass).ok());
  ASSERT_TRUE(pass->set_scene(h.scene).ok());
  for (int f = 0; f < 6; ++f) {
    CullFrame frame;
    frame.clear(2, glm::dmat4(1.0));
    frame.add_region(uint32_t(f % 2), {-1, -1, 1, 1},
                     std::vector<std::vector<glm::vec2>>(size_t(f), {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}));
    ASSERT_TRUE(pass->set_frame(frame).ok());
    CullReadback rb;
    ASSERT_TRUE(pass->run(&rb).ok());
    ASSERT_EQ(rb.commands[0].instance_count, 1u);
    EXPECT_EQ(rb.group_ids(0)[0], uint32_t(f % 2));
  }
}

// The pass dispatches the ranges of the visible cells only (plus the loose range of instances
// reaching several cells): a frame's work follows what it sees, not the scene's size. Instances
// are listed with their cells interleaved (i % 20), so the pass's own cell order is what groups them.
TEST_F(CullPassTest, OnlyVisibleCellsAreDispatched) {
  constexpr uint32_t kCells = 20, kPerCell = 640;
  HandScene h;
  h.scene.cell_count = kCells;
  h.add_group(kCells * kPerCell + 5);
  for (uint32_t i = 0; i < kCells * kPerCell; ++i)
    h.add(i % kCells, 0, -0.9f + 1.8f * float(i / kCells) / kPerCell, 0.0f, 0.001f);
  std::unique_ptr<CullPass> pass;
  ASSERT_TRUE(CullPass::create(ctx(), {}, pass).ok());
  ASSERT_TRUE(pass->set_scene(h.scene).ok());
  for (uint32_t visible_cells : {0u, 1u, 3u}) {
    CullFrame frame;
    frame.clear(kCells, glm::dmat4(1.0));
    for (uint32_t k = 0; k < visible_cells; ++k) frame.add_region(7 * k + 2, {-1, -1, 1, 1}, {});
    ASSERT_TRUE(pass->set_frame(frame).ok());
    EXPECT_EQ(pass->work_items(), visible_cells * kPerCell / kCullWorkgroupSize) << visible_cells << " visible cells";
    CullReadback rb;
    ASSERT_TRUE(pass->run(&rb).ok());
    EXPECT_EQ(rb.stats.visible_instances, visible_cells * kPerCell);
    for (uint32_t id : rb.group_ids(0)) EXPECT_EQ((id % kCells - 2) % 7, 0u) << id;
  }

  // Five instances reaching cells 0 and 5: one more work item (the loose range), always dispatched.
  for (uint32_t k = 0; k < 5; ++k) {
    h.add(kCells - 1, 0, 0.1f * float(k), 0.5f);
    h.scene.instances.back().cell = kReachListBit | uint32_t(h.scene.reach.size());
    h.scene.reach.insert(h.scene.reach.end(), {2, 0, 5});
  }
  ASSERT_TRUE(pass->set_scene(h.scene).ok());
  CullFrame frame;
  frame.clear(kCells, glm::dmat4(1.0));
  frame.add_region(5, {-1, -1, 1, 1}, {});
  ASSERT_TRUE(pass->set_frame(frame).ok());
  EXPECT_EQ(pass->work_items(), kPerCell / kCullWorkgroupSize + 1);
  CullReadback rb;
  ASSERT_TRUE(pass->run(&rb).ok());
  EXPECT_EQ(rb.stats.visible_instances, kPerCell + 5);
}

}  // namespace
}  // namespace lintel::gpu
