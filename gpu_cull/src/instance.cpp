// The Vulkan instance: API 1.3, no surface extensions (headless), and when validation is asked
// for, the Khronos layer with synchronization validation and GPU-assisted validation, because
// lavapipe runs every barrier as a full wait and would hide a missing one (LESSONS.md).
#include <lintel/gpu/context.h>

#include "vk_status.h"

#include <cstring>

namespace lintel::gpu {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool has_layer(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  for (const VkLayerProperties& layer : layers)
    if (std::strcmp(layer.layerName, name) == 0) return true;
  return false;
}

}  // namespace

VKAPI_ATTR VkBool32 VKAPI_CALL Context::on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT types,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  // The loader's own chatter (general messages below error) is not a validation finding.
  if (!(types & (VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT)) &&
      severity < VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT)
    return VK_FALSE;
  auto* log = static_cast<MessageLog*>(user);
  std::string line = severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error: " : "warning: ";
  if (data->pMessageIdName) line += std::string("[") + data->pMessageIdName + "] ";
  line += data->pMessage ? data->pMessage : "";
  std::lock_guard<std::mutex> lock(log->mutex);
  log->messages.push_back(std::move(line));
  return VK_FALSE;
}

Status Context::create_instance(bool validation) {
  if (validation && !has_layer(kValidationLayer))
    return Status::unsupported(
        "Vulkan validation requested but VK_LAYER_KHRONOS_validation is not installed "
        "(Debian: vulkan-validationlayers)");
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "lintel";
  app.pEngineName = "lintel";
  app.apiVersion = VK_API_VERSION_1_3;

  VkDebugUtilsMessengerCreateInfoEXT messenger_info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger_info.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger_info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger_info.pfnUserCallback = &Context::on_message;
  messenger_info.pUserData = log_.get();

  const VkValidationFeatureEnableEXT enables[] = {
      VK_VALIDATION_FEATURE_ENABLE_GPU_ASSISTED_EXT,
      VK_VALIDATION_FEATURE_ENABLE_GPU_ASSISTED_RESERVE_BINDING_SLOT_EXT,
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT,
  };
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = uint32_t(std::size(enables));
  features.pEnabledValidationFeatures = enables;
  features.pNext = &messenger_info;  // also catches messages from vkCreate/DestroyInstance

  const char* layers[] = {kValidationLayer};
  const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  if (validation) {
    info.pNext = &features;
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = layers;
    info.enabledExtensionCount = 1;
    info.ppEnabledExtensionNames = extensions;
  }
  if (Status s = vk_check(vkCreateInstance(&info, nullptr, &instance_), "vkCreateInstance", "Vulkan 1.3 instance"); !s)
    return s;
  if (validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
    if (!create) return Status::unsupported("vkCreateDebugUtilsMessengerEXT not found (VK_EXT_debug_utils)");
    if (Status s = vk_check(create(instance_, &messenger_info, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT",
                            "validation messages");
        !s)
      return s;
  }
  return {};
}

std::vector<std::string> Context::take_validation_messages() {
  std::lock_guard<std::mutex> lock(log_->mutex);
  std::vector<std::string> out;
  out.swap(log_->messages);
  return out;
}

Status list_devices(std::vector<std::string>& out) {
  out.clear();
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.apiVersion = VK_API_VERSION_1_3;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  VkInstance instance = VK_NULL_HANDLE;
  if (Status s = vk_check(vkCreateInstance(&info, nullptr, &instance), "vkCreateInstance", "listing devices"); !s)
    return s;
  uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance, &count, devices.data());
  for (uint32_t i = 0; i < count; ++i) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(devices[i], &props);
    out.push_back(std::to_string(i) + ": " + props.deviceName);
  }
  vkDestroyInstance(instance, nullptr);
  return {};
}

}  // namespace lintel::gpu
