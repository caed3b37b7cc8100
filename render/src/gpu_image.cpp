// Image creation: device-local memory, views for the whole image and optionally per layer.
#include "gpu_image.h"

#include "vk_status.h"

#include <utility>

namespace lintel::render {

bool is_depth_format(VkFormat format) {
  return format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D16_UNORM || format == VK_FORMAT_D24_UNORM_S8_UINT ||
         format == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

VkImageAspectFlags GpuImage::aspect() const {
  return is_depth_format(desc_.format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

GpuImage& GpuImage::operator=(GpuImage&& other) noexcept {
  if (this != &other) {
    reset();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    image_ = std::exchange(other.image_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    view_ = std::exchange(other.view_, VK_NULL_HANDLE);
    layer_views_ = std::move(other.layer_views_);
    desc_ = other.desc_;
  }
  return *this;
}

void GpuImage::reset() {
  if (device_) {
    for (VkImageView v : layer_views_) vkDestroyImageView(device_, v, nullptr);
    if (view_) vkDestroyImageView(device_, view_, nullptr);
    if (image_) vkDestroyImage(device_, image_, nullptr);
    if (memory_) vkFreeMemory(device_, memory_, nullptr);
  }
  layer_views_.clear();
  device_ = VK_NULL_HANDLE;
  image_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  view_ = VK_NULL_HANDLE;
}

Status GpuImage::create(const gpu::Context& ctx, const ImageDesc& desc, const char* label, GpuImage& out) {
  out.reset();
  GpuImage img;
  img.device_ = ctx.device();
  img.desc_ = desc;
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = desc.format;
  info.extent = {desc.width, desc.height, 1};
  info.mipLevels = desc.mip_levels;
  info.arrayLayers = desc.layers;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = desc.usage;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  if (Status s = gpu::vk_check(vkCreateImage(img.device_, &info, nullptr, &img.image_), "vkCreateImage", label); !s)
    return s;
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(img.device_, img.image_, &req);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = ctx.find_memory_type(req.memoryTypeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  if (alloc.memoryTypeIndex == UINT32_MAX) return Status::unsupported(std::string("no memory type for image ") + label);
  if (Status s = gpu::vk_check(vkAllocateMemory(img.device_, &alloc, nullptr, &img.memory_), "vkAllocateMemory", label);
      !s)
    return s;
  vkBindImageMemory(img.device_, img.image_, img.memory_, 0);

  VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  view.image = img.image_;
  view.viewType = desc.layers > 1 || desc.array_view ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
  view.format = desc.format;
  view.subresourceRange = {img.aspect(), 0, desc.mip_levels, 0, desc.layers};
  if (Status s = gpu::vk_check(vkCreateImageView(img.device_, &view, nullptr, &img.view_), "vkCreateImageView", label);
      !s)
    return s;
  if (desc.per_layer_views) {
    img.layer_views_.resize(desc.layers, VK_NULL_HANDLE);
    for (uint32_t l = 0; l < desc.layers; ++l) {
      view.viewType = VK_IMAGE_VIEW_TYPE_2D;
      view.subresourceRange = {img.aspect(), 0, 1, l, 1};
      if (Status s = gpu::vk_check(vkCreateImageView(img.device_, &view, nullptr, &img.layer_views_[l]),
                                   "vkCreateImageView", label);
          !s)
        return s;
    }
  }
  out = std::move(img);
  return {};
}

}  // namespace lintel::render
