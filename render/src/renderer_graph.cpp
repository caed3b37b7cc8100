// The frame as a render graph: each pass declares what it reads and writes; the graph places the
// barriers. Pass order is the order added here.
#include "renderer_impl.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace lintel::render {
namespace {

uint32_t groups_for(uint32_t n, uint32_t size) { return (n + size - 1) / size; }

VkRenderingAttachmentInfo attachment(VkImageView view, VkImageLayout layout, VkClearValue clear) {
  VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  a.imageView = view;
  a.imageLayout = layout;
  a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  a.clearValue = clear;
  return a;
}

// Vulkan's framebuffer y points down; Lintel's NDC y points up (lintel/view.h): flip the viewport.
void set_viewport(VkCommandBuffer cmd, uint32_t w, uint32_t h) {
  VkViewport vp{0.0f, float(h), float(w), -float(h), 0.0f, 1.0f};
  VkRect2D scissor{{0, 0}, {w, h}};
  vkCmdSetViewport(cmd, 0, 1, &vp);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
}

}  // namespace

void Renderer::Impl::dispatch(VkCommandBuffer cmd, VkPipeline pipeline, const void* push, uint32_t push_bytes,
                              uint32_t x, uint32_t y) const {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compute_layout, 0, 1, &compute_set, 0, nullptr);
  vkCmdPushConstants(cmd, compute_layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, push_bytes, push);
  if (x && y) vkCmdDispatch(cmd, x, y, 1);
}

void Renderer::Impl::record_shadows(VkCommandBuffer cmd) const {
  const uint32_t res = options.shadow_resolution;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, shadow_pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, draw_layout, 0, 1, &shadow_set, 0, nullptr);
  const VkDeviceSize zero = 0;
  const VkBuffer vb = vertices.handle();
  vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &zero);
  vkCmdBindIndexBuffer(cmd, indices.handle(), 0, VK_INDEX_TYPE_UINT32);
  for (size_t i = 0; i < frame_lights.size(); ++i) {
    const uint32_t l = frame_lights[i];
    if (frame_slots[i] == kNoShadowSlot) continue;  // no room in the atlas: lit unshadowed
    for (uint32_t k = 0; k < light_views.view_count[l]; ++k) {
      const uint32_t v = light_views.first_view[l] + k;
      const uint32_t slot = frame_slots[i] + k;
      VkClearValue clear{};
      clear.depthStencil.depth = 1.0f;
      VkRenderingAttachmentInfo d =
          attachment(shadow_atlas.layer_view(slot), VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, clear);
      VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
      ri.renderArea = {{0, 0}, {res, res}};
      ri.layerCount = 1;
      ri.pDepthAttachment = &d;
      vkCmdBeginRendering(cmd, &ri);
      set_viewport(cmd, res, res);
      GBufferPush push{light_views.views[v].world_to_clip, glm::vec4(0.0f)};
      vkCmdPushConstants(cmd, draw_layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(push),
                         &push);
      const CommandRange r = shadow_ranges[v];
      if (r.count)
        vkCmdDrawIndexedIndirect(cmd, shadow_commands.handle(), VkDeviceSize(r.first) * sizeof(gpu::DrawIndexedCommand),
                                 r.count, sizeof(gpu::DrawIndexedCommand));
      vkCmdEndRendering(cmd);
    }
  }
}

