// Puts the renderer's RGBA8 frames on the window: a swapchain and kFramesInFlight frame slots
// (per slot a command buffer, a fence, an image-available semaphore and a host-visible staging
// buffer; per swapchain image a render-finished semaphore). Each frame is copied into the staging
// buffer of its slot, copied into the acquired image and presented; the CPU waits only for the
// slot's previous use. Offscreen, two images of the viewer's own stand in for the swapchain.
// A screenshot copies the image back after the upload: what was presented, not the CPU frame.
#pragma once

#include "window_device.h"

#include <cstdint>
#include <span>
#include <vector>

namespace lintel::view {

inline constexpr uint32_t kFramesInFlight = 2;

class Presenter {
 public:
  // Errors: the surface offers no 8-bit RGBA/BGRA format or no transfer-destination usage
  // (Unsupported), Vulkan failures.
  static Status create(WindowDevice& device, uint32_t width, uint32_t height, std::unique_ptr<Presenter>& out);
  ~Presenter();
  Presenter(const Presenter&) = delete;
  Presenter& operator=(const Presenter&) = delete;

  // Uploads `rgba8` (width x height x 4, row 0 at the top) and presents it. With `readback`,
  // also reads the presented image back into it as RGBA8 (waits for this frame's copy). A frame
  // dropped because the swapchain was out of date (it is recreated) reads back as `rgba8`.
  Status present(std::span<const uint8_t> rgba8, std::vector<uint8_t>* readback);
  // Waits until no slot is in use (before the renderer is rebuilt, and at the end).
  Status wait_idle();
  uint64_t frames_presented() const { return frame_; }
  VkFormat format() const { return format_; }

 private:
  struct HostBuffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr;
  };
  struct Slot {
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;
    VkSemaphore image_available = VK_NULL_HANDLE;
    HostBuffer staging, readback;
  };
  explicit Presenter(WindowDevice& device) : dev_(device) {}
  Status create_slots();
  Status create_swapchain();
  Status create_offscreen_images();
  void destroy_swapchain_images();
  Status make_host_buffer(VkDeviceSize size, VkBufferUsageFlags usage, HostBuffer& out);
  void destroy_host_buffer(HostBuffer& b);
  void record(Slot& slot, VkImage image, bool readback);

  WindowDevice& dev_;
  uint32_t width_ = 0, height_ = 0;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  bool bgra_ = false;          // the image stores B, G, R, A: swizzle on the way in and out
  bool can_read_back_ = true;  // swapchain images allow TRANSFER_SRC
  VkExtent2D extent_{};
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  std::vector<VkImage> images_;
  std::vector<VkSemaphore> render_finished_;  // one per swapchain image
  std::vector<VkDeviceMemory> offscreen_memory_;
  Slot slots_[kFramesInFlight];
  uint64_t frame_ = 0;
};

}  // namespace lintel::view
