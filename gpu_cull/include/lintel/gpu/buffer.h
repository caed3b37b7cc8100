// A VkBuffer bound to memory from the context's gpu::Allocator (by default one allocation each:
// few, large buffers per pass). Move-only; destroys itself and gives its memory back to the
// allocator it came from.
#pragma once

#include <lintel/gpu/allocator.h>
#include <lintel/gpu/context.h>
#include <lintel/status.h>

#include <vulkan/vulkan.h>

namespace lintel::gpu {

enum class MemoryUse {
  Device,    // device-local; reached by copies and shaders
  Upload,    // host-visible + coherent, mapped: the host writes, the GPU copies from it
  Readback,  // host-visible + coherent (cached where offered), mapped: the GPU copies into it
};

class Buffer {
 public:
  Buffer() = default;
  ~Buffer() { reset(); }
  Buffer(Buffer&& other) noexcept { *this = std::move(other); }
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  // `label` names the buffer in error messages, e.g. "instance ids (16 MiB)". size > 0.
  static Status create(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use,
                       const char* label, Buffer& out);
  void reset();

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  // Host pointer of an Upload/Readback buffer (nullptr for Device).
  void* mapped() const { return block_.mapped; }
  explicit operator bool() const { return buffer_ != VK_NULL_HANDLE; }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  Allocator* allocator_ = nullptr;  // the one `block_` came from
  MemoryBlock block_;
  VkDeviceSize size_ = 0;
};

}  // namespace lintel::gpu