void Renderer::Impl::record_gbuffer(VkCommandBuffer cmd) const {
  VkClearValue zero{};
  VkClearValue no_cell{};
  no_cell.color.uint32[0] = kNoCell;
  VkClearValue far{};
  far.depthStencil.depth = 1.0f;
  VkRenderingAttachmentInfo colors[3] = {
      attachment(albedo.view(), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, zero),
      attachment(normal.view(), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, zero),
      attachment(cell_ids.view(), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, no_cell)};
  VkRenderingAttachmentInfo d = attachment(depth.view(), VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, far);
  VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
  ri.renderArea = {{0, 0}, {options.width, options.height}};
  ri.layerCount = 1;
  ri.colorAttachmentCount = 3;
  ri.pColorAttachments = colors;
  ri.pDepthAttachment = &d;
  vkCmdBeginRendering(cmd, &ri);
  set_viewport(cmd, options.width, options.height);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, gbuffer_pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, draw_layout, 0, 1, &camera_set, 0, nullptr);
  GBufferPush push{view_proj, glm::vec4(view.eye_world, 1.0f)};
  vkCmdPushConstants(cmd, draw_layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(push), &push);
  const VkDeviceSize offset = 0;
  const VkBuffer vb = vertices.handle();
  vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &offset);
  vkCmdBindIndexBuffer(cmd, indices.handle(), 0, VK_INDEX_TYPE_UINT32);
  // Only the cull's commands (or, with CameraCull::None, the static all-drawing list).
  const uint32_t groups = uint32_t(scene.drawables.groups.size());
  if (groups) {
    if (cull)
      vkCmdDrawIndexedIndirect(cmd, cull->draw_commands(), 0, cull->group_count(), sizeof(gpu::DrawIndexedCommand));
    else
      vkCmdDrawIndexedIndirect(cmd, all_commands.handle(), 0, uint32_t(all_commands.size() / sizeof(gpu::DrawIndexedCommand)),
                               sizeof(gpu::DrawIndexedCommand));
  }
  vkCmdEndRendering(cmd);
}

void Renderer::Impl::record_readback(VkCommandBuffer cmd) const {
  VkBufferImageCopy copy{};
  copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  copy.imageExtent = {options.width, options.height, 1};
  vkCmdCopyImageToBuffer(cmd, ldr.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, ldr_readback.handle(), 1, &copy);
  if (options.readback_hdr)
    vkCmdCopyImageToBuffer(cmd, hdr.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, hdr_readback.handle(), 1, &copy);
  if (options.readback_cells)
    vkCmdCopyImageToBuffer(cmd, cell_ids.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, cell_readback.handle(), 1, &copy);
  if (options.count_fragments) {
    VkBufferCopy bc{0, 0, fragment_counts.size()};
    vkCmdCopyBuffer(cmd, fragment_counts.handle(), counts_readback.handle(), 1, &bc);
  }
  VkMemoryBarrier2 to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  to_host.srcStageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
  to_host.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  to_host.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
  to_host.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.memoryBarrierCount = 1;
  dep.pMemoryBarriers = &to_host;
  vkCmdPipelineBarrier2(cmd, &dep);
}

