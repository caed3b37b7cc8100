// A headless Vulkan 1.3 context (no window, no surface): instance, one physical device chosen by
// type or by LINTEL_VK_DEVICE, one graphics+compute queue, and a one-shot submit helper.
// It refuses devices that lack a feature the GPU-driven draws need, naming the feature, instead of
// falling back to a path that silently drops draws (docs/gpu_cull.md, "Device requirements").
#pragma once

#include <lintel/status.h>

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace lintel::gpu {

struct ContextOptions {
  // Khronos validation with synchronization validation and GPU-assisted validation. Every
  // warning or error it reports is recorded (take_validation_messages()); tests fail on any.
  bool validation = false;
  // Which device: an index into vkEnumeratePhysicalDevices or a case-insensitive substring of
  // the device name. Empty: the LINTEL_VK_DEVICE environment variable; if that is unset too, the
  // first discrete GPU, else integrated, virtual, then CPU (lavapipe) that has every feature.
  std::string device;
  // Testing only: features to treat as unsupported, by their Vulkan name (e.g.
  // "drawIndirectFirstInstance"), to prove that a device without them is refused.
  std::vector<std::string> pretend_missing;
};

// What the chosen device offers beyond the required features.
struct DeviceInfo {
  std::string name;
  uint32_t index = 0;  // in vkEnumeratePhysicalDevices order
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  uint32_t api_version = 0;
  bool draw_indirect_count = false;  // vkCmdDrawIndexedIndirectCount usable (enabled)
  bool subgroup_ballot = false;      // compute shaders may use subgroupBallot & co.
  uint32_t subgroup_size = 0;
  bool timestamps = false;           // timestamp queries on the queue family
  float timestamp_period_ns = 0.0f;
  uint32_t max_storage_buffer_range = 0;
  VkDeviceSize min_storage_buffer_offset_alignment = 0;
};

class Context {
 public:
  // Creates the context. Errors name the missing layer, device or feature, e.g.
  // "Vulkan device 'llvmpipe (...)' lacks drawIndirectFirstInstance: every draw group but the one
  // at instance 0 would be silently dropped".
  static Status create(const ContextOptions& options, std::unique_ptr<Context>& out);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physical_device() const { return physical_device_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  uint32_t queue_family() const { return queue_family_; }
  const DeviceInfo& info() const { return info_; }
  bool validation() const { return messenger_ != VK_NULL_HANDLE; }

  // Memory type index with all of `required` (and, among those, `preferred` where possible)
  // allowed by `type_bits`, or UINT32_MAX.
  uint32_t find_memory_type(uint32_t type_bits, VkMemoryPropertyFlags required,
                            VkMemoryPropertyFlags preferred = 0) const;

  // Records `record` into a fresh primary command buffer, submits it and waits for it.
  // `what` names the work in error messages.
  Status submit_and_wait(const std::function<void(VkCommandBuffer)>& record, const char* what);

  // Validation messages (warnings and errors) since creation or the previous call. Thread-safe.
  std::vector<std::string> take_validation_messages();

 private:
  Context() = default;
  struct MessageLog {
    std::mutex mutex;
    std::vector<std::string> messages;
  };
  static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT types,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                   void* user);
  Status create_instance(bool validation);
  Status create_device(const ContextOptions& options);

  std::unique_ptr<MessageLog> log_ = std::make_unique<MessageLog>();
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queue_family_ = 0;
  VkCommandPool command_pool_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  VkPhysicalDeviceMemoryProperties memory_{};
  DeviceInfo info_;
};

// Every physical device Vulkan reports, as "index: name (type)", for messages and `lintel`.
Status list_devices(std::vector<std::string>& out);

}  // namespace lintel::gpu
