#include "vk_helpers.h"

#include "shader_pipeline.h"
#include "vk_status.h"
#include "render_scene.h"

#include <algorithm>
#include <cstring>

namespace lintel::render {

Status upload_buffer(gpu::Context& ctx, const void* data, VkDeviceSize bytes, VkBufferUsageFlags usage,
                     const char* label, gpu::Buffer& out) {
  const VkDeviceSize size = std::max<VkDeviceSize>(bytes, 16);
  if (Status s =
          gpu::Buffer::create(ctx, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Device, label, out);
      !s)
    return s;
  gpu::Buffer staging;
  if (Status s =
          gpu::Buffer::create(ctx, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryUse::Upload, label, staging);
      !s)
    return s;
  std::memset(staging.mapped(), 0, size);
  if (bytes) std::memcpy(staging.mapped(), data, bytes);
  return ctx.submit_and_wait(
      [&](VkCommandBuffer cmd) {
        VkBufferCopy copy{0, 0, size};
        vkCmdCopyBuffer(cmd, staging.handle(), out.handle(), 1, &copy);
        memory_barrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT);
      },
      label);
}

Status write_buffer(gpu::Context& ctx, const gpu::Buffer& dst, VkDeviceSize offset, const void* data,
                    VkDeviceSize bytes, const char* label) {
  if (bytes == 0) return {};
  gpu::Buffer staging;
  if (Status s =
          gpu::Buffer::create(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryUse::Upload, label, staging);
      !s)
    return s;
  std::memcpy(staging.mapped(), data, bytes);
  return ctx.submit_and_wait(
      [&](VkCommandBuffer cmd) {
        // After every earlier use of `dst`, before every later one.
        memory_barrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                       VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                       VK_ACCESS_2_TRANSFER_WRITE_BIT);
        VkBufferCopy copy{0, offset, bytes};
        vkCmdCopyBuffer(cmd, staging.handle(), dst.handle(), 1, &copy);
        memory_barrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT);
      },
      label);
}

void memory_barrier(VkCommandBuffer cmd, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                    VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
  VkMemoryBarrier2 mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  mb.srcStageMask = src_stage;
  mb.srcAccessMask = src_access;
  mb.dstStageMask = dst_stage;
  mb.dstAccessMask = dst_access;
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.memoryBarrierCount = 1;
  dep.pMemoryBarriers = &mb;
  vkCmdPipelineBarrier2(cmd, &dep);
}

Status create_set_layout(VkDevice device, std::span<const BindingDesc> bindings, const char* label,
                         VkDescriptorSetLayout& out) {
  std::vector<VkDescriptorSetLayoutBinding> b;
  for (const BindingDesc& d : bindings) b.push_back({d.binding, d.type, 1, d.stages, nullptr});
  VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  info.bindingCount = uint32_t(b.size());
  info.pBindings = b.data();
  return gpu::vk_check(vkCreateDescriptorSetLayout(device, &info, nullptr, &out), "vkCreateDescriptorSetLayout", label);
}

Status create_graphics_pipeline(VkDevice device, VkPipelineLayout layout, const GraphicsPipelineDesc& desc,
                                const char* label, VkPipeline& out) {
  VkShaderModule vert = VK_NULL_HANDLE, frag = VK_NULL_HANDLE;
  if (Status s = gpu::create_shader_module(device, desc.vertex_spirv, label, vert); !s) return s;
  if (!desc.fragment_spirv.empty()) {
    if (Status s = gpu::create_shader_module(device, desc.fragment_spirv, label, frag); !s) {
      vkDestroyShaderModule(device, vert, nullptr);
      return s;
    }
  }
  std::vector<VkSpecializationMapEntry> entries;
  for (uint32_t i = 0; i < desc.fragment_spec.size(); ++i) entries.push_back({i, i * 4, 4});
  VkSpecializationInfo spec{uint32_t(entries.size()), entries.data(), desc.fragment_spec.size() * 4,
                            desc.fragment_spec.data()};
  VkPipelineShaderStageCreateInfo stages[2] = {{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                               {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vert;
  stages[0].pName = "main";
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = frag;
  stages[1].pName = "main";
  stages[1].pSpecializationInfo = entries.empty() ? nullptr : &spec;

  VkVertexInputBindingDescription vb{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
  VkVertexInputAttributeDescription va[4] = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position_mesh)},
                                             {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, normal_mesh)},
                                             {2, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(Vertex, uv)},
                                             {3, 0, VK_FORMAT_R16G16B16A16_UNORM, offsetof(Vertex, color)}};
  VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertex_input.vertexBindingDescriptionCount = 1;
  vertex_input.pVertexBindingDescriptions = &vb;
  vertex_input.vertexAttributeDescriptionCount = 4;
  vertex_input.pVertexAttributeDescriptions = va;
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = desc.cull_mode;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  raster.depthBiasEnable = desc.depth_bias ? VK_TRUE : VK_FALSE;
  raster.depthBiasConstantFactor = 1.0f;
  raster.depthBiasSlopeFactor = 1.5f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = VK_TRUE;
  depth.depthWriteEnable = VK_TRUE;
  depth.depthCompareOp = VK_COMPARE_OP_LESS;
  std::vector<VkPipelineColorBlendAttachmentState> blend_attachments(desc.color_formats.size());
  for (auto& a : blend_attachments)
    a.colorWriteMask =
        VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = uint32_t(blend_attachments.size());
  blend.pAttachments = blend_attachments.data();
  const VkDynamicState dynamic_states[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamic_states;
  VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
  rendering.colorAttachmentCount = uint32_t(desc.color_formats.size());
  rendering.pColorAttachmentFormats = desc.color_formats.data();
  rendering.depthAttachmentFormat = desc.depth_format;
  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.pNext = &rendering;
  info.stageCount = frag ? 2 : 1;
  info.pStages = stages;
  info.pVertexInputState = &vertex_input;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = layout;
  Status s = gpu::vk_check(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &out),
                           "vkCreateGraphicsPipelines", label);
  vkDestroyShaderModule(device, vert, nullptr);
  if (frag) vkDestroyShaderModule(device, frag, nullptr);
  return s;
}

}  // namespace lintel::render
