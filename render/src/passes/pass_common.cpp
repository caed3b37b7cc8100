// The passes' shared helpers: checked pipeline creation, draw-set writes and binding, indirect
// command lists, attachments and the flipped viewport.
#include "pass_common.h"

#include "../binding_tables.h"
#include "../spirv_bindings.h"
#include "render_bindings.h"

#include "shader_pipeline.h"

namespace lintel::render {

void ComputeBinding::dispatch(VkCommandBuffer cmd, uint32_t slot, VkPipeline pipeline, const void* push,
                              uint32_t push_bytes, uint32_t x, uint32_t y) const {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 1, &sets[slot], 0, nullptr);
  vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, push_bytes, push);
  if (x && y) vkCmdDispatch(cmd, x, y, 1);
}

Status create_compute_pass_pipeline(VkDevice device, const ComputeBinding& binding, std::span<const uint32_t> spirv,
                                    const char* label, Pipeline& out, std::span<const uint32_t> spec) {
  if (Status s = check_shader_bindings(spirv, VK_SHADER_STAGE_COMPUTE_BIT, compute_set_bindings(), label); !s) return s;
  std::vector<gpu::SpecConstant> constants;
  for (uint32_t i = 0; i < spec.size(); ++i) constants.push_back({i, spec[i]});
  VkPipeline p = VK_NULL_HANDLE;
  if (Status s = gpu::create_compute_pipeline(device, binding.layout, spirv, constants, label, p); !s) return s;
  out.adopt(device, p);
  return {};
}

Status create_draw_pass_pipeline(VkDevice device, const DrawShared& shared, const GraphicsPipelineDesc& desc,
                                 const char* label, Pipeline& out) {
  if (Status s = check_shader_bindings(desc.vertex_spirv, VK_SHADER_STAGE_VERTEX_BIT, draw_set_bindings(), label); !s)
    return s;
  if (!desc.fragment_spirv.empty())
    if (Status s = check_shader_bindings(desc.fragment_spirv, VK_SHADER_STAGE_FRAGMENT_BIT, draw_set_bindings(), label);
        !s)
      return s;
  VkPipeline p = VK_NULL_HANDLE;
  if (Status s = create_graphics_pipeline(device, shared.layout, desc, label, p); !s) return s;
  out.adopt(device, p);
  return {};
}

void write_draw_set(VkDevice device, VkDescriptorSet set, const DrawShared& shared, VkBuffer ids,
                    VkBufferView link_clip) {
  const VkDescriptorBufferInfo buffers[2] = {{ids, 0, VK_WHOLE_SIZE}, {shared.fragment_counts, 0, VK_WHOLE_SIZE}};
  const uint32_t buffer_bindings[2] = {kDrawBindIds, kDrawBindCounts};
  const VkBufferView texel_views[2] = {shared.draw_instances, link_clip};
  const uint32_t texel_bindings[2] = {kDrawBindInstances, kDrawBindLinkClip};
  const VkDescriptorImageInfo textures{shared.texture_sampler, shared.textures,
                                       VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  VkWriteDescriptorSet writes[5];
  for (int i = 0; i < 5; ++i) {
    writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[i].dstSet = set;
    writes[i].descriptorCount = 1;
  }
  for (int i = 0; i < 2; ++i) {
    writes[i].dstBinding = buffer_bindings[i];
    writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[i].pBufferInfo = &buffers[i];
    writes[2 + i].dstBinding = texel_bindings[i];
    writes[2 + i].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
    writes[2 + i].pTexelBufferView = &texel_views[i];
  }
  writes[4].dstBinding = kDrawBindTextures;
  writes[4].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  writes[4].pImageInfo = &textures;
  vkUpdateDescriptorSets(device, 5, writes, 0, nullptr);
}

void bind_draw(VkCommandBuffer cmd, const DrawShared& shared, VkPipeline pipeline, VkDescriptorSet set,
               const GBufferPush& push) {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, shared.layout, 0, 1, &set, 0, nullptr);
  vkCmdPushConstants(cmd, shared.layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(push),
                     &push);
  const VkDeviceSize zero = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &shared.vertices, &zero);
  vkCmdBindIndexBuffer(cmd, shared.indices, 0, VK_INDEX_TYPE_UINT32);
}

CommandRange append_commands(const RenderScene& scene, const std::vector<uint32_t>& drawables,
                             std::vector<gpu::DrawIndexedCommand>& commands, std::vector<uint32_t>& ids) {
  CommandRange range{uint32_t(commands.size()), 0};
  std::vector<std::vector<uint32_t>> by_group(scene.drawables.groups.size());
  for (uint32_t d : drawables) by_group[scene.drawables.instances[d].group].push_back(d);
  for (uint32_t g = 0; g < by_group.size(); ++g) {
    if (by_group[g].empty()) continue;
    const gpu::MeshRange& m = scene.mesh_ranges[scene.drawables.groups[g].mesh];
    gpu::DrawIndexedCommand c{};
    c.index_count = m.index_count;
    c.instance_count = uint32_t(by_group[g].size());
    c.first_index = m.first_index;
    c.vertex_offset = m.vertex_offset;
    c.first_instance = uint32_t(ids.size());
    ids.insert(ids.end(), by_group[g].begin(), by_group[g].end());
    commands.push_back(c);
    ++range.count;
  }
  return range;
}

VkRenderingAttachmentInfo cleared_attachment(VkImageView view, VkImageLayout layout, VkClearValue clear) {
  VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  a.imageView = view;
  a.imageLayout = layout;
  a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  a.clearValue = clear;
  return a;
}

void set_flipped_viewport(VkCommandBuffer cmd, uint32_t w, uint32_t h) {
  VkViewport vp{0.0f, float(h), float(w), -float(h), 0.0f, 1.0f};
  VkRect2D scissor{{0, 0}, {w, h}};
  vkCmdSetViewport(cmd, 0, 1, &vp);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
}

}  // namespace lintel::render
