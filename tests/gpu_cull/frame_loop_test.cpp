// The cull pass inside a game's frame loop, under validation with synchronization validation:
// N frames in flight recorded into the caller's command buffers and submitted back to back, the
// output barrier left to the caller, and moved instances updated without a scene re-upload. Each
// result is compared with the same frame culled alone by a fresh single-slot pass.
#include <lintel/gpu/cull_pass.h>

#include "gpu_test_support.h"

#include <gtest/gtest.h>

#include <random>

#include <algorithm>
#include <vector>

namespace lintel::gpu {
namespace {

using test::HandScene;
using test::ValidatedGpu;
// Per group, the ids drawn, sorted (the append order is unspecified).
constexpr auto drawn = test::ids_by_group;

// The frame culled alone: a fresh pass, one slot, one-shot run().
std::vector<std::vector<uint32_t>> alone(Context& ctx, const CullScene& scene, const CullFrame& frame) {
  std::unique_ptr<CullPass> pass;
  CullReadback rb;
  EXPECT_TRUE(CullPass::create(ctx, {}, pass).ok());
  EXPECT_TRUE(pass->set_scene(scene).ok());
  EXPECT_TRUE(pass->set_frame(frame).ok());
  EXPECT_TRUE(pass->run(&rb).ok());
  return drawn(rb);
}

// Three cells, two groups, instances spread over the NDC square.
HandScene three_cells() {
  HandScene h;
  h.scene.cell_count = 3;
  h.add_group(6);
  h.add_group(4);
  h.add(0, 0, -0.5f, -0.5f);  // 0
  h.add(0, 1, 0.5f, 0.5f);    // 1
  h.add(1, 0, -0.5f, 0.5f);   // 2
  h.add(1, 1, 0.5f, -0.5f);   // 3
  h.add(2, 0, 0.1f, 0.1f);    // 4
  h.add(2, 0, -0.8f, -0.8f);  // 5
  h.add(2, 1, 0.8f, 0.8f);    // 6
  h.add(0, 0, 0.0f, 0.0f);    // 7
  return h;
}

// Frames that draw different subsets of three_cells().
std::vector<CullFrame> distinct_frames() {
  std::vector<CullFrame> frames(3);
  frames[0].clear(3, glm::dmat4(1.0));
  frames[0].add_region(0, {-1, -1, 1, 1}, {});
  frames[0].add_region(1, {-1, 0, 0, 1}, {});
  frames[1].clear(3, glm::dmat4(1.0));
  frames[1].add_region(2, {-1, -1, 1, 1}, std::vector<std::vector<glm::vec2>>{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}});
  frames[2].clear(3, glm::dmat4(1.0));
  frames[2].add_region(1, {0, -1, 1, 0}, {});
  frames[2].add_region(2, {-1, -1, 0, 0}, {});
  return frames;
}

// What a game owns: a command pool, one command buffer and one fence per slot.
class GameFrames {
 public:
  GameFrames(Context& ctx, uint32_t slots) : ctx_(ctx), cmds_(slots), fences_(slots) {
    VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool_info.queueFamilyIndex = ctx.queue_family();
    EXPECT_EQ(vkCreateCommandPool(ctx.device(), &pool_info, nullptr, &pool_), VK_SUCCESS);
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool_;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = slots;
    EXPECT_EQ(vkAllocateCommandBuffers(ctx.device(), &alloc, cmds_.data()), VK_SUCCESS);
    VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fence_info.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    for (VkFence& f : fences_) EXPECT_EQ(vkCreateFence(ctx.device(), &fence_info, nullptr, &f), VK_SUCCESS);
  }
  ~GameFrames() {
    vkDeviceWaitIdle(ctx_.device());
    for (VkFence f : fences_) vkDestroyFence(ctx_.device(), f, nullptr);
    vkDestroyCommandPool(ctx_.device(), pool_, nullptr);
  }
  // Waits until the slot's previous submission finished; returns its command buffer, begun.
  VkCommandBuffer begin(uint32_t slot) {
    wait(slot);
    vkResetFences(ctx_.device(), 1, &fences_[slot]);
    vkResetCommandBuffer(cmds_[slot], 0);
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(cmds_[slot], &begin);
    return cmds_[slot];
  }
  // Ends and submits the slot's command buffer; does not wait.
  void submit(uint32_t slot) {
    ASSERT_EQ(vkEndCommandBuffer(cmds_[slot]), VK_SUCCESS);
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmds_[slot];
    ASSERT_EQ(vkQueueSubmit(ctx_.queue(), 1, &submit, fences_[slot]), VK_SUCCESS);
  }
  void wait(uint32_t slot) {
    ASSERT_EQ(vkWaitForFences(ctx_.device(), 1, &fences_[slot], VK_TRUE, 60ull * 1000 * 1000 * 1000), VK_SUCCESS);
  }

