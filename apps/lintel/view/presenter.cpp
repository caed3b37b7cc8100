// Frames in flight and presentation for `lintel view` (see presenter.h). Synchronization:
// the slot's fence guards its command buffer and buffers; the acquire semaphore makes the copy
// wait for the presentation engine; the per-image render-finished semaphore makes presentation
// wait for the copy (per image, not per slot, because an image can come back before its slot).
#include "presenter.h"

#include "vk_status.h"

#include <algorithm>
#include <cstring>

namespace lintel::view {
namespace {

VkImageMemoryBarrier2 image_barrier(VkImage image, VkImageLayout from, VkImageLayout to,
                                    VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                                    VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
  VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  b.srcStageMask = src_stage;
  b.srcAccessMask = src_access;
  b.dstStageMask = dst_stage;
  b.dstAccessMask = dst_access;
  b.oldLayout = from;
  b.newLayout = to;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  return b;
}

void barrier(VkCommandBuffer cmd, const VkImageMemoryBarrier2* image, const VkBufferMemoryBarrier2* buffer = nullptr) {
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.imageMemoryBarrierCount = image ? 1u : 0u;
  dep.pImageMemoryBarriers = image;
  dep.bufferMemoryBarrierCount = buffer ? 1u : 0u;
  dep.pBufferMemoryBarriers = buffer;
  vkCmdPipelineBarrier2(cmd, &dep);
}

// RGBA <-> BGRA is the same swap both ways.
void copy_pixels(const uint8_t* from, uint8_t* to, size_t pixels, bool swap_red_blue) {
  if (!swap_red_blue) {
    std::memcpy(to, from, pixels * 4);
    return;
  }
  for (size_t i = 0; i < pixels; ++i) {
    to[4 * i + 0] = from[4 * i + 2];
    to[4 * i + 1] = from[4 * i + 1];
    to[4 * i + 2] = from[4 * i + 0];
    to[4 * i + 3] = from[4 * i + 3];
  }
}

}  // namespace

Status Presenter::create(WindowDevice& device, uint32_t width, uint32_t height, std::unique_ptr<Presenter>& out) {
  out.reset();
  std::unique_ptr<Presenter> p(new Presenter(device));
  p->width_ = width;
  p->height_ = height;
  if (Status s = p->create_slots(); !s) return s;
  if (Status s = device.surface() ? p->create_swapchain() : p->create_offscreen_images(); !s) return s;
  out = std::move(p);
  return {};
}

Status Presenter::make_host_buffer(VkDeviceSize size, VkBufferUsageFlags usage, HostBuffer& out) {
  VkDevice d = dev_.device();
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  if (Status s = gpu::vk_check(vkCreateBuffer(d, &info, nullptr, &out.buffer), "vkCreateBuffer", "viewer staging"); !s)
    return s;
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(d, out.buffer, &req);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = dev_.find_memory_type(
      req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  if (alloc.memoryTypeIndex == UINT32_MAX)
    return Status::unsupported("no host-visible coherent memory for the viewer's staging");
  if (Status s = gpu::vk_check(vkAllocateMemory(d, &alloc, nullptr, &out.memory), "vkAllocateMemory", "viewer staging");
      !s)
    return s;
  if (Status s =
          gpu::vk_check(vkBindBufferMemory(d, out.buffer, out.memory, 0), "vkBindBufferMemory", "viewer staging");
      !s)
    return s;
  return gpu::vk_check(vkMapMemory(d, out.memory, 0, VK_WHOLE_SIZE, 0, &out.mapped), "vkMapMemory", "viewer staging");
}

void Presenter::destroy_host_buffer(HostBuffer& b) {
  if (b.buffer) vkDestroyBuffer(dev_.device(), b.buffer, nullptr);
  if (b.memory) vkFreeMemory(dev_.device(), b.memory, nullptr);
  b = {};
}

Status Presenter::create_slots() {
  VkDevice d = dev_.device();
  VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool.queueFamilyIndex = dev_.queue_family();
  if (Status s = gpu::vk_check(vkCreateCommandPool(d, &pool, nullptr, &pool_), "vkCreateCommandPool", "viewer frames");
      !s)
    return s;
  const VkDeviceSize bytes = VkDeviceSize(width_) * height_ * 4;
  for (Slot& slot : slots_) {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool_;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    if (Status s =
            gpu::vk_check(vkAllocateCommandBuffers(d, &alloc, &slot.cmd), "vkAllocateCommandBuffers", "viewer frames");
        !s)
      return s;
    VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fence.flags = VK_FENCE_CREATE_SIGNALED_BIT;  // the first wait on a slot returns at once
    if (Status s = gpu::vk_check(vkCreateFence(d, &fence, nullptr, &slot.fence), "vkCreateFence", "viewer frames"); !s)
      return s;
    VkSemaphoreCreateInfo sem{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    if (Status s = gpu::vk_check(vkCreateSemaphore(d, &sem, nullptr, &slot.image_available), "vkCreateSemaphore",
                                 "viewer frames");
        !s)
      return s;
    if (Status s = make_host_buffer(bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, slot.staging); !s) return s;
    if (Status s = make_host_buffer(bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, slot.readback); !s) return s;
  }
  return {};
}

Status Presenter::create_swapchain() {
  VkPhysicalDevice pd = dev_.physical_device();
  VkSurfaceKHR surface = dev_.surface();
  VkSurfaceCapabilitiesKHR caps;
  if (Status s = gpu::vk_check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(pd, surface, &caps),
                               "vkGetPhysicalDeviceSurfaceCapabilitiesKHR", "the window");
      !s)
    return s;
  if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
    return Status::unsupported("the window's swapchain images cannot be copied into (no TRANSFER_DST usage)");
  can_read_back_ = (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0;
  if (format_ == VK_FORMAT_UNDEFINED) {
    uint32_t n = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(pd, surface, &n, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(n);
    vkGetPhysicalDeviceSurfaceFormatsKHR(pd, surface, &n, formats.data());
    // The frame's bytes are already sRGB-encoded: a copy moves bits, so a UNORM or an SRGB image
    // shows them the same. Only the channel order matters.
    for (const VkSurfaceFormatKHR& f : formats) {
      if (f.colorSpace != VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) continue;
      const bool bgra = f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_B8G8R8A8_SRGB;
      const bool rgba = f.format == VK_FORMAT_R8G8B8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_SRGB;
      if (!bgra && !rgba) continue;
      format_ = f.format;
      bgra_ = bgra;
      break;
    }
    if (format_ == VK_FORMAT_UNDEFINED)
      return Status::unsupported("the window offers no 8-bit RGBA or BGRA sRGB format");
  }
  extent_ = caps.currentExtent;
  if (extent_.width == UINT32_MAX) {
    extent_.width = std::clamp(width_, caps.minImageExtent.width, caps.maxImageExtent.width);
    extent_.height = std::clamp(height_, caps.minImageExtent.height, caps.maxImageExtent.height);
  }
  uint32_t image_count = std::max(caps.minImageCount + 1, kFramesInFlight);
  if (caps.maxImageCount) image_count = std::min(image_count, caps.maxImageCount);

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface;
  info.minImageCount = image_count;
  info.imageFormat = format_;
  info.imageColorSpace = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
  info.imageExtent = extent_;
  info.imageArrayLayers = 1;
  info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                    (can_read_back_ ? VkImageUsageFlags(VK_IMAGE_USAGE_TRANSFER_SRC_BIT) : VkImageUsageFlags(0));
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  if (!(caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR))
    info.compositeAlpha = VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha & -caps.supportedCompositeAlpha);
  info.presentMode = VK_PRESENT_MODE_FIFO_KHR;  // always supported
  info.clipped = VK_TRUE;
  const VkSwapchainKHR old = swapchain_;
  info.oldSwapchain = old;
  VkDevice d = dev_.device();
  if (Status s =
          gpu::vk_check(vkCreateSwapchainKHR(d, &info, nullptr, &swapchain_), "vkCreateSwapchainKHR", "the window");
      !s)
    return s;
  if (old) vkDestroySwapchainKHR(d, old, nullptr);
  uint32_t n = 0;
  vkGetSwapchainImagesKHR(d, swapchain_, &n, nullptr);
  images_.resize(n);
  vkGetSwapchainImagesKHR(d, swapchain_, &n, images_.data());
  render_finished_.resize(n);
  for (VkSemaphore& sem : render_finished_) {
    VkSemaphoreCreateInfo si{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    if (Status s = gpu::vk_check(vkCreateSemaphore(d, &si, nullptr, &sem), "vkCreateSemaphore", "viewer frames"); !s)
      return s;
  }
  return {};
}

Status Presenter::create_offscreen_images() {
  VkDevice d = dev_.device();
  format_ = VK_FORMAT_R8G8B8A8_UNORM;
  bgra_ = false;
  extent_ = {width_, height_};
  images_.resize(kFramesInFlight);
  offscreen_memory_.resize(kFramesInFlight);
  for (uint32_t i = 0; i < kFramesInFlight; ++i) {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format_;
    info.extent = {width_, height_, 1};
    info.mipLevels = info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    if (Status s = gpu::vk_check(vkCreateImage(d, &info, nullptr, &images_[i]), "vkCreateImage", "offscreen frame"); !s)
      return s;
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(d, images_[i], &req);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = dev_.find_memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (alloc.memoryTypeIndex == UINT32_MAX) alloc.memoryTypeIndex = dev_.find_memory_type(req.memoryTypeBits, 0);
    if (Status s = gpu::vk_check(vkAllocateMemory(d, &alloc, nullptr, &offscreen_memory_[i]), "vkAllocateMemory",
                                 "offscreen frame");
        !s)
      return s;
    if (Status s = gpu::vk_check(vkBindImageMemory(d, images_[i], offscreen_memory_[i], 0), "vkBindImageMemory",
                                 "offscreen frame");
        !s)
      return s;
  }
  return {};
}

void Presenter::destroy_swapchain_images() {
  VkDevice d = dev_.device();
  for (VkSemaphore s : render_finished_) vkDestroySemaphore(d, s, nullptr);
  render_finished_.clear();
  if (!swapchain_) {
    for (VkImage i : images_) vkDestroyImage(d, i, nullptr);
    for (VkDeviceMemory m : offscreen_memory_) vkFreeMemory(d, m, nullptr);
    offscreen_memory_.clear();
  }
  images_.clear();
}

void Presenter::record(Slot& slot, VkImage image, bool readback) {
  VkCommandBuffer cmd = slot.cmd;
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkBeginCommandBuffer(cmd, &begin);
  const VkPipelineStageFlags2 transfer = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
  // Old contents are discarded (UNDEFINED); the source scope covers this image's previous copy
  // when the image is an offscreen one reused without a semaphore.
  VkImageMemoryBarrier2 to_dst = image_barrier(image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                               transfer, VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_TRANSFER_READ_BIT,
                                               transfer, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  barrier(cmd, &to_dst);
  const uint32_t w = std::min(width_, extent_.width), h = std::min(height_, extent_.height);
  if (w != extent_.width || h != extent_.height) {
    // The window is not the frame's size (a window manager chose): black around the frame.
    const VkClearColorValue black{};
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &black, 1, &range);
    VkImageMemoryBarrier2 after_clear =
        image_barrier(image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, transfer,
                      VK_ACCESS_2_TRANSFER_WRITE_BIT, transfer, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    barrier(cmd, &after_clear);
  }
  VkBufferImageCopy region{};
  region.bufferRowLength = width_;
  region.bufferImageHeight = height_;
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {w, h, 1};
  vkCmdCopyBufferToImage(cmd, slot.staging.buffer, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);

  const bool presenting = swapchain_ != VK_NULL_HANDLE;
  const VkImageLayout final_layout =
      presenting ? VK_IMAGE_LAYOUT_PRESENT_SRC_KHR : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  if (readback) {
    VkImageMemoryBarrier2 to_src =
        image_barrier(image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, transfer,
                      VK_ACCESS_2_TRANSFER_WRITE_BIT, transfer, VK_ACCESS_2_TRANSFER_READ_BIT);
    barrier(cmd, &to_src);
    vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, slot.readback.buffer, 1, &region);
    VkBufferMemoryBarrier2 to_host{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
    to_host.srcStageMask = transfer;
    to_host.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    to_host.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
    to_host.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
    to_host.srcQueueFamilyIndex = to_host.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    to_host.buffer = slot.readback.buffer;
    to_host.size = VK_WHOLE_SIZE;
    VkImageMemoryBarrier2 to_final = image_barrier(image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, final_layout, transfer,
                                                   0, VK_PIPELINE_STAGE_2_NONE, 0);
    barrier(cmd, final_layout == VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL ? nullptr : &to_final, &to_host);
  } else {
    VkImageMemoryBarrier2 to_final = image_barrier(image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, final_layout, transfer,
                                                   VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_NONE, 0);
    barrier(cmd, &to_final);
  }
  vkEndCommandBuffer(cmd);
}

Status Presenter::present(std::span<const uint8_t> rgba8, std::vector<uint8_t>* readback) {
  if (rgba8.size() != size_t(width_) * height_ * 4) return Status::internal("viewer frame of the wrong size");
  VkDevice d = dev_.device();
  Slot& slot = slots_[frame_ % kFramesInFlight];
  if (Status s =
          gpu::vk_check(vkWaitForFences(d, 1, &slot.fence, VK_TRUE, UINT64_MAX), "vkWaitForFences", "viewer frame");
      !s)
    return s;
  uint32_t index = uint32_t(frame_ % kFramesInFlight);
  if (swapchain_) {
    const VkResult r = vkAcquireNextImageKHR(d, swapchain_, UINT64_MAX, slot.image_available, VK_NULL_HANDLE, &index);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) {
      // The window changed under us: a new swapchain, and this frame is dropped (a screenshot of
      // it is the frame as it would have been uploaded).
      if (readback) readback->assign(rgba8.begin(), rgba8.end());
      if (Status s = gpu::vk_check(vkDeviceWaitIdle(d), "vkDeviceWaitIdle", "the window"); !s) return s;
      destroy_swapchain_images();
      return create_swapchain();
    }
    if (r != VK_SUBOPTIMAL_KHR)
      if (Status s = gpu::vk_check(r, "vkAcquireNextImageKHR", "the window"); !s) return s;
  }
  if (Status s = gpu::vk_check(vkResetFences(d, 1, &slot.fence), "vkResetFences", "viewer frame"); !s) return s;
  copy_pixels(rgba8.data(), static_cast<uint8_t*>(slot.staging.mapped), size_t(width_) * height_, bgra_);
  const bool read_back = readback && (can_read_back_ || !swapchain_);
  record(slot, images_[index], read_back);

  VkCommandBufferSubmitInfo cmd_info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cmd_info.commandBuffer = slot.cmd;
  VkSemaphoreSubmitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  wait.semaphore = slot.image_available;
  wait.stageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
  VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &cmd_info;
  if (swapchain_) {
    signal.semaphore = render_finished_[index];
    submit.waitSemaphoreInfoCount = submit.signalSemaphoreInfoCount = 1;
    submit.pWaitSemaphoreInfos = &wait;
    submit.pSignalSemaphoreInfos = &signal;
  }
  if (Status s = gpu::vk_check(vkQueueSubmit2(dev_.queue(), 1, &submit, slot.fence), "vkQueueSubmit2", "viewer frame");
      !s)
    return s;
  bool recreate = false;
  if (swapchain_) {
    VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    info.waitSemaphoreCount = 1;
    info.pWaitSemaphores = &render_finished_[index];
    info.swapchainCount = 1;
    info.pSwapchains = &swapchain_;
    info.pImageIndices = &index;
    const VkResult r = vkQueuePresentKHR(dev_.queue(), &info);
    recreate = r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR;
    if (!recreate)
      if (Status s = gpu::vk_check(r, "vkQueuePresentKHR", "the window"); !s) return s;
  }
  ++frame_;
  if (readback) {
    readback->resize(rgba8.size());
    if (read_back) {
      if (Status s =
              gpu::vk_check(vkWaitForFences(d, 1, &slot.fence, VK_TRUE, UINT64_MAX), "vkWaitForFences", "screenshot");
          !s)
        return s;
      copy_pixels(static_cast<const uint8_t*>(slot.readback.mapped), readback->data(), size_t(width_) * height_, bgra_);
    } else {
      // The surface does not let its images be read: the frame as uploaded.
      std::memcpy(readback->data(), rgba8.data(), rgba8.size());
    }
  }
  if (recreate) {
    if (Status s = gpu::vk_check(vkDeviceWaitIdle(d), "vkDeviceWaitIdle", "the window"); !s) return s;
    destroy_swapchain_images();
    return create_swapchain();
  }
  return {};
}

Status Presenter::wait_idle() {
  VkFence fences[kFramesInFlight];
  for (uint32_t i = 0; i < kFramesInFlight; ++i) fences[i] = slots_[i].fence;
  return gpu::vk_check(vkWaitForFences(dev_.device(), kFramesInFlight, fences, VK_TRUE, UINT64_MAX), "vkWaitForFences",
                       "viewer frames");
}

Presenter::~Presenter() {
  VkDevice d = dev_.device();
  vkDeviceWaitIdle(d);
  destroy_swapchain_images();
  if (swapchain_) vkDestroySwapchainKHR(d, swapchain_, nullptr);
  for (Slot& slot : slots_) {
    if (slot.fence) vkDestroyFence(d, slot.fence, nullptr);
    if (slot.image_available) vkDestroySemaphore(d, slot.image_available, nullptr);
    destroy_host_buffer(slot.staging);
    destroy_host_buffer(slot.readback);
  }
  if (pool_) vkDestroyCommandPool(d, pool_, nullptr);
}

}  // namespace lintel::view
