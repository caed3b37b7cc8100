// The viewer's own Vulkan setup (see window_device.h), written as a game would write it: nothing
// here uses Lintel's Context::create; Lintel only sees the finished device through wrap().
#include "window_device.h"

#include "vk_status.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <utility>

namespace lintel::view {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool all_digits(const std::string& s) {
  return !s.empty() &&
         std::all_of(s.begin(), s.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

// Discrete GPUs first, lavapipe (CPU) last, as Context::create orders them.
int type_rank(VkPhysicalDeviceType t) {
  switch (t) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return 3;
    default:
      return 4;
  }
}

bool has_device_extension(VkPhysicalDevice d, const char* name) {
  uint32_t n = 0;
  vkEnumerateDeviceExtensionProperties(d, nullptr, &n, nullptr);
  std::vector<VkExtensionProperties> ext(n);
  vkEnumerateDeviceExtensionProperties(d, nullptr, &n, ext.data());
  for (const VkExtensionProperties& e : ext)
    if (std::strcmp(e.extensionName, name) == 0) return true;
  return false;
}

}  // namespace

VKAPI_ATTR VkBool32 VKAPI_CALL WindowDevice::on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                        VkDebugUtilsMessageTypeFlagsEXT types,
                                                        const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  const bool finding =
      types & (VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT);
  if (finding || severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) {
    auto* log = static_cast<MessageLog*>(user);
    std::lock_guard<std::mutex> lock(log->mutex);
    log->messages.push_back(data && data->pMessage ? data->pMessage : "(no message)");
  }
  return VK_FALSE;
}

Status WindowDevice::create(const WindowDeviceOptions& options, std::unique_ptr<WindowDevice>& out) {
  out.reset();
  std::unique_ptr<WindowDevice> d(new WindowDevice());
  if (!options.offscreen)
    if (Status s = d->create_window(options); !s) return s;
  if (Status s = d->create_instance(options); !s) return s;
  if (d->window_)
    if (Status s = gpu::vk_check(glfwCreateWindowSurface(d->instance_, d->window_, nullptr, &d->surface_),
                                 "glfwCreateWindowSurface", "the viewer's window");
        !s)
      return s;
  if (Status s = d->pick_physical_device(options); !s) return s;
  if (Status s = d->create_device(); !s) return s;
  out = std::move(d);
  return {};
}

Status WindowDevice::create_window(const WindowDeviceOptions& options) {
  if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY"))
    return Status::unsupported(
        "no display to open a window on (DISPLAY is unset): run under 'xvfb-run -a', or give "
        "--script to run offscreen");
  if (glfwInit() != GLFW_TRUE) {
    const char* why = nullptr;
    glfwGetError(&why);
    return Status::unsupported(std::string("cannot open the display: ") + (why ? why : "glfwInit failed") +
                               " (run under 'xvfb-run -a', or give --script to run offscreen)");
  }
  glfw_ = true;
  if (glfwVulkanSupported() != GLFW_TRUE) return Status::unsupported("GLFW finds no Vulkan loader");
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);  // the frame size is the renderer's, fixed at creation
  window_ = glfwCreateWindow(int(options.width), int(options.height), options.title.c_str(), nullptr, nullptr);
  if (!window_) {
    const char* why = nullptr;
    glfwGetError(&why);
    return Status::unsupported(std::string("cannot create the window: ") + (why ? why : "unknown GLFW error"));
  }
  return {};
}

