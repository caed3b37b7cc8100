// What a game sets up before it calls Lintel, done by the viewer itself: a GLFW window (no GL
// context), its own VkInstance with GLFW's surface extensions (+ the Khronos validation layer with
// synchronization validation when asked), a physical device that can present to the window and
// has Lintel's features, and a VkDevice made with DeviceFeatures' chain + VK_KHR_swapchain.
// Lintel borrows it through external() and gpu::Context::wrap. Offscreen (no window): the same
// without surface or swapchain extension, for --script runs where there is no display.
#pragma once

#include <lintel/gpu/context.h>
#include <lintel/status.h>

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

struct GLFWwindow;

namespace lintel::view {

struct WindowDeviceOptions {
  uint32_t width = 640, height = 360;
  std::string title = "lintel view";
  bool offscreen = false;   // no window, no surface
  bool validation = false;  // VK_LAYER_KHRONOS_validation + synchronization validation
  std::string device;       // index or case-insensitive name substring; empty: best type first
};

class WindowDevice {
 public:
  // Errors: no display (Unsupported, one line saying how to run headless), no Vulkan device that
  // can present with Lintel's features (each candidate's reason named), Vulkan failures.
  static Status create(const WindowDeviceOptions& options, std::unique_ptr<WindowDevice>& out);
  ~WindowDevice();
  WindowDevice(const WindowDevice&) = delete;
  WindowDevice& operator=(const WindowDevice&) = delete;

  // The handles for gpu::Context::wrap.
  gpu::ExternalDevice external() const;
  GLFWwindow* window() const { return window_; }  // null offscreen
  VkSurfaceKHR surface() const { return surface_; }
  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physical_device() const { return physical_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  uint32_t queue_family() const { return family_; }
  const std::string& device_name() const { return device_name_; }
  uint32_t find_memory_type(uint32_t type_bits, VkMemoryPropertyFlags required) const;

  // Validation messages since the previous call (warnings and errors of any validation type).
  std::vector<std::string> take_validation_messages();

 private:
  WindowDevice() = default;
  struct MessageLog {
    std::mutex mutex;
    std::vector<std::string> messages;
  };
  static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT types,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);
  Status create_window(const WindowDeviceOptions& options);
  Status create_instance(const WindowDeviceOptions& options);
  Status pick_physical_device(const WindowDeviceOptions& options);
  Status create_device();

  std::unique_ptr<MessageLog> log_ = std::make_unique<MessageLog>();
  bool glfw_ = false;
  GLFWwindow* window_ = nullptr;
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t family_ = 0;
  gpu::DeviceFeatures enabled_;
  std::string device_name_;
};

}  // namespace lintel::view