 private:
  Context& ctx_;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  std::vector<VkCommandBuffer> cmds_;
  std::vector<VkFence> fences_;
};

class FrameLoopTest : public ValidatedGpu {};

// Property: with two slots, frames recorded into two command buffers and submitted back to back
// (no wait between them) each give exactly the result of the same frame culled alone; sync
// validation sees no hazard on the shared outputs.
TEST_F(FrameLoopTest, TwoFramesInFlightEachEqualTheFrameAlone) {
  const HandScene h = three_cells();
  const std::vector<CullFrame> frames = distinct_frames();
  std::vector<std::vector<std::vector<uint32_t>>> expected;
  for (const CullFrame& f : frames) expected.push_back(alone(ctx(), h.scene, f));
  ASSERT_NE(expected[0], expected[1]);
  ASSERT_NE(expected[1], expected[2]);

  CullPassOptions options;
  options.frames_in_flight = 2;
  std::unique_ptr<CullPass> pass;
  ASSERT_TRUE(CullPass::create(ctx(), options, pass).ok());
  ASSERT_TRUE(pass->set_scene(h.scene).ok());
  GameFrames game(ctx(), 2);
  std::vector<size_t> frame_in_slot(2, SIZE_MAX);
  auto check_slot = [&](uint32_t slot) {
    if (frame_in_slot[slot] == SIZE_MAX) return;
    game.wait(slot);
    CullReadback rb;
    ASSERT_TRUE(pass->read_back(slot, false, rb).ok());
    EXPECT_EQ(drawn(rb), expected[frame_in_slot[slot]]) << "frame " << frame_in_slot[slot] << " in slot " << slot;
  };
  for (size_t k = 0; k < 7; ++k) {
    const uint32_t slot = uint32_t(k % 2);
    check_slot(slot);  // the game's fence wait before it reuses the slot
    const size_t f = (k * 2) % frames.size();
    ASSERT_TRUE(pass->set_frame(frames[f], slot).ok());
    VkCommandBuffer cmd = game.begin(slot);
    pass->record(cmd, slot);
    pass->record_readback(cmd, slot, false);
    game.submit(slot);
    frame_in_slot[slot] = f;
  }
  check_slot(0);
  check_slot(1);
}

// The same two frames recorded back to back into ONE command buffer: synchronization validation
// 1.3.239 checks hazards within a command buffer but not across submissions, so this is where it
// proves that record()'s leading barrier orders frame k+1's writes to the shared outputs after
// frame k's reads (its readback copies here). Lavapipe runs barriers as full waits, so the results
// alone could not show a missing one.
TEST_F(FrameLoopTest, TwoFramesInOneCommandBufferNeedNoWaitBetween) {
  const HandScene h = three_cells();
  const std::vector<CullFrame> frames = distinct_frames();
  CullPassOptions options;
  options.frames_in_flight = 2;
  std::unique_ptr<CullPass> pass;
  ASSERT_TRUE(CullPass::create(ctx(), options, pass).ok());
  ASSERT_TRUE(pass->set_scene(h.scene).ok());
  ASSERT_TRUE(pass->set_frame(frames[0], 0).ok());
  ASSERT_TRUE(pass->set_frame(frames[1], 1).ok());
  GameFrames game(ctx(), 1);
  VkCommandBuffer cmd = game.begin(0);
  for (uint32_t slot = 0; slot < 2; ++slot) {
    pass->record(cmd, slot);
    pass->record_readback(cmd, slot, false);
  }
  game.submit(0);
  game.wait(0);
  for (uint32_t slot = 0; slot < 2; ++slot) {
    CullReadback rb;
    ASSERT_TRUE(pass->read_back(slot, false, rb).ok());
    EXPECT_EQ(drawn(rb), alone(ctx(), h.scene, frames[slot])) << "slot " << slot;
  }
}

// With output_barrier = false the pass leaves the compute -> indirect/vertex barrier to the
// caller; placing output_barrier_info()'s barrier gives the same result, validation clean.
TEST_F(FrameLoopTest, OutputBarrierLeftToTheCaller) {
  const HandScene h = three_cells();
  const CullFrame frame = distinct_frames()[0];
  CullPassOptions options;
  options.output_barrier = false;
  std::unique_ptr<CullPass> pass;
  ASSERT_TRUE(CullPass::create(ctx(), options, pass).ok());
  ASSERT_TRUE(pass->set_scene(h.scene).ok());
  ASSERT_TRUE(pass->set_frame(frame).ok());
  const CullOutputBarrier info = pass->output_barrier_info();
  EXPECT_EQ(info.buffers[0], pass->draw_commands());
  EXPECT_EQ(info.buffers[1], pass->compact_commands());
  EXPECT_EQ(info.buffers[2], pass->compact_groups());
  EXPECT_EQ(info.buffers[3], pass->counters());
  EXPECT_EQ(info.buffers[4], pass->instance_ids());
  EXPECT_TRUE(info.dst_stage & VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT);
  EXPECT_TRUE(info.dst_access & VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);

  GameFrames game(ctx(), 1);
  VkCommandBuffer cmd = game.begin(0);
  pass->record(cmd, 0);
  const VkMemoryBarrier2 mb = info.memory_barrier();  // the render graph's barrier
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.memoryBarrierCount = 1;
  dep.pMemoryBarriers = &mb;
  vkCmdPipelineBarrier2(cmd, &dep);
  pass->record_readback(cmd, 0, false);
  game.submit(0);
  game.wait(0);
  CullReadback rb;
  ASSERT_TRUE(pass->read_back(0, false, rb).ok());
  EXPECT_EQ(drawn(rb), alone(ctx(), h.scene, frame));
}

// Property: after update_instances(moved ids, re-packed scene), the pass culls exactly as a fresh
// pass given the re-packed scene by set_scene -- including an instance that moved into another
// cell, one that left the frustum, one that now reaches a second cell (a new reach list), and an
// instance staged twice before one record (the later record wins).
TEST_F(FrameLoopTest, UpdatedInstancesCullAsAFreshScene) {
  HandScene h = three_cells();
  CullFrame frame;
  frame.clear(3, glm::dmat4(1.0));
  frame.add_region(0, {-1, -1, 1, 1}, {});
  CullPassOptions options;
  options.frames_in_flight = 2;
  std::unique_ptr<CullPass> pass;
  ASSERT_TRUE(CullPass::create(ctx(), options, pass).ok());
  ASSERT_TRUE(pass->set_scene(h.scene).ok());
  ASSERT_TRUE(pass->set_frame(frame, 0).ok());
  CullReadback before;
  ASSERT_TRUE(pass->run(&before).ok());
  ASSERT_EQ(drawn(before), alone(ctx(), h.scene, frame));

  HandScene moved = h;
  GpuInstance& to_cell0 = moved.scene.instances[2];  // cell 1 -> cell 0: now drawn
  to_cell0.cell = 0;
  GpuInstance& out_of_view = moved.scene.instances[7];  // leaves the frustum: no longer drawn
  out_of_view.bounds_min_world.x += 5.0f;
  out_of_view.bounds_max_world.x += 5.0f;
  moved.scene.reach = {2, 2, 0};  // instance 4 (cell 2) now reaches cell 0 too: drawn
  moved.scene.instances[4].cell = kReachListBit | 0u;
  const uint32_t first[] = {2, 7};
  ASSERT_TRUE(pass->update_instances(first, h.scene, 0).ok());  // stale positions, overwritten below
  const uint32_t ids[] = {2, 7, 4, 2};
  ASSERT_TRUE(pass->update_instances(ids, moved.scene, 0).ok());
  CullReadback after;
  ASSERT_TRUE(pass->run(&after).ok());
  const auto expected = alone(ctx(), moved.scene, frame);
  EXPECT_NE(expected, drawn(before));
  EXPECT_EQ(drawn(after), expected);

  // Through the other slot, in the frame loop: moved back, recorded into slot 1.
  const uint32_t back[] = {2, 4, 7};
  ASSERT_TRUE(pass->update_instances(back, h.scene, 1).ok());
  ASSERT_TRUE(pass->set_frame(frame, 1).ok());
  GameFrames game(ctx(), 2);
  VkCommandBuffer cmd = game.begin(1);
  pass->record(cmd, 1);
  pass->record_readback(cmd, 1, false);
  game.submit(1);
  game.wait(1);
  CullReadback back_rb;
  ASSERT_TRUE(pass->read_back(1, false, back_rb).ok());
  EXPECT_EQ(drawn(back_rb), drawn(before));
}

// Property: after any sequence of moves between cells (out of the range an instance was uploaded
// in, into reach lists, and back home), with several visible cells and several dispatch windows,
// the pass draws exactly what a fresh set_scene of the moved scene draws: every moved instance
// once, none twice (its home range and the moved list never both test it).
TEST_F(FrameLoopTest, InstancesMovedBetweenCellsDrawnExactlyOnce) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> pos(-0.9f, 0.9f);
  HandScene h;
  h.scene.cell_count = 4;
  h.add_group(150);
  h.add_group(150);
  for (uint32_t i = 0; i < 300; ++i) h.add(rng() % 4, i % 2, pos(rng), pos(rng));
  h.scene.reach = {2, 1, 3};
  CullFrame frame;
  frame.clear(4, glm::dmat4(1.0));
  frame.add_region(0, {-1, -1, 1, 1}, {});
  frame.add_region(1, {-1, -1, 0.5f, 1}, {});
  frame.add_region(3, {-0.5f, -1, 1, 1}, {});
  CullPassOptions options;
  options.instances_per_dispatch = 64;  // five windows
  std::unique_ptr<CullPass> pass;
  ASSERT_TRUE(CullPass::create(ctx(), options, pass).ok());
  ASSERT_TRUE(pass->set_scene(h.scene).ok());
  HandScene moved = h;
  for (int round = 0; round < 3; ++round) {
    std::vector<uint32_t> ids;
    for (int k = 0; k < 40; ++k) {
      const uint32_t id = rng() % 300;
      const uint32_t to = rng() % 6;  // 0..3: a cell (often its first one again), 4: reach list, 5: home
      moved.scene.instances[id].cell = to < 4 ? to : to == 4 ? (kReachListBit | 0u) : h.scene.instances[id].cell;
      ids.push_back(id);
    }
    ASSERT_TRUE(pass->update_instances(ids, moved.scene).ok());
    ASSERT_TRUE(pass->set_frame(frame).ok());
    CullReadback rb;
    ASSERT_TRUE(pass->run(&rb).ok());
    EXPECT_EQ(drawn(rb), alone(ctx(), moved.scene, frame)) << "round " << round;
  }
}

