// The default allocator: a dedicated VkDeviceMemory per buffer, mapped for its lifetime when the
// host reaches it (staging and readback).
#include <lintel/gpu/allocator.h>

#include <lintel/gpu/context.h>
#include "vk_status.h"

#include <string>

namespace lintel::gpu {

Status DedicatedAllocator::allocate(const VkMemoryRequirements& requirements, VkMemoryPropertyFlags required,
                                    VkMemoryPropertyFlags preferred, const char* label, MemoryBlock& out) {
  out = {};
  const uint32_t type = ctx_.find_memory_type(requirements.memoryTypeBits, required, preferred);
  if (type == UINT32_MAX) return Status::unsupported(std::string("no suitable Vulkan memory type for ") + label);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = requirements.size;
  alloc.memoryTypeIndex = type;
  MemoryBlock block;
  if (Status s = vk_check(vkAllocateMemory(ctx_.device(), &alloc, nullptr, &block.memory), "vkAllocateMemory", label);
      !s)
    return s;
  if (required & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) {
    if (Status s = vk_check(vkMapMemory(ctx_.device(), block.memory, 0, VK_WHOLE_SIZE, 0, &block.mapped), "vkMapMemory",
                            label);
        !s) {
      vkFreeMemory(ctx_.device(), block.memory, nullptr);
      return s;
    }
  }
  out = block;
  return {};
}

void DedicatedAllocator::free(const MemoryBlock& block) {
  if (block.memory) vkFreeMemory(ctx_.device(), block.memory, nullptr);  // unmaps implicitly
}

}  // namespace lintel::gpu
