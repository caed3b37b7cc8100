// The Vulkan 1.3 device Lintel works on: either its own headless one (Context::create: instance,
// one physical device chosen by type or by name, one graphics+compute queue) or a game's, borrowed
// (Context::wrap), plus a one-shot submit helper for uploads at setup and for tools.
// It refuses devices that lack a feature the GPU-driven draws need, naming the feature, instead of
// falling back to a path that silently drops draws (docs/gpu_cull.md, "Device requirements").
#pragma once

#include <lintel/gpu/allocator.h>
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
  // the device name. Empty: the first discrete GPU, else integrated, virtual, then CPU (lavapipe)
  // that has every feature. (The library reads no environment variable; the CLI and the tests
  // take LINTEL_VK_DEVICE and pass it here.)
  std::string device;
  // Where buffers get their memory; null: DedicatedAllocator. Not owned: it outlives the context
  // and every buffer made on it.
  Allocator* allocator = nullptr;
};

// The device features Lintel needs, as a chain a caller can hand to vkCreateDevice: the required
// ones (multiDrawIndirect, drawIndirectFirstInstance, synchronization2, dynamicRendering,
// maintenance4) and the optional ones it uses where the device has them (drawIndirectCount,
// shaderDrawParameters, vertex/fragment stores for GPU-assisted validation). A game with its own
// chain ORs these flags into it instead.
struct DeviceFeatures {
  VkPhysicalDeviceFeatures2 core{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  VkPhysicalDeviceVulkan11Features v11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
  VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};

  // Links core -> v11 -> v12 -> v13 (-> `next`) and returns &core, for VkDeviceCreateInfo::pNext.
  // Call it again after copying the struct: the links point into this object.
  VkPhysicalDeviceFeatures2* link(void* next = nullptr);

  // What Lintel would enable on `device`. Errors (Unsupported): it lacks Vulkan 1.3 or a required
  // feature, named with why Lintel needs it.
  static Status for_device(VkPhysicalDevice device, DeviceFeatures& out);
};

// A device the caller created and keeps owning (a game's), for Context::wrap.
struct ExternalDevice {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  uint32_t queue_family = 0;       // must have graphics and compute
  VkQueue queue = VK_NULL_HANDLE;  // of queue_family; used only by submit_and_wait (setup, tools)
  // What the caller enabled in vkCreateDevice: Vulkan cannot be asked afterwards. Lintel checks the
  // required flags here and uses the optional ones only where they are set.
  DeviceFeatures enabled;
  // The game's allocator for Lintel's buffers; null: DedicatedAllocator. Not owned (see
  // ContextOptions::allocator).
  Allocator* allocator = nullptr;
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
  bool timestamps = false;  // timestamp queries on the queue family
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
  // Borrows the caller's instance, device and queue: Lintel destroys none of them, and creates on
  // the device only what its passes need (pipelines, buffers, images, descriptors, samplers, query
  // pools) plus one command pool and fence for submit_and_wait. The caller keeps the device alive
  // until every Lintel object made on it is destroyed, and externally synchronizes the queue
  // (Lintel submits to it only inside submit_and_wait). Validation is the caller's: its own
  // messenger sees Lintel's calls; take_validation_messages() stays empty. Errors: null handles,
  // a queue family without graphics+compute, a required feature not enabled (named).
  static Status wrap(const ExternalDevice& device, std::unique_ptr<Context>& out);
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
  bool borrowed() const { return borrowed_; }  // made by wrap(): the device is the caller's

  // The allocator every gpu::Buffer made from now on takes its memory from. set_allocator(nullptr)
  // returns to the default. A buffer gives its memory back to the allocator it came from, so an
  // allocator must outlive the buffers made while it was set.
  Allocator& allocator() const { return *allocator_; }
  void set_allocator(Allocator* allocator) { allocator_ = allocator ? allocator : default_allocator_.get(); }

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
  friend struct ContextTesting;  // test-only: devices pretending to lack features (src/context_testing.h)
  Context() = default;
  // create(), treating `pretend_missing` (Vulkan feature names) as unsupported.
  static Status create(const ContextOptions& options, const std::vector<std::string>& pretend_missing,
                       std::unique_ptr<Context>& out);
  struct MessageLog {
    std::mutex mutex;
    std::vector<std::string> messages;
  };
  static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT types,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);
  Status create_instance(bool validation);
  Status create_device(const ContextOptions& options, const std::vector<std::string>& pretend_missing);
  Status create_submit_objects();
  void describe_device(uint32_t index, const DeviceFeatures& enabled, bool subgroup_ballot_allowed);

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
  bool borrowed_ = false;
  std::unique_ptr<DedicatedAllocator> default_allocator_ = std::make_unique<DedicatedAllocator>(*this);
  Allocator* allocator_ = default_allocator_.get();
};

// Every physical device Vulkan reports, as "index: name (type)", for messages and `lintel`.
Status list_devices(std::vector<std::string>& out);

}  // namespace lintel::gpu
