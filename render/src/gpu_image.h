// A VkImage with its own memory and views: the whole image (2D or 2D array) and, for layered
// render targets, one 2D view per layer. Move-only; destroys itself. Few, large images per
// renderer, so one allocation each is simple.
#pragma once

#include <lintel/gpu/context.h>
#include <lintel/status.h>

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

namespace lintel::render {

struct ImageDesc {
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  uint32_t width = 1, height = 1, layers = 1;
  VkImageUsageFlags usage = 0;
  bool per_layer_views = false;  // one 2D view per layer (layered render targets)
  bool array_view = false;       // view() is a 2D array even with one layer (sampler2DArray)
  uint32_t mip_levels = 1;       // view() covers every level; per-layer views level 0 only
};

class GpuImage {
 public:
  GpuImage() = default;
  ~GpuImage() { reset(); }
  GpuImage(GpuImage&& other) noexcept { *this = std::move(other); }
  GpuImage& operator=(GpuImage&& other) noexcept;
  GpuImage(const GpuImage&) = delete;
  GpuImage& operator=(const GpuImage&) = delete;

  // `label` names the image in error messages.
  static Status create(const gpu::Context& ctx, const ImageDesc& desc, const char* label, GpuImage& out);
  void reset();

  VkImage handle() const { return image_; }
  VkImageView view() const { return view_; }  // all layers (2D when layers == 1 unless array_view, else 2D array)
  VkImageView layer_view(uint32_t layer) const { return layer_views_[layer]; }
  const ImageDesc& desc() const { return desc_; }
  VkImageAspectFlags aspect() const;
  explicit operator bool() const { return image_ != VK_NULL_HANDLE; }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  std::vector<VkImageView> layer_views_;
  ImageDesc desc_;
};

bool is_depth_format(VkFormat format);

}  // namespace lintel::render
