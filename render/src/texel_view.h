// A read-only buffer seen as rgba32ui texels (a uniform texel buffer view). The renderer binds the
// data its shaders read per pixel this way rather than as storage buffers: lavapipe (Mesa 22.3)
// loads a storage buffer at a per-lane index one lane at a time, in a loop with a branch per
// lane, and a texel buffer with one vector gather (docs/rendering.md, "Performance"). The
// shaders rebuild render_shared.h's structs from the texels (compute_bindings.glsl, gbuffer.frag).
#pragma once

#include <lintel/gpu/buffer.h>
#include <lintel/gpu/context.h>
#include <lintel/status.h>

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

namespace lintel::render {

// Unsupported, naming the device and `label`, when `texels` exceed the device's
// maxTexelBufferElements; ok otherwise. Checked before a view is made (TexelView::create).
Status check_texel_count(const std::string& device_name, uint64_t max_texels, uint64_t texels, const char* label);

class TexelView {
 public:
  TexelView() = default;
  ~TexelView() { reset(); }
  TexelView(TexelView&& o) noexcept : device_(o.device_), view_(o.view_) { o.view_ = VK_NULL_HANDLE; }
  TexelView& operator=(TexelView&& o) noexcept;
  TexelView(const TexelView&) = delete;
  TexelView& operator=(const TexelView&) = delete;

  // A view of all of `buffer` (created with VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT) as
  // `format`: R32G32B32A32_UINT (16-byte texels) or R32G32_UINT (8-byte texels), both required of
  // every device for texel buffers. Unsupported, naming `label`, where the device reads fewer
  // texels (maxTexelBufferElements: 65,536 at the least, 2^27 on lavapipe and NVIDIA).
  static Status create(const gpu::Context& ctx, const gpu::Buffer& buffer, const char* label, TexelView& out,
                       VkFormat format = VK_FORMAT_R32G32B32A32_UINT);

  VkBufferView handle() const { return view_; }
  void reset();

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  VkBufferView view_ = VK_NULL_HANDLE;
};

}  // namespace lintel::render
