// The raster test's renderer. Every barrier is explicit (lavapipe would forgive a missing one;
// the synchronization validation the tests run under does not).
#include "id_raster.h"

#include "shader_pipeline.h"
#include "gpu_cull_raster_test_spirv.h"
#include "vk_status.h"

#include <cstring>

namespace lintel::gpu::test {
namespace {

Status upload(Context& ctx, const void* data, VkDeviceSize bytes, VkBufferUsageFlags usage, const char* label,
              Buffer& out) {
  if (Status s = Buffer::create(ctx, bytes, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Device, label, out);
      !s)
    return s;
  Buffer staging;
  if (Status s = Buffer::create(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Upload, label, staging); !s)
    return s;
  std::memcpy(staging.mapped(), data, bytes);
  return ctx.submit_and_wait(
      [&](VkCommandBuffer cmd) {
        VkBufferCopy copy{0, 0, bytes};
        vkCmdCopyBuffer(cmd, staging.handle(), out.handle(), 1, &copy);
        VkMemoryBarrier2 mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
        mb.srcStageMask = VK_PIPELINE_STAGE_2_TRANSFER_BIT;
        mb.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        mb.dstStageMask = VK_PIPELINE_STAGE_2_VERTEX_INPUT_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT;
        mb.dstAccessMask =
            VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_2_INDEX_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT;
        VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dep.memoryBarrierCount = 1;
        dep.pMemoryBarriers = &mb;
        vkCmdPipelineBarrier2(cmd, &dep);
      },
      label);
}

}  // namespace

uint32_t IdRaster::pixel_index(glm::vec2 p) {
  const uint32_t x = uint32_t((p.x + 1.0f) * 0.5f * float(kSize));
  const uint32_t y = uint32_t((p.y + 1.0f) * 0.5f * float(kSize));
  return y * kSize + x;
}

IdRaster::~IdRaster() {
  if (!ctx_) return;
  VkDevice d = ctx_->device();
  vkDeviceWaitIdle(d);
  if (pool_) vkDestroyDescriptorPool(d, pool_, nullptr);
  if (pipeline_) vkDestroyPipeline(d, pipeline_, nullptr);
  if (layout_) vkDestroyPipelineLayout(d, layout_, nullptr);
  if (set_layout_) vkDestroyDescriptorSetLayout(d, set_layout_, nullptr);
  if (view_) vkDestroyImageView(d, view_, nullptr);
  if (image_) vkDestroyImage(d, image_, nullptr);
  if (image_memory_) vkFreeMemory(d, image_memory_, nullptr);
}

Status IdRaster::init(Context& ctx, const std::vector<glm::vec3>& vertices, const std::vector<uint32_t>& indices,
                      const std::vector<glm::vec2>& offsets_ndc) {
  ctx_ = &ctx;
  VkDevice d = ctx.device();
  Status s = upload(ctx, vertices.data(), vertices.size() * sizeof(glm::vec3), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                    "raster vertices", vertices_);
  if (s)
    s = upload(ctx, indices.data(), indices.size() * 4, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, "raster indices", indices_);
  std::vector<glm::vec4> offsets;
  for (const glm::vec2& o : offsets_ndc) offsets.emplace_back(o, 0.0f, 0.0f);
  if (s)
    s = upload(ctx, offsets.data(), offsets.size() * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
               "raster offsets", offsets_);
  if (s)
    s = Buffer::create(ctx, VkDeviceSize(kSize) * kSize * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Readback,
                       "raster readback", readback_);
  if (!s) return s;

  VkImageCreateInfo image_info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  image_info.imageType = VK_IMAGE_TYPE_2D;
  image_info.format = VK_FORMAT_R32_UINT;
  image_info.extent = {kSize, kSize, 1};
  image_info.mipLevels = 1;
  image_info.arrayLayers = 1;
  image_info.samples = VK_SAMPLE_COUNT_1_BIT;
  image_info.tiling = VK_IMAGE_TILING_OPTIMAL;
  image_info.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  if (s = vk_check(vkCreateImage(d, &image_info, nullptr, &image_), "vkCreateImage", "id target"); !s) return s;
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(d, image_, &req);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = ctx.find_memory_type(req.memoryTypeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  if (s = vk_check(vkAllocateMemory(d, &alloc, nullptr, &image_memory_), "vkAllocateMemory", "id target"); !s) return s;
  vkBindImageMemory(d, image_, image_memory_, 0);
  VkImageViewCreateInfo view_info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  view_info.image = image_;
  view_info.viewType = VK_IMAGE_VIEW_TYPE_2D;
  view_info.format = VK_FORMAT_R32_UINT;
  view_info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  if (s = vk_check(vkCreateImageView(d, &view_info, nullptr, &view_), "vkCreateImageView", "id target"); !s) return s;

  VkDescriptorSetLayoutBinding bindings[2] = {};
  for (uint32_t b = 0; b < 2; ++b) {
    bindings[b].binding = b;
    bindings[b].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    bindings[b].descriptorCount = 1;
    bindings[b].stageFlags = VK_SHADER_STAGE_VERTEX_BIT;
  }
  VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set_info.bindingCount = 2;
  set_info.pBindings = bindings;
  if (s = vk_check(vkCreateDescriptorSetLayout(d, &set_info, nullptr, &set_layout_), "vkCreateDescriptorSetLayout",
                   "raster");
      !s)
    return s;
  VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &set_layout_;
  if (s = vk_check(vkCreatePipelineLayout(d, &layout_info, nullptr, &layout_), "vkCreatePipelineLayout", "raster"); !s)
    return s;
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2};
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = 1;
  pool_info.pPoolSizes = &size;
  if (s = vk_check(vkCreateDescriptorPool(d, &pool_info, nullptr, &pool_), "vkCreateDescriptorPool", "raster"); !s)
    return s;
  VkDescriptorSetAllocateInfo set_alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  set_alloc.descriptorPool = pool_;
  set_alloc.descriptorSetCount = 1;
  set_alloc.pSetLayouts = &set_layout_;
  if (s = vk_check(vkAllocateDescriptorSets(d, &set_alloc, &set_), "vkAllocateDescriptorSets", "raster"); !s) return s;

  VkShaderModule vert = VK_NULL_HANDLE, frag = VK_NULL_HANDLE;
  if (s = create_shader_module(d, spirv::draw_ids_vert(), "draw_ids.vert", vert); !s) return s;
  if (s = create_shader_module(d, spirv::draw_ids_frag(), "draw_ids.frag", frag); !s) {
    vkDestroyShaderModule(d, vert, nullptr);
    return s;
  }
  VkPipelineShaderStageCreateInfo stages[2] = {{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                               {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vert;
  stages[0].pName = "main";
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = frag;
  stages[1].pName = "main";
  VkVertexInputBindingDescription vb{0, sizeof(glm::vec3), VK_VERTEX_INPUT_RATE_VERTEX};
  VkVertexInputAttributeDescription va{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0};
  VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertex_input.vertexBindingDescriptionCount = 1;
  vertex_input.pVertexBindingDescriptions = &vb;
  vertex_input.vertexAttributeDescriptionCount = 1;
  vertex_input.pVertexAttributeDescriptions = &va;
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkViewport viewport{0.0f, 0.0f, float(kSize), float(kSize), 0.0f, 1.0f};
  VkRect2D scissor{{0, 0}, {kSize, kSize}};
  VkPipelineViewportStateCreateInfo viewport_state{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport_state.viewportCount = 1;
  viewport_state.pViewports = &viewport;
  viewport_state.scissorCount = 1;
  viewport_state.pScissors = &scissor;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineColorBlendAttachmentState blend_attachment{};
  blend_attachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT;
  VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = 1;
  blend.pAttachments = &blend_attachment;
  const VkFormat format = VK_FORMAT_R32_UINT;
  VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
  rendering.colorAttachmentCount = 1;
  rendering.pColorAttachmentFormats = &format;
  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.pNext = &rendering;
  info.stageCount = 2;
  info.pStages = stages;
  info.pVertexInputState = &vertex_input;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport_state;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pColorBlendState = &blend;
  info.layout = layout_;
  s = vk_check(vkCreateGraphicsPipelines(d, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_), "vkCreateGraphicsPipelines",
               "raster");
  vkDestroyShaderModule(d, vert, nullptr);
  vkDestroyShaderModule(d, frag, nullptr);
  return s;
}

Status IdRaster::cull_and_draw(const CullPass& pass, bool use_count, std::vector<uint32_t>& pixels) {
  if (bound_ids_ != pass.instance_ids()) {
    VkDescriptorBufferInfo infos[2] = {{pass.instance_ids(), 0, VK_WHOLE_SIZE}, {offsets_.handle(), 0, VK_WHOLE_SIZE}};
    VkWriteDescriptorSet writes[2] = {{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET},
                                      {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}};
    for (uint32_t b = 0; b < 2; ++b) {
      writes[b].dstSet = set_;
      writes[b].dstBinding = b;
      writes[b].descriptorCount = 1;
      writes[b].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      writes[b].pBufferInfo = &infos[b];
    }
    vkUpdateDescriptorSets(ctx_->device(), 2, writes, 0, nullptr);
    bound_ids_ = pass.instance_ids();
  }
  Status s = ctx_->submit_and_wait(
      [&](VkCommandBuffer cmd) {
        pass.record(cmd);  // ends with compute -> DRAW_INDIRECT + VERTEX_SHADER
        VkImageMemoryBarrier2 to_attachment{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
        to_attachment.srcStageMask = VK_PIPELINE_STAGE_2_TRANSFER_BIT;  // the previous readback
        to_attachment.srcAccessMask = VK_ACCESS_2_NONE;
        to_attachment.dstStageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
        to_attachment.dstAccessMask = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
        to_attachment.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        to_attachment.newLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        to_attachment.srcQueueFamilyIndex = to_attachment.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        to_attachment.image = image_;
        to_attachment.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dep.imageMemoryBarrierCount = 1;
        dep.pImageMemoryBarriers = &to_attachment;
        vkCmdPipelineBarrier2(cmd, &dep);

        VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        color.imageView = view_;
        color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        color.clearValue.color.uint32[0] = 0;
        VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
        rendering.renderArea = {{0, 0}, {kSize, kSize}};
        rendering.layerCount = 1;
        rendering.colorAttachmentCount = 1;
        rendering.pColorAttachments = &color;
        vkCmdBeginRendering(cmd, &rendering);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set_, 0, nullptr);
        const VkDeviceSize zero = 0;
        const VkBuffer vb = vertices_.handle();
        vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &zero);
        vkCmdBindIndexBuffer(cmd, indices_.handle(), 0, VK_INDEX_TYPE_UINT32);
        if (use_count) {
          vkCmdDrawIndexedIndirectCount(cmd, pass.compact_commands(), 0, pass.counters(), 0, pass.group_count(),
                                        sizeof(DrawIndexedCommand));
        } else if (pass.group_count()) {
          vkCmdDrawIndexedIndirect(cmd, pass.draw_commands(), 0, pass.group_count(), sizeof(DrawIndexedCommand));
        }
        vkCmdEndRendering(cmd);

        VkImageMemoryBarrier2 to_transfer = to_attachment;
        to_transfer.srcStageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
        to_transfer.srcAccessMask = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
        to_transfer.dstStageMask = VK_PIPELINE_STAGE_2_TRANSFER_BIT;
        to_transfer.dstAccessMask = VK_ACCESS_2_TRANSFER_READ_BIT;
        to_transfer.oldLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        to_transfer.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        dep.pImageMemoryBarriers = &to_transfer;
        vkCmdPipelineBarrier2(cmd, &dep);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        copy.imageExtent = {kSize, kSize, 1};
        vkCmdCopyImageToBuffer(cmd, image_, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.handle(), 1, &copy);
        VkMemoryBarrier2 to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
        to_host.srcStageMask = VK_PIPELINE_STAGE_2_TRANSFER_BIT;
        to_host.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        to_host.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
        to_host.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
        VkDependencyInfo host_dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        host_dep.memoryBarrierCount = 1;
        host_dep.pMemoryBarriers = &to_host;
        vkCmdPipelineBarrier2(cmd, &host_dep);
      },
      "raster test");
  if (!s) return s;
  pixels.resize(size_t(kSize) * kSize);
  std::memcpy(pixels.data(), readback_.mapped(), pixels.size() * 4);
  return {};
}

}  // namespace lintel::gpu::test
