#include "texel_view.h"

#include "vk_status.h"

#include <string>

namespace lintel::render {

TexelView& TexelView::operator=(TexelView&& o) noexcept {
  if (this != &o) {
    reset();
    device_ = o.device_;
    view_ = o.view_;
    o.view_ = VK_NULL_HANDLE;
  }
  return *this;
}

void TexelView::reset() {
  if (view_) vkDestroyBufferView(device_, view_, nullptr);
  view_ = VK_NULL_HANDLE;
}

Status check_texel_count(const std::string& device_name, uint64_t max_texels, uint64_t texels, const char* label) {
  if (texels <= max_texels) return {};
  return Status::unsupported("Vulkan device '" + device_name + "' reads at most " + std::to_string(max_texels) +
                             " texels from a texel buffer; the " + label + " need " + std::to_string(texels));
}

Status TexelView::create(const gpu::Context& ctx, const gpu::Buffer& buffer, const char* label, TexelView& out,
                         VkFormat format) {
  VkPhysicalDeviceProperties props{};
  vkGetPhysicalDeviceProperties(ctx.physical_device(), &props);
  const VkDeviceSize texel_bytes = format == VK_FORMAT_R32G32_UINT ? 8 : 16;
  const VkDeviceSize texels = buffer.size() / texel_bytes;
  if (Status s = check_texel_count(ctx.info().name, props.limits.maxTexelBufferElements, texels, label); !s) return s;
  VkBufferViewCreateInfo vi{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
  vi.buffer = buffer.handle();
  vi.format = format;
  vi.range = texels * texel_bytes;
  VkBufferView view = VK_NULL_HANDLE;
  if (Status s = gpu::vk_check(vkCreateBufferView(ctx.device(), &vi, nullptr, &view), "vkCreateBufferView", label); !s)
    return s;
  out.reset();
  out.device_ = ctx.device();
  out.view_ = view;
  return {};
}

}  // namespace lintel::render
