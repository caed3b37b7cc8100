// Small Vulkan helpers the renderer's setup repeats: device-local buffers filled once from host
// data, descriptor set layouts from (binding, type, stages) lists, and the two graphics pipelines'
// shared state.
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
  std::vector<uint32_t> fragment_spec;       // constant_id 0.. values (bools as 0/1)
};

// Triangle lists of Vertex (position, normal), no rasterizer culling (the g-buffer fragment shader
// culls single-sided back faces per drawable; shadow casters block with both faces), depth LESS,
// dynamic viewport and scissor (the renderer flips y with a negative viewport height).
Status create_graphics_pipeline(VkDevice device, VkPipelineLayout layout, const GraphicsPipelineDesc& desc,
                                const char* label, VkPipeline& out);

}  // namespace lintel::render
