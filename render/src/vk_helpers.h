// Small Vulkan helpers the renderer's setup repeats: device-local buffers filled once from host
// data, one global memory barrier (setup uploads; frames get theirs from the render graph),
// descriptor set layouts from (binding, type, stages) lists, an owned pipeline, and the two
// graphics pipelines' shared state.
#pragma once

#include <lintel/gpu/buffer.h>
#include <lintel/gpu/context.h>
#include <lintel/status.h>

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <vector>

namespace lintel::render {

// A device-local buffer holding `bytes` of `data` (at least 16 bytes, zero-filled past `bytes`,
// so an empty list still makes a bindable buffer). Blocks until the copy is done and visible to
// every later command.
Status upload_buffer(gpu::Context& ctx, const void* data, VkDeviceSize bytes, VkBufferUsageFlags usage,
                     const char* label, gpu::Buffer& out);

template <typename T>
Status upload_vector(gpu::Context& ctx, const std::vector<T>& v, VkBufferUsageFlags usage, const char* label,
                     gpu::Buffer& out) {
  return upload_buffer(ctx, v.data(), v.size() * sizeof(T), usage, label, out);
}

// Copies `bytes` from `data` into `dst` (a device buffer with TRANSFER_DST, e.g. from upload_buffer)
// at `offset` through a staging buffer, then waits: for setup and between frames only.
Status write_buffer(gpu::Context& ctx, const gpu::Buffer& dst, VkDeviceSize offset, const void* data,
                    VkDeviceSize bytes, const char* label);

// One global memory barrier (vkCmdPipelineBarrier2 with a single VkMemoryBarrier2).
void memory_barrier(VkCommandBuffer cmd, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                    VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access);

// A VkPipeline that destroys itself. Move-only.
class Pipeline {
 public:
  Pipeline() = default;
  ~Pipeline() { reset(); }
  Pipeline(Pipeline&& o) noexcept : device_(o.device_), pipeline_(o.pipeline_) { o.pipeline_ = VK_NULL_HANDLE; }
  Pipeline& operator=(Pipeline&& o) noexcept {
    if (this != &o) {
      reset();
      device_ = o.device_;
      pipeline_ = o.pipeline_;
      o.pipeline_ = VK_NULL_HANDLE;
    }
    return *this;
  }
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;
  // Takes ownership of `pipeline` (created on `device`).
  void adopt(VkDevice device, VkPipeline pipeline) {
    reset();
    device_ = device;
    pipeline_ = pipeline;
  }
  void reset() {
    if (pipeline_) vkDestroyPipeline(device_, pipeline_, nullptr);
    pipeline_ = VK_NULL_HANDLE;
  }
  VkPipeline handle() const { return pipeline_; }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
};

struct BindingDesc {
  uint32_t binding;
  VkDescriptorType type;
  VkShaderStageFlags stages;
};

Status create_set_layout(VkDevice device, std::span<const BindingDesc> bindings, const char* label,
                         VkDescriptorSetLayout& out);

struct GraphicsPipelineDesc {
  std::span<const uint32_t> vertex_spirv;
  std::span<const uint32_t> fragment_spirv;  // empty: depth only
  std::vector<VkFormat> color_formats;
  VkFormat depth_format = VK_FORMAT_UNDEFINED;
  bool depth_bias = false;
  std::vector<uint32_t> fragment_spec;  // constant_id 0.. values (bools as 0/1)
  // The front face is counter-clockwise (glTF's). NONE: the g-buffer fragment shader culls
  // single-sided back faces per drawable, and shadow casters block with both faces; BACK: the
  // g-buffer of a frame whose drawables are all single-sided and unmirrored (GBufferPass).
  VkCullModeFlags cull_mode = VK_CULL_MODE_NONE;
};

// Triangle lists of Vertex (position, normal, uv, colour), culling by desc.cull_mode, depth LESS,
// dynamic viewport and scissor (the renderer flips y with a negative viewport height).
Status create_graphics_pipeline(VkDevice device, VkPipelineLayout layout, const GraphicsPipelineDesc& desc,
                                const char* label, VkPipeline& out);

}  // namespace lintel::render
