// Buffer creation: memory type by use (device-local, or host-visible and mapped for staging).
#include <lintel/gpu/buffer.h>

#include <lintel/gpu/vk_status.h>

#include <string>
#include <utility>

namespace lintel::gpu {

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    reset();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    size_ = std::exchange(other.size_, 0);
    mapped_ = std::exchange(other.mapped_, nullptr);
  }
  return *this;
}

void Buffer::reset() {
  if (device_) {
    if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
    if (memory_) vkFreeMemory(device_, memory_, nullptr);  // unmaps implicitly
  }
  device_ = VK_NULL_HANDLE;
  buffer_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  size_ = 0;
  mapped_ = nullptr;
}

Status Buffer::create(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use,
                      const char* label, Buffer& out) {
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
  uint32_t type = UINT32_MAX;
  switch (use) {
    case MemoryUse::Device:
      type = ctx.find_memory_type(req.memoryTypeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
      break;
    case MemoryUse::Upload:
      type = ctx.find_memory_type(req.memoryTypeBits,
                                  VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
      break;
    case MemoryUse::Readback:
      type = ctx.find_memory_type(req.memoryTypeBits,
                                  VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                                  VK_MEMORY_PROPERTY_HOST_CACHED_BIT);
      break;
  }
  if (type == UINT32_MAX) return Status::unsupported(std::string("no suitable Vulkan memory type for ") + label);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = type;
  if (Status s = vk_check(vkAllocateMemory(b.device_, &alloc, nullptr, &b.memory_), "vkAllocateMemory", label); !s)
    return s;
  if (Status s = vk_check(vkBindBufferMemory(b.device_, b.buffer_, b.memory_, 0), "vkBindBufferMemory", label); !s)
    return s;
  if (use != MemoryUse::Device) {
    if (Status s = vk_check(vkMapMemory(b.device_, b.memory_, 0, VK_WHOLE_SIZE, 0, &b.mapped_), "vkMapMemory", label); !s)
      return s;
  }
  out = std::move(b);
  return {};
}

}  // namespace lintel::gpu