TEST_F(FrameLoopTest, BadUpdatesAreStatusesAndSpareReachRoomRunsOut) {
  HandScene h = three_cells();
  std::unique_ptr<CullPass> pass;
  ASSERT_TRUE(CullPass::create(ctx(), {}, pass).ok());
  ASSERT_TRUE(pass->set_scene(h.scene).ok());
  const uint32_t out_of_range[] = {8};
  EXPECT_EQ(pass->update_instances(out_of_range, h.scene).kind(), StatusKind::BadInput);
  HandScene other = h;
  other.add(0, 0, 0, 0);
  const uint32_t one[] = {0};
  EXPECT_EQ(pass->update_instances(one, other.scene).kind(), StatusKind::BadInput);
  HandScene bad_reach = h;
  bad_reach.scene.instances[0].cell = kReachListBit | 5u;  // past the (empty) reach list
  EXPECT_EQ(pass->update_instances(one, bad_reach.scene).kind(), StatusKind::BadInput);

  // An instance that keeps moving while it reaches many cells uses the spare room up; the pass
  // says so instead of writing past it, and set_scene starts afresh.
  HandScene wide = h;
  wide.scene.cell_count = kMaxReachCells;
  wide.scene.reach.assign(1, kMaxReachCells);
  for (uint32_t c = 0; c < kMaxReachCells; ++c) wide.scene.reach.push_back(c);
  wide.scene.instances[0].cell = kReachListBit | 0u;
  ASSERT_TRUE(pass->set_scene(wide.scene).ok());
  const uint32_t fits = kReachSpareEntries / (kMaxReachCells + 1);
  for (uint32_t i = 0; i < fits; ++i) ASSERT_TRUE(pass->update_instances(one, wide.scene).ok()) << i;
  EXPECT_EQ(pass->update_instances(one, wide.scene).kind(), StatusKind::Unsupported);
  ASSERT_TRUE(pass->set_scene(wide.scene).ok());
  EXPECT_TRUE(pass->update_instances(one, wide.scene).ok());
}

}  // namespace
}  // namespace lintel::gpu
