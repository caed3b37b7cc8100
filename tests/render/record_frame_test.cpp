// The renderer inside a caller's frame loop (Renderer::record_frame), under the Khronos
// validation layers with synchronization validation and GPU-AV (any message fails the test).
//
// Property (frames in flight): with RenderOptions::frames_in_flight = 2, two frames of different
// views recorded into two command buffers on slots 0 and 1 — both recorded before either is
// submitted, so the host writes of slot 1 happen while slot 0's are pending — and submitted back
// to back without a wait in between, each produce exactly the image that Renderer::render() with
// one frame in flight makes of the same view (lavapipe is deterministic for a frame that depends
// only on its view: gi_persist off). The caller reads the final image itself, as an engine would
// (Renderer::image), after the frame it belongs to.
//
// Property (g-buffer only): a renderer with RenderPasses::GBuffer records only the cull and the
// g-buffer, and its cell-id image equals the full renderer's read-back cell ids for the same view.
// About 10 s on the 2-core lavapipe machine.
#include "render_test_support.h"

#include <lintel/gpu/buffer.h>
#include "vk_status.h"
#include <lintel/visibility_builder.h>

#include <gtest/gtest.h>

#include <cstring>

namespace lintel::render::test {
namespace {

constexpr uint32_t kWidth = 160, kHeight = 90;
constexpr uint32_t kFrames[2] = {150, 258};  // the golden test's hall and kitchen views

// A command pool and buffers of the test's own, as an engine has.
struct CommandBuffers {
  VkDevice device = VK_NULL_HANDLE;
  VkCommandPool pool = VK_NULL_HANDLE;
  std::vector<VkCommandBuffer> buffers;
  ~CommandBuffers() {
    if (pool) vkDestroyCommandPool(device, pool, nullptr);
  }
};

void make_command_buffers(gpu::Context& ctx, uint32_t count, CommandBuffers& out) {
  out.device = ctx.device();
  VkCommandPoolCreateInfo pi{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pi.queueFamilyIndex = ctx.queue_family();
  ASSERT_EQ(vkCreateCommandPool(ctx.device(), &pi, nullptr, &out.pool), VK_SUCCESS);
  out.buffers.resize(count);
  VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  ai.commandPool = out.pool;
  ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  ai.commandBufferCount = count;
  ASSERT_EQ(vkAllocateCommandBuffers(ctx.device(), &ai, out.buffers.data()), VK_SUCCESS);
}

// Records a copy of `image` (in the state the frame left it) into `dst`, visible to the host.
void record_copy_out(VkCommandBuffer cmd, const ImageAccess& image, VkImageAspectFlags aspect, VkBuffer dst) {
  VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  b.srcStageMask = image.stage;
  b.srcAccessMask = image.access;
  b.dstStageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
  b.dstAccessMask = VK_ACCESS_2_TRANSFER_READ_BIT;
  b.oldLayout = image.layout;
  b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image.image;
  b.subresourceRange = {aspect, 0, 1, 0, 1};
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.imageMemoryBarrierCount = 1;
  dep.pImageMemoryBarriers = &b;
  vkCmdPipelineBarrier2(cmd, &dep);
  VkBufferImageCopy copy{};
  copy.imageSubresource = {aspect, 0, 0, 1};
  copy.imageExtent = {image.width, image.height, 1};
  vkCmdCopyImageToBuffer(cmd, image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst, 1, &copy);
  VkMemoryBarrier2 host{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  host.srcStageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
  host.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  host.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
  host.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
  VkDependencyInfo to_host{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  to_host.memoryBarrierCount = 1;
  to_host.pMemoryBarriers = &host;
  vkCmdPipelineBarrier2(cmd, &to_host);
}

class RecordFrameTest : public ValidatedGpu {
 protected:
  void SetUp() override {
    ValidatedGpu::SetUp();
    ASSERT_TRUE(load_committed_scene("cottage.gltf", world_));
    const int walk = world_.find_timeline("doorway");
    ASSERT_GE(walk, 0);
    frames_ = timeline_frames(world_, world_.timelines[size_t(walk)], 1);
    ASSERT_GT(frames_.size(), kFrames[1]);
  }
  // The caller's visibility, built as render() builds it.
  VisibleSet visible_for(const TimelineFrame& f) {
    VisibleSet vs;
    VisibilityOptions vo;
    vo.cull_instances = false;
    const Status s = builder_.build(world_, f.view, f.start_cell, vo, vs);
    EXPECT_TRUE(s.ok()) << s.message();
    return vs;
  }

  World world_;
  std::vector<TimelineFrame> frames_;
  VisibilityBuilder builder_;
};

TEST_F(RecordFrameTest, TwoFramesInFlightMatchOneFrameRenders) {
  const RenderOptions one = test_options(kWidth, kHeight);
  std::unique_ptr<Renderer> reference = make_renderer(ctx(), world_, one);
  ASSERT_NE(reference, nullptr);
  std::vector<uint8_t> expected[2];
  for (int i = 0; i < 2; ++i) {
    RenderedFrame f;
    const TimelineFrame& tf = frames_[kFrames[i]];
    const Status s = reference->render(tf.view, tf.start_cell, f);
    ASSERT_TRUE(s.ok()) << s.message();
    expected[i] = std::move(f.rgba8);
  }
  ASSERT_NE(expected[0], expected[1]) << "the two views must differ, or the test proves nothing";

  // With two-phase occlusion too (CameraCull::PortalHiz): its buffers are shared by the slots and
  // ordered by submission; the images are the portal cull's.
  for (const CameraCull cull : {CameraCull::Portal, CameraCull::PortalHiz}) {
    SCOPED_TRACE(cull == CameraCull::Portal ? "portal" : "portal+hiz");
    RenderOptions two = one;
    two.camera_cull = cull;
    two.frames_in_flight = 2;
    std::unique_ptr<Renderer> renderer = make_renderer(ctx(), world_, two);
    ASSERT_NE(renderer, nullptr);
    ImageAccess final_image;
    ASSERT_TRUE(renderer->image(RenderImage::Final, final_image).ok());
    CommandBuffers cmds;
    make_command_buffers(ctx(), 2, cmds);
    gpu::Buffer readback[2];
    const VkDeviceSize bytes = VkDeviceSize(kWidth) * kHeight * 4;
    for (auto& b : readback)
      ASSERT_TRUE(gpu::Buffer::create(ctx(), bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Readback,
                                      "test readback", b)
                      .ok());

    // Both frames recorded before either is submitted.
    for (uint32_t slot = 0; slot < 2; ++slot) {
      const TimelineFrame& tf = frames_[kFrames[slot]];
      const VisibleSet vs = visible_for(tf);
      VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
      bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
      ASSERT_EQ(vkBeginCommandBuffer(cmds.buffers[slot], &bi), VK_SUCCESS);
      const Status s = renderer->record_frame(cmds.buffers[slot], vs, tf.view, slot);
      ASSERT_TRUE(s.ok()) << s.message();
      record_copy_out(cmds.buffers[slot], final_image, VK_IMAGE_ASPECT_COLOR_BIT, readback[slot].handle());
      ASSERT_EQ(vkEndCommandBuffer(cmds.buffers[slot]), VK_SUCCESS);
    }
    // Back to back, one fence at the end.
    VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence = VK_NULL_HANDLE;
    ASSERT_EQ(vkCreateFence(ctx().device(), &fi, nullptr, &fence), VK_SUCCESS);
    for (uint32_t slot = 0; slot < 2; ++slot) {
      VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
      si.commandBufferCount = 1;
      si.pCommandBuffers = &cmds.buffers[slot];
      EXPECT_EQ(vkQueueSubmit(ctx().queue(), 1, &si, slot == 1 ? fence : VK_NULL_HANDLE), VK_SUCCESS);
    }
    EXPECT_EQ(vkWaitForFences(ctx().device(), 1, &fence, VK_TRUE, UINT64_MAX), VK_SUCCESS);
    vkDestroyFence(ctx().device(), fence, nullptr);

    for (int i = 0; i < 2; ++i) {
      const auto* got = static_cast<const uint8_t*>(readback[i].mapped());
      size_t differing = 0;
      for (size_t p = 0; p < expected[i].size(); ++p) differing += got[p] != expected[i][p];
      EXPECT_EQ(differing, 0u) << "frame " << kFrames[i] << " (slot " << i << "): " << differing
                               << " bytes differ from the one-frame-in-flight render";
    }
  }
}

TEST_F(RecordFrameTest, GBufferOnlyMatchesTheFullRenderersCells) {
  const TimelineFrame& tf = frames_[kFrames[0]];
  RenderOptions full = test_options(kWidth, kHeight);
  full.readback_cells = true;
  std::unique_ptr<Renderer> reference = make_renderer(ctx(), world_, full);
  ASSERT_NE(reference, nullptr);
  RenderedFrame expected;
  ASSERT_TRUE(reference->render(tf.view, tf.start_cell, expected).ok());

  RenderOptions gbuffer_only = test_options(kWidth, kHeight);
  gbuffer_only.passes = RenderPasses::GBuffer;
  std::unique_ptr<Renderer> renderer = make_renderer(ctx(), world_, gbuffer_only);
  ASSERT_NE(renderer, nullptr);
  EXPECT_EQ(renderer->describe_graph(),
            "cull: draw commands(copy+write) instance ids(copy+write) draw count(copy+write)\n"
            "g-buffer: draw commands(indirect) instance ids(vertex) albedo(color) "
            "normal(color) cell(color) depth(depth) emission(color)\n");
  ImageAccess cells, final_image;
  ASSERT_TRUE(renderer->image(RenderImage::Cell, cells).ok());
  EXPECT_EQ(cells.format, VK_FORMAT_R32_UINT);
  EXPECT_EQ(cells.layout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  ImageAccess emission;
  ASSERT_TRUE(renderer->image(RenderImage::Emission, emission).ok());
  EXPECT_EQ(emission.format, VK_FORMAT_R16G16B16A16_SFLOAT);
  EXPECT_EQ(emission.layout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  EXPECT_FALSE(renderer->image(RenderImage::Final, final_image).ok()) << "a g-buffer-only renderer has no final image";
  RenderedFrame unused;
  EXPECT_EQ(renderer->render(tf.view, tf.start_cell, unused).kind(), StatusKind::BadInput);

  gpu::Buffer readback;
  ASSERT_TRUE(gpu::Buffer::create(ctx(), VkDeviceSize(kWidth) * kHeight * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                  gpu::MemoryUse::Readback, "test readback", readback)
                  .ok());
  const VisibleSet vs = visible_for(tf);
  const Status s = ctx().submit_and_wait(
      [&](VkCommandBuffer cmd) {
        const Status r = renderer->record_frame(cmd, vs, tf.view, 0);
        EXPECT_TRUE(r.ok()) << r.message();
        record_copy_out(cmd, cells, VK_IMAGE_ASPECT_COLOR_BIT, readback.handle());
      },
      "g-buffer only");
  ASSERT_TRUE(s.ok()) << s.message();
  ASSERT_EQ(expected.cell_ids.size(), size_t(kWidth) * kHeight);
  EXPECT_EQ(std::memcmp(readback.mapped(), expected.cell_ids.data(), expected.cell_ids.size() * 4), 0)
      << "the g-buffer-only renderer's cells differ from the full renderer's";
}

TEST_F(RecordFrameTest, BadSlotAndForeignVisibleSetAreBadInput) {
  std::unique_ptr<Renderer> renderer = make_renderer(ctx(), world_, test_options(kWidth, kHeight));
  ASSERT_NE(renderer, nullptr);
  const TimelineFrame& tf = frames_[kFrames[0]];
  const VisibleSet vs = visible_for(tf);
  VisibleSet foreign = vs;
  foreign.slot_of_cell.push_back(-1);  // one cell more than the world has
  const Status s = ctx().submit_and_wait(
      [&](VkCommandBuffer cmd) {
        EXPECT_EQ(renderer->record_frame(cmd, vs, tf.view, 1).kind(), StatusKind::BadInput);
        EXPECT_EQ(renderer->record_frame(cmd, foreign, tf.view, 0).kind(), StatusKind::BadInput);
      },
      "nothing recorded");
  ASSERT_TRUE(s.ok()) << s.message();
}

}  // namespace
}  // namespace lintel::render::test
