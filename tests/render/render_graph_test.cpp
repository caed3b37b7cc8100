// The render graph's barriers, checked by synchronization validation on real commands (every
// validation message fails the test: tests/gpu_cull/gpu_test_support.h).
#include "gpu_test_support.h"
#include "render_graph.h"

#include <lintel/gpu/buffer.h>

#include <gtest/gtest.h>

#include <cstdint>

namespace lintel::render {
namespace {

using gpu::test::ValidatedGpu;

class RenderGraphTest : public ValidatedGpu {};

// Property: a read waits for the last write even when other reads, in other stages, came between
// them. Here a buffer is filled (transfer write), declared read as indirect arguments (a barrier
// to the draw-indirect stage only), then copied out (a transfer read): the copy needs its own
// barrier from the fill, or synchronization validation reports a read-after-write hazard. Two
// frames, so the next frame's fill also waits for the copy (write after read).
TEST_F(RenderGraphTest, ReadInANewStageAfterOtherReadsWaitsForTheWrite) {
  constexpr VkDeviceSize kBytes = 256;
  gpu::Buffer source, copy;
  ASSERT_TRUE(gpu::Buffer::create(ctx(), kBytes,
                                  VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                      VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                                  gpu::MemoryUse::Device, "graph test source", source)
                  .ok());
  ASSERT_TRUE(gpu::Buffer::create(ctx(), kBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Readback,
                                  "graph test copy", copy)
                  .ok());
  RenderGraph g;
  const ResourceId src = g.import_buffer("source", source.handle());
  const ResourceId dst = g.import_buffer("copy", copy.handle());
  uint32_t value = 0;
  g.add_pass("fill", {{src, Use::TransferDst}},
             [&](VkCommandBuffer cmd, uint32_t) { vkCmdFillBuffer(cmd, source.handle(), 0, kBytes, value); });
  g.add_pass("indirect arguments", {{src, Use::IndirectRead}}, [](VkCommandBuffer, uint32_t) {});
  g.add_pass("copy out", {{src, Use::TransferSrc}, {dst, Use::TransferDst}}, [&](VkCommandBuffer cmd, uint32_t) {
    const VkBufferCopy region{0, 0, kBytes};
    vkCmdCopyBuffer(cmd, source.handle(), copy.handle(), 1, &region);
  });
  ASSERT_TRUE(g.validate({}).ok());
  for (uint32_t frame = 1; frame <= 2; ++frame) {
    value = 0x1000u + frame;
    ASSERT_TRUE(ctx().submit_and_wait([&](VkCommandBuffer cmd) { g.record(cmd, {}); }, "graph test").ok());
    const auto* words = static_cast<const uint32_t*>(copy.mapped());
    EXPECT_EQ(words[0], value);
    EXPECT_EQ(words[kBytes / 4 - 1], value);
  }
}

}  // namespace
}  // namespace lintel::render
