// Buffer creation: memory type by use (device-local, or host-visible and mapped for staging).
#include <lintel/gpu/buffer.h>

#include "vk_status.h"

#include <string>
#include <utility>

namespace lintel::gpu {

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    reset();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
    allocator_ = std::exchange(other.allocator_, nullptr);
    block_ = std::exchange(other.block_, MemoryBlock{});
    size_ = std::exchange(other.size_, 0);
  }
  return *this;
}

void Buffer::reset() {
  if (device_ && buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
  if (allocator_ && block_.memory) allocator_->free(block_);
  device_ = VK_NULL_HANDLE;
  buffer_ = VK_NULL_HANDLE;
  allocator_ = nullptr;
  block_ = {};
  size_ = 0;
}

Status Buffer::create(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use, const char* label,
                      Buffer& out) {
  out.reset();
  Buffer b;
  b.device_ = ctx.device();
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  if (Status s = vk_check(vkCreateBuffer(b.device_, &info, nullptr, &b.buffer_), "vkCreateBuffer", label); !s) return s;
  b.size_ = size;

  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(b.device_, b.buffer_, &req);
  VkMemoryPropertyFlags required = 0, preferred = 0;
  switch (use) {
    case MemoryUse::Device:
      preferred = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
      break;
    case MemoryUse::Upload:
      required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
      break;
    case MemoryUse::Readback:
      required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
      preferred = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
      break;
  }
  Allocator& allocator = ctx.allocator();
  if (Status s = allocator.allocate(req, required, preferred, label, b.block_); !s) return s;
  b.allocator_ = &allocator;
  if (use != MemoryUse::Device && !b.block_.mapped)
    return Status::internal(std::string("allocator returned unmapped host-visible memory for ") + label);
  if (Status s = vk_check(vkBindBufferMemory(b.device_, b.buffer_, b.block_.memory, b.block_.offset),
                          "vkBindBufferMemory", label);
      !s)
    return s;
  out = std::move(b);
  return {};
}

}  // namespace lintel::gpu
