// The shadow pass: caster lists per view, one depth-only rendering per view whose layer is not
// cached from an earlier frame.
#include "shadow_pass.h"

#include "lintel_render_spirv.h"

namespace lintel::render {

Status ShadowPass::create(gpu::Context& ctx, const RenderScene& scene, const LightViews& views,
                          const DrawShared& shared, VkDescriptorSet set, const GpuImage& atlas, uint32_t resolution,
                          ShadowPass& out) {
  out.views_ = &views;
  out.atlas_ = &atlas;
  out.shared_ = shared;
  out.set_ = set;
  out.resolution_ = resolution;
  if (Status s = out.set_casters(ctx, scene, views); !s) return s;
  GraphicsPipelineDesc desc;
  desc.vertex_spirv = gpu::spirv::gbuffer_vert();
  // Cut-outs cast shadows where they are covered only; without them, depth needs no shader.
  if (any_cut_out(scene)) desc.fragment_spirv = gpu::spirv::shadow_cutout_frag();
  desc.depth_format = VK_FORMAT_D32_SFLOAT;
  desc.depth_bias = true;
  return create_draw_pass_pipeline(ctx.device(), shared, desc, "shadow pipeline", out.pipeline_);
}

Status ShadowPass::set_casters(gpu::Context& ctx, const RenderScene& scene, const LightViews& views) {
  std::vector<gpu::DrawIndexedCommand> commands;
  std::vector<uint32_t> ids;
  ranges_.clear();
  for (const ShadowView& v : views.views) ranges_.push_back(append_commands(scene, v.casters, commands, ids));
  Status s = upload_vector(ctx, commands, VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, "shadow commands", commands_);
  if (s) s = upload_vector(ctx, ids, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "shadow caster ids", ids_);
  if (!s) return s;
  write_draw_set(ctx.device(), set_, shared_, ids_.handle(), shared_.shadow_link_clip);
  return {};
}

void ShadowPass::record(VkCommandBuffer cmd, const FrameContext& frame) const {
  const uint32_t res = resolution_;
  for (size_t i = 0; i < frame.lights.size(); ++i) {
    const uint32_t l = frame.lights[i];
    if (frame.light_slots[i] == kNoShadowSlot) continue;  // no room in the atlas: lit unshadowed
    if (!frame.light_redraw[i]) continue;                 // its layers from an earlier frame still hold
    for (uint32_t k = 0; k < views_->view_count[l]; ++k) {
      const uint32_t v = views_->first_view[l] + k;
      VkClearValue clear{};
      clear.depthStencil.depth = 1.0f;
      VkRenderingAttachmentInfo d = cleared_attachment(atlas_->layer_view(frame.light_slots[i] + k),
                                                       VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, clear);
      VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
      ri.renderArea = {{0, 0}, {res, res}};
      ri.layerCount = 1;
      ri.pDepthAttachment = &d;
      vkCmdBeginRendering(cmd, &ri);
      set_flipped_viewport(cmd, res, res);
      bind_draw(cmd, shared_, pipeline_.handle(), set_, GBufferPush{views_->views[v].world_to_clip, glm::vec4(0.0f)});
      const CommandRange r = ranges_[v];
      if (r.count)
        vkCmdDrawIndexedIndirect(cmd, commands_.handle(), VkDeviceSize(r.first) * sizeof(gpu::DrawIndexedCommand),
                                 r.count, sizeof(gpu::DrawIndexedCommand));
      vkCmdEndRendering(cmd);
    }
  }
}

}  // namespace lintel::render