void Renderer::Impl::build_graph() {
  RenderGraph& g = graph;
  const ResourceId commands = g.import_buffer("draw commands", cull ? cull->draw_commands() : all_commands.handle());
  const ResourceId ids = g.import_buffer("instance ids", cull ? cull->instance_ids() : all_ids.handle());
  const ResourceId atlas = g.import_image("shadow atlas", &shadow_atlas);
  const ResourceId alb = g.import_image("albedo", &albedo);
  const ResourceId nrm = g.import_image("normal", &normal);
  const ResourceId cel = g.import_image("cell", &cell_ids);
  const ResourceId dep = g.import_image("depth", &depth);
  const ResourceId occ = g.import_image("ao", &ao);
  const ResourceId prb = g.import_buffer("probes", probes.handle());
  if (options.gi_persist) preloaded.push_back(prb);  // uploaded at setup, then kept frame to frame
  const ResourceId rad = g.import_buffer("surfel radiance", surfel_radiance.handle());
  const ResourceId hdr_id = g.import_image("hdr", &hdr);
  const ResourceId ldr_id = g.import_image("ldr", &ldr);
  const ResourceId counts = g.import_buffer("fragment counts", fragment_counts.handle());

  if (options.count_fragments)
    g.add_pass("reset counts", {{counts, Use::TransferDst}}, [this](VkCommandBuffer cmd) {
      vkCmdFillBuffer(cmd, fragment_counts.handle(), 0, VK_WHOLE_SIZE, 0u);
    });
  if (cull) {
    g.add_pass("cull", {{commands, Use::StorageWrite}, {ids, Use::StorageWrite}},
               [this](VkCommandBuffer cmd) { cull->record(cmd); });
  } else {
    // CameraCull::None: the static all-drawing list, uploaded (and made visible) at setup.
    preloaded.push_back(commands);
    preloaded.push_back(ids);
  }
  g.add_pass("shadows", {{atlas, Use::DepthWrite}}, [this](VkCommandBuffer cmd) { record_shadows(cmd); });
  std::vector<ResourceUse> gbuffer_uses = {{commands, Use::IndirectRead}, {ids, Use::VertexRead},
                                           {alb, Use::ColorWrite},        {nrm, Use::ColorWrite},
                                           {cel, Use::ColorWrite},        {dep, Use::DepthWrite}};
  if (options.count_fragments) gbuffer_uses.push_back({counts, Use::FragmentStorageWrite});
  g.add_pass("g-buffer", gbuffer_uses, [this](VkCommandBuffer cmd) { record_gbuffer(cmd); });

  const uint32_t tx = groups_for(options.width, kTileSize), ty = groups_for(options.height, kTileSize);
  // --no-ao skips GTAO entirely; the AO image is only cleared to 1 (the lighting's descriptor
  // must be in a defined layout, and the AO debug view then shows "no occlusion").
  if (!options.ao)
    g.add_pass("ao off", {{occ, Use::TransferDst}}, [this](VkCommandBuffer cmd) {
      VkClearColorValue one{};
      one.float32[0] = 1.0f;
      const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
      vkCmdClearColorImage(cmd, ao.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &one, 1, &range);
    });
  else
    g.add_pass("gtao", {{dep, Use::SampledRead}, {nrm, Use::StorageRead}, {cel, Use::StorageRead}, {occ, Use::StorageWrite}},
             [this, tx, ty](VkCommandBuffer cmd) {
               GtaoPush p{};
               p.world_to_view = glm::lookAtRH(view.eye_world, view.target_world, view.up_world);
               const float ty_half = std::tan(glm::radians(view.fov_y_deg) * 0.5f);
               p.projection = glm::vec4(ty_half * view.aspect, ty_half, view.near_m, view.far_m);
               p.params = glm::vec4(options.ao_radius_m, float(options.ao_slices), float(options.ao_steps), 0.4f);
               p.size = glm::uvec4(options.width, options.height, 0, 0);
               dispatch(cmd, gtao_pipeline, &p, sizeof(p), tx, ty);
             });
  if (options.gi) {
    if (!options.gi_persist)
      g.add_pass("gi reset", {{prb, Use::TransferDst}}, [this](VkCommandBuffer cmd) {
        VkBufferCopy c{0, 0, probes.size()};
        vkCmdCopyBuffer(cmd, probes_initial.handle(), probes.handle(), 1, &c);
      });
    for (uint32_t b = 0; b < options.gi_options.bounces; ++b) {
      g.add_pass("gi light " + std::to_string(b),
                 {{atlas, Use::SampledRead}, {prb, Use::StorageRead}, {rad, Use::StorageWrite}},
                 [this, b](VkCommandBuffer cmd) {
                   SurfelLightPush p{};
                   // Bounce 0 of a fresh frame reads no probes (they are zero); with persistence
                   // every iteration builds on the previous frame's.
                   const uint32_t bounce = options.gi_persist ? b + 1 : b;
                   p.counts = glm::uvec4(uint32_t(gi.surfels.size()), uint32_t(frame_lights.size()), bounce, 0);
                   dispatch(cmd, surfel_light_pipeline, &p, sizeof(p), groups_for(uint32_t(gi.surfels.size()), kLinearGroupSize), 1);
                 });
      g.add_pass("gi gather " + std::to_string(b), {{rad, Use::StorageRead}, {prb, Use::StorageWrite}},
                 [this](VkCommandBuffer cmd) {
                   ProbeGatherPush p{};
                   p.counts = glm::uvec4(uint32_t(gi.probes.size()), 0, 0, 0);
                   dispatch(cmd, probe_gather_pipeline, &p, sizeof(p), groups_for(uint32_t(gi.probes.size()), kLinearGroupSize), 1);
                 });
    }
  }
  std::vector<ResourceUse> lighting_uses = {{alb, Use::StorageRead},   {nrm, Use::StorageRead},
                                            {cel, Use::StorageRead},   {dep, Use::SampledRead},
                                            {atlas, Use::SampledRead}, {occ, Use::StorageRead},
                                            {hdr_id, Use::StorageWrite}};
  // The probes are read only with GI on (the shader tests size.z); without GI no pass writes them.
  if (options.gi) lighting_uses.push_back({prb, Use::StorageRead});
  g.add_pass("lighting", lighting_uses,
             [this, tx, ty](VkCommandBuffer cmd) {
               LightingPush p{};
               p.clip_to_world = glm::inverse(view_proj);
               p.size = glm::uvec4(options.width, options.height, options.gi ? 1u : 0u, options.ao ? 1u : 0u);
               p.mode = glm::uvec4(uint32_t(frame_lights.size()), options.view, 0, 0);
               dispatch(cmd, lighting_pipeline, &p, sizeof(p), tx, ty);
             });
  // Automatic exposure; the tonemap applies it to the final image only (debug views show their
  // pass as it is), decided when recording, so set_debug_view() can switch views between frames.
  const bool auto_exposure = options.auto_exposure;
  const ResourceId expo = g.import_buffer("exposure", exposure_value.handle());
  if (auto_exposure)
    g.add_pass("exposure", {{hdr_id, Use::StorageRead}, {cel, Use::StorageRead}, {expo, Use::StorageWrite}},
               [this](VkCommandBuffer cmd) {
                 ExposurePush p{};
                 p.params = glm::vec4(options.exposure, 0.0f, 0.0f, 0.0f);
                 // Up to about 256 K samples: a strided subset of big frames says the same.
                 const uint32_t pixels = options.width * options.height;
                 p.size = glm::uvec4(options.width, options.height, std::max(1u, pixels / (1u << 18)), 0);
                 dispatch(cmd, exposure_pipeline, &p, sizeof(p), 1, 1);
               });
  std::vector<ResourceUse> tonemap_uses = {{hdr_id, Use::StorageRead}, {alb, Use::StorageRead},
                                           {nrm, Use::StorageRead},    {cel, Use::StorageRead},
                                           {dep, Use::SampledRead},    {ldr_id, Use::StorageWrite}};
  if (auto_exposure) tonemap_uses.push_back({expo, Use::StorageRead});
  g.add_pass("tonemap", tonemap_uses,
             [this, tx, ty, auto_exposure](VkCommandBuffer cmd) {
               TonemapPush p{};
               p.params = glm::vec4(options.exposure, view.near_m, view.far_m, 15.0f);
               const bool use_auto = auto_exposure && options.view == kViewFinal;
               p.size = glm::uvec4(options.width, options.height, options.view, use_auto ? 1u : 0u);
               dispatch(cmd, tonemap_pipeline, &p, sizeof(p), tx, ty);
             });
  std::vector<ResourceUse> out_uses = {{ldr_id, Use::TransferSrc}};
  if (options.readback_hdr) out_uses.push_back({hdr_id, Use::TransferSrc});
  if (options.readback_cells) out_uses.push_back({cel, Use::TransferSrc});
  if (options.count_fragments) out_uses.push_back({counts, Use::TransferSrc});
  g.add_pass("readback", out_uses, [this](VkCommandBuffer cmd) { record_readback(cmd); });
}

}  // namespace lintel::render
