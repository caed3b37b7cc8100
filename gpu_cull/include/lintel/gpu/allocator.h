// Where Lintel's buffers get their device memory: a small interface a game implements with its own
// allocator (a sub-allocator, VMA, a budget tracker), and the default, one vkAllocateMemory per
// buffer. Context hands the chosen one to every gpu::Buffer (docs/gpu_cull.md, "Memory").
#pragma once

#include <lintel/status.h>

#include <vulkan/vulkan.h>

#include <cstdint>

namespace lintel::gpu {

class Context;

// A piece of device memory a resource is bound to.
struct MemoryBlock {
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkDeviceSize offset = 0;  // where the resource starts in `memory` (a multiple of its alignment)
  void* mapped = nullptr;   // host pointer to `offset`, for host-visible memory; else nullptr
  uint64_t user = 0;        // the allocator's own bookkeeping (e.g. its block index); Lintel keeps it
};

class Allocator {
 public:
  virtual ~Allocator() = default;
  // Memory for a resource with `requirements` (size, alignment, allowed memory types), from a type
  // that has every flag of `required` and, where one has them, those of `preferred`. Memory with
  // HOST_VISIBLE in `required` comes back mapped. `label` names the resource for messages.
  // Errors: no allowed type (Unsupported), out of memory.
  virtual Status allocate(const VkMemoryRequirements& requirements, VkMemoryPropertyFlags required,
                          VkMemoryPropertyFlags preferred, const char* label, MemoryBlock& out) = 0;
  // Gives back a block allocate() returned; the resource bound to it is already destroyed.
  virtual void free(const MemoryBlock& block) = 0;
};

// The default: one dedicated vkAllocateMemory per resource, mapped whole when host-visible. Lintel
// makes few, large buffers, far below maxMemoryAllocationCount.
class DedicatedAllocator final : public Allocator {
 public:
  explicit DedicatedAllocator(const Context& ctx) : ctx_(ctx) {}
  Status allocate(const VkMemoryRequirements& requirements, VkMemoryPropertyFlags required,
                  VkMemoryPropertyFlags preferred, const char* label, MemoryBlock& out) override;
  void free(const MemoryBlock& block) override;

 private:
  const Context& ctx_;
};

}  // namespace lintel::gpu
