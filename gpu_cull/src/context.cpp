// Context lifetime, memory type choice and the one-shot submit every upload, cull and readback
// goes through. Objects are destroyed in reverse order of creation; a half-built context (after a
// failed create) tears down cleanly.
#include <lintel/gpu/context.h>

#include "vk_status.h"

namespace lintel::gpu {

// Long enough for GPU-assisted validation on lavapipe with millions of instances; a hang beyond it
// comes back as an error instead of a frozen test.
constexpr uint64_t kSubmitTimeoutNs = 300ull * 1000 * 1000 * 1000;

Status Context::create(const ContextOptions& options, std::unique_ptr<Context>& out) {
  return create(options, {}, out);
}

Status Context::create(const ContextOptions& options, const std::vector<std::string>& pretend_missing,
                       std::unique_ptr<Context>& out) {
  out.reset();
  std::unique_ptr<Context> ctx(new Context());
  if (Status s = ctx->create_instance(options.validation); !s) return s;
  if (Status s = ctx->create_device(options, pretend_missing); !s) return s;
  ctx->set_allocator(options.allocator);
  out = std::move(ctx);
  return {};
}

Context::~Context() {
  if (borrowed_) {  // the device, queue and instance are the caller's: only what wrap() made goes
    if (fence_) vkDestroyFence(device_, fence_, nullptr);
    if (command_pool_) vkDestroyCommandPool(device_, command_pool_, nullptr);
    return;
  }
  if (device_) {
    vkDeviceWaitIdle(device_);
    if (fence_) vkDestroyFence(device_, fence_, nullptr);
    if (command_pool_) vkDestroyCommandPool(device_, command_pool_, nullptr);
    vkDestroyDevice(device_, nullptr);
  }
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
  }
  if (instance_) vkDestroyInstance(instance_, nullptr);
}

uint32_t Context::find_memory_type(uint32_t type_bits, VkMemoryPropertyFlags required,
                                   VkMemoryPropertyFlags preferred) const {
  uint32_t fallback = UINT32_MAX;
  for (uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
    if (!(type_bits & (1u << i))) continue;
    const VkMemoryPropertyFlags flags = memory_.memoryTypes[i].propertyFlags;
    if ((flags & required) != required) continue;
    if ((flags & preferred) == preferred) return i;
    if (fallback == UINT32_MAX) fallback = i;
  }
  return fallback;
}

Status Context::submit_and_wait(const std::function<void(VkCommandBuffer)>& record, const char* what) {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = command_pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  if (Status s = vk_check(vkAllocateCommandBuffers(device_, &alloc, &cmd), "vkAllocateCommandBuffers", what); !s)
    return s;
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkBeginCommandBuffer(cmd, &begin);
  record(cmd);
  Status status = vk_check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer", what);
  bool pending = false;
  if (status) {
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    status = vk_check(vkQueueSubmit(queue_, 1, &submit, fence_), "vkQueueSubmit", what);
    pending = status.ok();
  }
  if (pending) {
    status = vk_check(vkWaitForFences(device_, 1, &fence_, VK_TRUE, kSubmitTimeoutNs), "vkWaitForFences", what);
    if (status) {
      vkResetFences(device_, 1, &fence_);
      pending = false;
    }
  }
  // A buffer still pending after a timeout or device loss is reclaimed with the pool.
  if (!pending) vkFreeCommandBuffers(device_, command_pool_, 1, &cmd);
  return status;
}

}  // namespace lintel::gpu
