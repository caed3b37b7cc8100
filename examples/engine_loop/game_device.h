// What a game owns before it calls Lintel: its Vulkan instance (with the validation layers and
// its own messenger when asked), the physical device, and a device created with the feature
// chain Lintel asks for (lintel::gpu::DeviceFeatures) and one graphics+compute queue.
#pragma once

#include <lintel/gpu/context.h>

#include <vulkan/vulkan.h>

#include <mutex>
#include <string>
#include <vector>

struct GameDevice {
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  uint32_t queue_family = 0;
  lintel::gpu::DeviceFeatures enabled;

  // With `validate`: Khronos validation + synchronization validation + GPU-assisted validation,
  // every warning or error collected. `name`: a substring of the device name, or "" for the first
  // device Lintel accepts (discrete GPUs first). Returns "" or what went wrong.
  std::string create(bool validate, const std::string& name);
  void destroy();
  std::vector<std::string> take_messages();

  lintel::gpu::ExternalDevice external() const {
    return {instance, physical, device, queue_family, queue, enabled, nullptr};
  }

  std::mutex mutex;  // validation callbacks may come from the layer's threads
  std::vector<std::string> messages;
};
