// The g-buffer pass: one indirect multi-draw into five attachments.
#include "gbuffer_pass.h"

#include "../linked_draws.h"

#include "lintel_render_spirv.h"

namespace lintel::render {

Status GBufferPass::create(gpu::Context& ctx, const RenderScene& scene, const DrawShared& shared,
                           std::vector<DrawSource> sources, std::vector<VkDescriptorSet> sets,
                           std::vector<VkBufferView> link_clips, const GBufferImages& images, bool count_fragments,
                           GBufferPass& out) {
  out.shared_ = shared;
  out.images_ = &images;
  out.sets_ = std::move(sets);
  if (sources.empty()) {
    std::vector<gpu::DrawIndexedCommand> commands;
    std::vector<uint32_t> ids;
    std::vector<uint32_t> everything(scene.drawables.instances.size());
    for (uint32_t i = 0; i < everything.size(); ++i) everything[i] = i;
    append_commands(scene, everything, commands, ids);
    Status s = upload_vector(ctx, commands, VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, "all commands", out.all_commands_);
    if (s) s = upload_vector(ctx, ids, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "all ids", out.all_ids_);
    if (!s) return s;
    sources.push_back({out.all_commands_.handle(), out.all_ids_.handle(), uint32_t(commands.size())});
  }
  out.sources_ = std::move(sources);
  for (size_t k = 0; k < out.sets_.size(); ++k)
    write_draw_set(ctx.device(), out.sets_[k], shared, out.source(uint32_t(k)).ids, link_clips[k]);
  GraphicsPipelineDesc g;
  g.vertex_spirv = gpu::spirv::gbuffer_vert();
  g.fragment_spirv = gpu::spirv::gbuffer_frag();
  g.color_formats = {images.albedo.desc().format, images.normal.desc().format, images.cell_ids.desc().format,
                     images.emission.desc().format};
  g.depth_format = images.depth.desc().format;
  const uint32_t count = count_fragments ? 1u : 0u, alpha_test = any_cut_out(scene) ? 1u : 0u,
                 emission = any_emission(scene) ? 1u : 0u;
  g.fragment_spec = {count, 0u, 0u, alpha_test, emission};
  g.cull_mode = VK_CULL_MODE_BACK_BIT;
  if (Status s = create_draw_pass_pipeline(ctx.device(), shared, g, "g-buffer pipeline", out.one_sided_pipeline_); !s)
    return s;
  g.cull_mode = VK_CULL_MODE_NONE;
  g.fragment_spec = {count, 0u, 1u, alpha_test, emission};
  if (Status s = create_draw_pass_pipeline(ctx.device(), shared, g, "g-buffer pipeline", out.plain_pipeline_); !s)
    return s;
  g.fragment_spec = {count, 1u, 1u, alpha_test, emission};
  return create_draw_pass_pipeline(ctx.device(), shared, g, "g-buffer pipeline", out.pipeline_);
}

void GBufferPass::record(VkCommandBuffer cmd, const FrameContext& frame, GBufferPhase phase) const {
  const GBufferImages& im = *images_;
  const uint32_t w = im.albedo.desc().width, h = im.albedo.desc().height;
  VkClearValue zero{};
  VkClearValue no_cell{};
  no_cell.color.uint32[0] = kNoCell;
  VkClearValue far{};
  far.depthStencil.depth = 1.0f;
  VkRenderingAttachmentInfo colors[4] = {
      cleared_attachment(im.albedo.view(), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, zero),
      cleared_attachment(im.normal.view(), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, zero),
      cleared_attachment(im.cell_ids.view(), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, no_cell),
      cleared_attachment(im.emission.view(), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, zero)};
  VkRenderingAttachmentInfo d = cleared_attachment(im.depth.view(), VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, far);
  if (phase == GBufferPhase::Late) {  // on top of the early phase's draws
    for (VkRenderingAttachmentInfo& c : colors) c.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    d.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  }
  VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
  ri.renderArea = {{0, 0}, {w, h}};
  ri.layerCount = 1;
  ri.colorAttachmentCount = 4;
  ri.pColorAttachments = colors;
  ri.pDepthAttachment = &d;
  vkCmdBeginRendering(cmd, &ri);
  set_flipped_viewport(cmd, w, h);
  const bool linked = !frame.linked_views.empty();
  const Pipeline& plain = linked ? pipeline_ : frame.one_sided ? one_sided_pipeline_ : plain_pipeline_;
  bind_draw(cmd, shared_, plain.handle(), sets_[frame.slot % sets_.size()],
            GBufferPush{frame.view_proj, glm::vec4(frame.view.eye_world, 1.0f), glm::vec4(0.0f),
                        // the plain view gives up what mirrors and teleports show, when there are any
                        glm::uvec4(0, linked ? 1 : 0, 0, 0)});
  const DrawSource& src = source(frame.slot);
  const VkDeviceSize first = phase == GBufferPhase::Late ? VkDeviceSize(src.command_count) : 0;
  if (src.command_count)
    vkCmdDrawIndexedIndirect(cmd, src.commands, first * sizeof(gpu::DrawIndexedCommand), src.command_count,
                             sizeof(gpu::DrawIndexedCommand));
  // Then what mirrors and teleports show, each linked view clipped by its own push constants.
  if (!frame.linked_views.empty() && phase != GBufferPhase::Early) {
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, shared_.layout, 0, 1, &frame.linked_set, 0, nullptr);
    for (const LinkedViewDraw& v : frame.linked_views) {
      vkCmdPushConstants(cmd, shared_.layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                         sizeof(GBufferPush), &v.push);
      vkCmdDrawIndexedIndirect(cmd, frame.linked_commands,
                               VkDeviceSize(v.first_command) * sizeof(gpu::DrawIndexedCommand), v.command_count,
                               sizeof(gpu::DrawIndexedCommand));
    }
  }
  vkCmdEndRendering(cmd);
}

}  // namespace lintel::render
