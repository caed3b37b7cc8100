// gpu::Allocator: a caller's allocator sees every allocation Lintel's buffers make and gets every
// one back, whether passed in ContextOptions or set on a context later; without one the default
// (DedicatedAllocator) is used.
#include <lintel/gpu/allocator.h>
#include <lintel/gpu/buffer.h>
#include <lintel/gpu/cull_pass.h>

#include "gpu_test_support.h"

#include <gtest/gtest.h>

#include <map>

namespace lintel::gpu {
namespace {

using test::HandScene;
using test::ValidatedGpu;

// A game's allocator stand-in: forwards to the default and counts, keyed by VkDeviceMemory.
class CountingAllocator final : public Allocator {
 public:
  explicit CountingAllocator(const Context& ctx) : inner_(ctx) {}
  Status allocate(const VkMemoryRequirements& requirements, VkMemoryPropertyFlags required,
                  VkMemoryPropertyFlags preferred, const char* label, MemoryBlock& out) override {
    if (Status s = inner_.allocate(requirements, required, preferred, label, out); !s) return s;
    out.user = ++allocations;  // Lintel must hand it back unchanged
    live[out.memory] = out.user;
    return {};
  }
  void free(const MemoryBlock& block) override {
    ++frees;
    auto it = live.find(block.memory);
    if (it == live.end() || it->second != block.user)
      ++unknown_frees;
    else
      live.erase(it);
    inner_.free(block);
  }
  uint64_t allocations = 0, frees = 0, unknown_frees = 0;
  std::map<VkDeviceMemory, uint64_t> live;

 private:
  DedicatedAllocator inner_;
};

class AllocatorTest : public ValidatedGpu {};

// Every buffer of a cull pass (scene, outputs, frame staging of both slots, readback, instance
// updates) comes from the caller's allocator, and all of it is given back when the pass goes.
TEST_F(AllocatorTest, CountingAllocatorSeesEveryAllocationAndFree) {
  CountingAllocator counting(ctx());
  ctx().set_allocator(&counting);
  HandScene h;
  h.scene.cell_count = 2;
  h.add_group(2);
  h.add(0, 0, 0, 0);
  h.add(1, 0, 0.5f, 0.5f);
  {
    CullPassOptions options;
    options.frames_in_flight = 2;
    std::unique_ptr<CullPass> pass;
    ASSERT_TRUE(CullPass::create(ctx(), options, pass).ok());
    ASSERT_TRUE(pass->set_scene(h.scene).ok());
    EXPECT_EQ(counting.live.size(), counting.allocations - counting.frees);
    EXPECT_GT(counting.frees, 0u) << "set_scene's staging buffer was given back";
    CullFrame frame;
    frame.clear(2, glm::dmat4(1.0));
    frame.add_region(0, {-1, -1, 1, 1}, {});
    const uint64_t before_frame = counting.allocations;
    ASSERT_TRUE(pass->set_frame(frame, 1).ok());
    EXPECT_GT(counting.allocations, before_frame) << "the slot's frame buffers";
    const uint32_t ids[] = {1};
    ASSERT_TRUE(pass->update_instances(ids, h.scene, 0).ok());
    ASSERT_TRUE(pass->set_frame(frame, 0).ok());
    CullReadback rb;
    ASSERT_TRUE(pass->run(&rb).ok());
    EXPECT_EQ(rb.commands[0].instance_count, 1u);
  }
  ctx().set_allocator(nullptr);
  EXPECT_GE(counting.allocations, 10u);
  EXPECT_EQ(counting.frees, counting.allocations);
  EXPECT_EQ(counting.unknown_frees, 0u);
  EXPECT_TRUE(counting.live.empty());

  // Back on the default: new buffers no longer reach the counting allocator.
  Buffer b;
  ASSERT_TRUE(Buffer::create(ctx(), 256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Upload, "probe", b).ok());
  EXPECT_NE(b.mapped(), nullptr);
  EXPECT_EQ(counting.allocations, counting.frees);
}

// ContextOptions::allocator: the allocator is in use from the context's first buffer.
TEST(AllocatorOptionTest, ContextOptionsAllocatorIsUsed) {
  // Forwards to a DedicatedAllocator of the context it is set on (stateless, so made per call).
  struct Forwarding final : Allocator {
    const Context* ctx = nullptr;
    int allocations = 0, frees = 0;
    Status allocate(const VkMemoryRequirements& r, VkMemoryPropertyFlags req, VkMemoryPropertyFlags pref,
                    const char* label, MemoryBlock& out) override {
      ++allocations;
      return DedicatedAllocator(*ctx).allocate(r, req, pref, label, out);
    }
    void free(const MemoryBlock& block) override {
      ++frees;
      DedicatedAllocator(*ctx).free(block);
    }
  } forwarding;
  ContextOptions options;
  options.allocator = &forwarding;
  std::unique_ptr<Context> ctx = test::make_validated_context(options);
  ASSERT_NE(ctx, nullptr);
  forwarding.ctx = ctx.get();
  EXPECT_EQ(&ctx->allocator(), &forwarding);
  {
    Buffer b;
    ASSERT_TRUE(Buffer::create(*ctx, 1024, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Device, "probe", b).ok());
    EXPECT_EQ(forwarding.allocations, 1);
  }
  EXPECT_EQ(forwarding.frees, 1);
  test::expect_clean(*ctx);
}

}  // namespace
}  // namespace lintel::gpu
