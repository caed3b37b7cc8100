// Is GPU-assisted validation really running on this machine's first Vulkan device? The package
// test asks before it trusts "no validation message" from engine_loop and render_client.
// Evidence: with VK_VALIDATION_FEATURE_ENABLE_GPU_ASSISTED_RESERVE_BINDING_SLOT_EXT the Khronos
// layer keeps one descriptor set slot for its instrumentation and reports maxBoundDescriptorSets
// one lower than the driver; a layer that could not set GPU-AV up would not. Warnings and errors
// the layer raises while an instance and a device are made are printed and fail the probe.
// Exit: 0 active, 1 not active or a message, 2 no Vulkan.
#include <vulkan/vulkan.h>

#include <cstdio>
#include <vector>

namespace {

int g_messages = 0;

VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT, VkDebugUtilsMessageTypeFlagsEXT,
                                          const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
  std::fprintf(stderr, "gpu_av_probe: layer: %s\n", data->pMessage ? data->pMessage : "(no message)");
  ++g_messages;
  return VK_FALSE;
}

// maxBoundDescriptorSets of the first device, seen through an instance with or without the layer
// (GPU-AV, its reserved slot and sync validation enabled); 0 when Vulkan fails.
uint32_t max_bound_sets(bool validate) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.apiVersion = VK_API_VERSION_1_3;
  VkDebugUtilsMessengerCreateInfoEXT messenger{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                          VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger.pfnUserCallback = &on_message;
  const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_GPU_ASSISTED_EXT,
                                                  VK_VALIDATION_FEATURE_ENABLE_GPU_ASSISTED_RESERVE_BINDING_SLOT_EXT,
                                                  VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = 3;
  features.pEnabledValidationFeatures = enables;
  features.pNext = &messenger;
  const char* layer = "VK_LAYER_KHRONOS_validation";
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  if (validate) {
    info.pNext = &features;
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = &layer;
  }
  VkInstance instance = VK_NULL_HANDLE;
  if (vkCreateInstance(&info, nullptr, &instance) != VK_SUCCESS) return 0;
  uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance, &count, devices.data());
  uint32_t sets = 0;
  if (count > 0) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(devices[0], &props);
    sets = props.limits.maxBoundDescriptorSets;
    // A device too: the layer sets GPU-AV up per device and says so if it cannot.
    VkPhysicalDeviceFeatures supported{};
    vkGetPhysicalDeviceFeatures(devices[0], &supported);
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;
    VkDeviceCreateInfo device_info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    device_info.queueCreateInfoCount = 1;
    device_info.pQueueCreateInfos = &queue;
    device_info.pEnabledFeatures = &supported;
    VkDevice device = VK_NULL_HANDLE;
    if (vkCreateDevice(devices[0], &device_info, nullptr, &device) == VK_SUCCESS) vkDestroyDevice(device, nullptr);
    std::printf("gpu_av_probe: %s, layer %s: maxBoundDescriptorSets %u\n", props.deviceName, validate ? "on" : "off",
                sets);
  }
  vkDestroyInstance(instance, nullptr);
  return sets;
}

}  // namespace

int main() {
  const uint32_t plain = max_bound_sets(false);
  const uint32_t validated = max_bound_sets(true);
  if (plain == 0 || validated == 0) {
    std::fprintf(stderr, "gpu_av_probe: no Vulkan device (or no validation layer)\n");
    return 2;
  }
  const bool active = validated + 1 == plain;
  std::printf("gpu_av_probe: GPU-assisted validation %s (%u descriptor sets -> %u), %d layer messages\n",
              active ? "active" : "NOT active", plain, validated, g_messages);
  return active && g_messages == 0 ? 0 : 1;
}