Status WindowDevice::create_instance(const WindowDeviceOptions& options) {
  std::vector<const char*> extensions;
  if (window_) {
    uint32_t n = 0;
    const char** glfw_ext = glfwGetRequiredInstanceExtensions(&n);
    if (!glfw_ext) return Status::unsupported("GLFW names no Vulkan surface extensions for this display");
    extensions.assign(glfw_ext, glfw_ext + n);
  }
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "lintel view";
  app.apiVersion = VK_API_VERSION_1_3;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;

  VkDebugUtilsMessengerCreateInfoEXT messenger_info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger_info.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger_info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger_info.pfnUserCallback = &on_message;
  messenger_info.pUserData = log_.get();
  const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = enables;
  features.pNext = &messenger_info;
  const char* layers[] = {"VK_LAYER_KHRONOS_validation"};
  if (options.validation) {
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    info.pNext = &features;  // also catches messages of vkCreateInstance itself
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = layers;
  }
  info.enabledExtensionCount = uint32_t(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  const VkResult r = vkCreateInstance(&info, nullptr, &instance_);
  if (r == VK_ERROR_LAYER_NOT_PRESENT)
    return Status::unsupported("--validation: the Khronos validation layer is not installed (vulkan-validationlayers)");
  if (Status s = gpu::vk_check(r, "vkCreateInstance", "the viewer's instance"); !s) return s;
  if (options.validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
    if (!create) return Status::unsupported("--validation: vkCreateDebugUtilsMessengerEXT is missing");
    if (Status s = gpu::vk_check(create(instance_, &messenger_info, nullptr, &messenger_),
                                 "vkCreateDebugUtilsMessengerEXT", "validation messages");
        !s)
      return s;
  }
  return {};
}

Status WindowDevice::pick_physical_device(const WindowDeviceOptions& options) {
  uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance_, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance_, &count, devices.data());
  std::string rejected;  // "name: why; ..." for the error message
  int best_rank = 1 << 20;
  for (uint32_t i = 0; i < count; ++i) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(devices[i], &props);
    const std::string name = props.deviceName;
    if (!options.device.empty()) {
      const bool by_index = all_digits(options.device) && std::to_string(i) == options.device;
      if (!by_index && lower(name).find(lower(options.device)) == std::string::npos) continue;
    }
    auto reject = [&](const std::string& why) { rejected += (rejected.empty() ? "" : "; ") + name + ": " + why; };
    gpu::DeviceFeatures features;
    if (Status s = gpu::DeviceFeatures::for_device(devices[i], features); !s) {
      reject(s.message());
      continue;
    }
    if (window_ && !has_device_extension(devices[i], VK_KHR_SWAPCHAIN_EXTENSION_NAME)) {
      reject("no VK_KHR_swapchain");
      continue;
    }
    uint32_t nf = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(devices[i], &nf, nullptr);
    std::vector<VkQueueFamilyProperties> families(nf);
    vkGetPhysicalDeviceQueueFamilyProperties(devices[i], &nf, families.data());
    uint32_t family = UINT32_MAX;
    for (uint32_t f = 0; f < nf && family == UINT32_MAX; ++f) {
      const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
      if ((families[f].queueFlags & need) != need) continue;
      VkBool32 present = VK_TRUE;
      if (surface_) vkGetPhysicalDeviceSurfaceSupportKHR(devices[i], f, surface_, &present);
      if (present) family = f;
    }
    if (family == UINT32_MAX) {
      reject("no graphics+compute queue family that can present to the window");
      continue;
    }
    const int rank = type_rank(props.deviceType);
    if (rank < best_rank) {
      best_rank = rank;
      physical_ = devices[i];
      family_ = family;
      enabled_ = features;
      device_name_ = name;
    }
  }
  if (physical_) return {};
  if (!options.device.empty() && rejected.empty())
    return Status::error("--device '" + options.device + "': no Vulkan device with that index or name");
  return Status::unsupported("no Vulkan device can run the viewer" +
                             (rejected.empty() ? std::string() : ": " + rejected));
}

Status WindowDevice::create_device() {
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue_info.queueFamilyIndex = family_;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;
  const char* extensions[] = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  info.pNext = enabled_.link();
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue_info;
  info.enabledExtensionCount = window_ ? 1u : 0u;
  info.ppEnabledExtensionNames = extensions;
  if (Status s = gpu::vk_check(vkCreateDevice(physical_, &info, nullptr, &device_), "vkCreateDevice", device_name_); !s)
    return s;
  vkGetDeviceQueue(device_, family_, 0, &queue_);
  return {};
}

gpu::ExternalDevice WindowDevice::external() const {
  gpu::ExternalDevice e;
  e.instance = instance_;
  e.physical_device = physical_;
  e.device = device_;
  e.queue_family = family_;
  e.queue = queue_;
  e.enabled = enabled_;
  e.enabled.link();  // the copy's chain must point into the copy
  return e;
}

uint32_t WindowDevice::find_memory_type(uint32_t type_bits, VkMemoryPropertyFlags required) const {
  VkPhysicalDeviceMemoryProperties memory;
  vkGetPhysicalDeviceMemoryProperties(physical_, &memory);
  for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
    if ((type_bits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & required) == required) return i;
  return UINT32_MAX;
}

std::vector<std::string> WindowDevice::take_validation_messages() {
  std::lock_guard<std::mutex> lock(log_->mutex);
  return std::exchange(log_->messages, {});
}

WindowDevice::~WindowDevice() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    vkDestroyDevice(device_, nullptr);
  }
  if (surface_) vkDestroySurfaceKHR(instance_, surface_, nullptr);
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
  }
  if (instance_) vkDestroyInstance(instance_, nullptr);
  if (window_) glfwDestroyWindow(window_);
  if (glfw_) glfwTerminate();
}

}  // namespace lintel::view
