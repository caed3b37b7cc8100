// The game's Vulkan setup, as little as Lintel needs: Vulkan 1.3, the features of
// DeviceFeatures::for_device enabled through its chain, one queue with graphics and compute.
#include "game_device.h"

#include <cstring>
#include <iterator>

namespace {

VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT, VkDebugUtilsMessageTypeFlagsEXT,
                                          const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  GameDevice& game = *static_cast<GameDevice*>(user);
  std::lock_guard<std::mutex> lock(game.mutex);
  game.messages.push_back(data->pMessage ? data->pMessage : "(no message)");
  return VK_FALSE;
}

}  // namespace

std::string GameDevice::create(bool validate, const std::string& name) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "engine_loop";
  app.apiVersion = VK_API_VERSION_1_3;
  VkDebugUtilsMessengerCreateInfoEXT messenger_info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger_info.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger_info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger_info.pfnUserCallback = &on_message;
  messenger_info.pUserData = this;
  const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_GPU_ASSISTED_EXT,
                                                  VK_VALIDATION_FEATURE_ENABLE_GPU_ASSISTED_RESERVE_BINDING_SLOT_EXT,
                                                  VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = uint32_t(std::size(enables));
  features.pEnabledValidationFeatures = enables;
  features.pNext = &messenger_info;
  const char* layers[] = {"VK_LAYER_KHRONOS_validation"};
  const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  if (validate) {
    info.pNext = &features;
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = layers;
    info.enabledExtensionCount = 1;
    info.ppEnabledExtensionNames = extensions;
  }
  if (vkCreateInstance(&info, nullptr, &instance) != VK_SUCCESS)
    return validate ? "vkCreateInstance failed (are the Vulkan validation layers installed?)"
                    : "vkCreateInstance failed";
  if (validate) {
    auto create_messenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    if (!create_messenger || create_messenger(instance, &messenger_info, nullptr, &messenger) != VK_SUCCESS)
      return "vkCreateDebugUtilsMessengerEXT failed";
  }

  // The first device Lintel accepts, discrete GPUs before the rest (lavapipe last).
  uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance, &count, devices.data());
  std::string refusals;
  for (int pass = 0; pass < 2 && !physical; ++pass) {
    for (VkPhysicalDevice d : devices) {
      VkPhysicalDeviceProperties props;
      vkGetPhysicalDeviceProperties(d, &props);
      if (!name.empty() && !std::strstr(props.deviceName, name.c_str())) continue;
      if ((pass == 0) != (props.deviceType == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU)) continue;
      if (lintel::Status s = lintel::gpu::DeviceFeatures::for_device(d, enabled); !s) {
        refusals += "; " + s.message();
        continue;
      }
      physical = d;
      break;
    }
  }
  if (!physical) return "no Vulkan device Lintel can use" + (name.empty() ? "" : " named '" + name + "'") + refusals;
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, families.data());
  queue_family = UINT32_MAX;
  for (uint32_t f = 0; f < count && queue_family == UINT32_MAX; ++f)
    if ((families[f].queueFlags & (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) ==
        (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT))
      queue_family = f;
  if (queue_family == UINT32_MAX) return "no queue family with graphics and compute";

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue_info.queueFamilyIndex = queue_family;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;
  VkDeviceCreateInfo device_info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  device_info.pNext = enabled.link();  // a game with its own chain would OR these flags into it
  device_info.queueCreateInfoCount = 1;
  device_info.pQueueCreateInfos = &queue_info;
  if (vkCreateDevice(physical, &device_info, nullptr, &device) != VK_SUCCESS) return "vkCreateDevice failed";
  vkGetDeviceQueue(device, queue_family, 0, &queue);
  return "";
}

void GameDevice::destroy() {
  if (device) vkDestroyDevice(device, nullptr);
  if (messenger) {
    auto destroy_messenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy_messenger) destroy_messenger(instance, messenger, nullptr);
  }
  if (instance) vkDestroyInstance(instance, nullptr);
  device = VK_NULL_HANDLE;
  messenger = VK_NULL_HANDLE;
  instance = VK_NULL_HANDLE;
}

std::vector<std::string> GameDevice::take_messages() {
  std::lock_guard<std::mutex> lock(mutex);
  std::vector<std::string> out;
  out.swap(messages);
  return out;
}
