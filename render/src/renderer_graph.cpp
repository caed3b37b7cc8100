// The frame's render graph: which pass reads and writes what. Every barrier of a frame comes from
// these declarations (render_graph.h); the passes (render/src/passes/) record commands only.
#include "renderer_impl.h"

#include <string>

namespace lintel::render {

// CameraCull::PortalHiz: the g-buffer in two phases around the depth pyramid (hiz_pass.h).
// `gbuffer_uses` are the one-phase g-buffer's; its commands and ids become the hiz pass's.
void Renderer::Impl::add_hiz_passes(std::vector<ResourceUse> gbuffer_uses, ResourceId cull_commands,
                                    ResourceId cull_ids) {
  RenderGraph& g = graph;
  const FrameContext* f = &frame;
  const ResourceId commands = g.import_buffer("hiz commands", hiz->commands());
  const ResourceId ids = g.import_buffer("hiz ids", hiz->ids());
  const ResourceId counters = g.import_buffer("hiz counters", hiz->counters());
  const ResourceId visibility = g.import_buffer("hiz visibility", hiz->visibility());
  const ResourceId pyramid = g.import_buffer("depth pyramid", hiz->pyramid());
  preloaded.push_back(visibility);  // zero at setup, then carried from frame to frame
  gbuffer_uses[0].resource = commands;
  gbuffer_uses[1].resource = ids;
  g.add_pass("hiz reset", {{counters, Use::TransferDst}},
             [this](VkCommandBuffer cmd, uint32_t) { hiz->record_reset(cmd); });
  g.add_pass("hiz early",
             {{cull_commands, Use::StorageRead},
              {cull_ids, Use::StorageRead},
              {visibility, Use::StorageRead},
              {counters, Use::StorageWrite},
              {ids, Use::StorageWrite}},
             [this](VkCommandBuffer cmd, uint32_t) { hiz->record_early(cmd); });
  g.add_pass("hiz early commands",
             {{cull_commands, Use::StorageRead}, {counters, Use::StorageRead}, {commands, Use::StorageWrite}},
             [this](VkCommandBuffer cmd, uint32_t) { hiz->record_commands(cmd, 0); });
  g.add_pass("g-buffer early", gbuffer_uses,
             [this, f](VkCommandBuffer cmd, uint32_t) { gbuffer_pass.record(cmd, *f, GBufferPhase::Early); });
  for (uint32_t l = 0; l < hiz->levels(); ++l) {
    std::vector<ResourceUse> uses = {{pyramid, Use::StorageWrite}};
    if (l == 0) uses.push_back({depth_id, Use::SampledRead});
    g.add_pass("hiz pyramid " + std::to_string(l), uses,
               [this, l](VkCommandBuffer cmd, uint32_t) { hiz->record_pyramid(cmd, l); });
  }
  g.add_pass("hiz late",
             {{cull_commands, Use::StorageRead},
              {cull_ids, Use::StorageRead},
              {pyramid, Use::StorageRead},
              {visibility, Use::StorageWrite},
              {counters, Use::StorageWrite},
              {ids, Use::StorageWrite}},
             [this, f](VkCommandBuffer cmd, uint32_t) { hiz->record_late(cmd, *f); });
  g.add_pass("hiz late commands",
             {{cull_commands, Use::StorageRead}, {counters, Use::StorageRead}, {commands, Use::StorageWrite}},
             [this](VkCommandBuffer cmd, uint32_t) { hiz->record_commands(cmd, 1); });
  g.add_pass("g-buffer late", gbuffer_uses,
             [this, f](VkCommandBuffer cmd, uint32_t) { gbuffer_pass.record(cmd, *f, GBufferPhase::Late); });
  hiz_counters_host = g.import_buffer("hiz counters readback", hiz->counters_readback());
  g.add_pass(
      "hiz readback", {{counters, Use::TransferSrc}, {hiz_counters_host, Use::TransferDst}},
      [this](VkCommandBuffer cmd, uint32_t) { hiz->record_readback(cmd); }, PassKind::Readback);
}

void Renderer::Impl::build_graph() {
  RenderGraph& g = graph;
  std::vector<VkBuffer> command_buffers, id_buffers, count_buffers;
  for (uint32_t k = 0; k < std::max<size_t>(1, gbuffer_pass.source_count()); ++k) {
    // The cull's outputs (with hiz: what the hiz pass reads; the g-buffer draws the hiz pass's).
    command_buffers.push_back(hiz ? cull->draw_commands() : gbuffer_pass.source(k).commands);
    id_buffers.push_back(hiz ? cull->instance_ids() : gbuffer_pass.source(k).ids);
  }
  if (cull)
    for (uint32_t k = 0; k < slots(); ++k) count_buffers.push_back(cull->counters());
  const ResourceId commands = g.import_buffers("draw commands", command_buffers);
  const ResourceId ids = g.import_buffers("instance ids", id_buffers);
  // Kept between frames: cached shadow layers are read again without being redrawn.
  const ResourceId atlas = g.import_image("shadow atlas", &shadow_atlas, options.cache_shadow_maps);
  albedo_id = g.import_image("albedo", &gbuffer.albedo);
  normal_id = g.import_image("normal", &gbuffer.normal);
  cell_id = g.import_image("cell", &gbuffer.cell_ids);
  depth_id = g.import_image("depth", &gbuffer.depth);
  emission_id = g.import_image("emission", &gbuffer.emission);
  const ResourceId alb = albedo_id, nrm = normal_id, cel = cell_id, dep = depth_id, emi = emission_id;
  const ResourceId counts = g.import_buffer("fragment counts", fragment_counts.handle());
  const FrameContext* f = &frame;

  if (options.count_fragments)
    g.add_pass("reset counts", {{counts, Use::TransferDst}}, [this](VkCommandBuffer cmd, uint32_t) {
      vkCmdFillBuffer(cmd, fragment_counts.handle(), 0, VK_WHOLE_SIZE, 0u);
    });
  if (cull) {
    // The cull fills its outputs with transfers (the counters) and compute shaders; the graph's
    // barriers order them before this frame's draws (CullPassOptions::output_barrier is off).
    // CullPass's own leading barrier orders them after the previous frame's reads, which the
    // graph, tracking each slot separately, does not see.
    const ResourceId draw_count = g.import_buffers("draw count", count_buffers);
    g.add_pass(
        "cull",
        {{commands, Use::CopyAndComputeWrite}, {ids, Use::CopyAndComputeWrite}, {draw_count, Use::CopyAndComputeWrite}},
        [this](VkCommandBuffer cmd, uint32_t slot) { cull->record(cmd, slot); });
  } else {
    // CameraCull::None: the static all-drawing list, uploaded (and made visible) at setup.
    preloaded.push_back(commands);
    preloaded.push_back(ids);
  }
  if (full())
    g.add_pass("shadows", {{atlas, Use::DepthWrite}},
               [this, f](VkCommandBuffer cmd, uint32_t) { shadow_pass.record(cmd, *f); });
  std::vector<ResourceUse> gbuffer_uses = {
      {commands, Use::IndirectRead}, {ids, Use::VertexRead}, {alb, Use::ColorWrite}, {nrm, Use::ColorWrite},
      {cel, Use::ColorWrite},        {dep, Use::DepthWrite}, {emi, Use::ColorWrite}};
  if (options.count_fragments) gbuffer_uses.push_back({counts, Use::FragmentStorageWrite});
  if (hiz)
    add_hiz_passes(gbuffer_uses, commands, ids);
  else
    g.add_pass("g-buffer", gbuffer_uses, [this, f](VkCommandBuffer cmd, uint32_t) { gbuffer_pass.record(cmd, *f); });
  if (!full()) return;  // RenderPasses::GBuffer: the caller lights the g-buffer itself

  const ResourceId occ = g.import_image("ao", &ao);
  const ResourceId prb = g.import_buffer("probes", probes.handle());
  if (options.gi_persist) preloaded.push_back(prb);  // uploaded at setup, then kept frame to frame
  const ResourceId rad = g.import_buffer("surfel radiance", surfel_radiance.handle());
  hdr_id = g.import_image("hdr", &hdr);
  ldr_id = g.import_image("ldr", &ldr);
  // --no-ao skips GTAO entirely; the AO image is only cleared to 1 (the lighting's descriptor
  // must be in a defined layout, and the AO debug view then shows "no occlusion").
  if (!options.ao)
    g.add_pass("ao off", {{occ, Use::TransferDst}}, [this](VkCommandBuffer cmd, uint32_t) {
      VkClearColorValue one{};
      one.float32[0] = 1.0f;
      const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
      vkCmdClearColorImage(cmd, ao.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &one, 1, &range);
    });
  else {
    // gtao.comp can write either AO image (full or half resolution, a push constant), so it
    // declares both; at half resolution the upsample then writes the full one.
    const ResourceId half = g.import_image("ao half", &ao_half);
    g.add_pass("gtao",
               {{dep, Use::SampledRead},
                {nrm, Use::StorageRead},
                {cel, Use::StorageRead},
                {half, Use::StorageWrite},
                {occ, Use::StorageWrite}},
               [this, f](VkCommandBuffer cmd, uint32_t) { gtao_pass.record(cmd, *f); });
    if (options.ao_half_resolution)
      g.add_pass("ao upsample",
                 {{half, Use::StorageRead}, {dep, Use::SampledRead}, {cel, Use::StorageRead}, {occ, Use::StorageWrite}},
                 [this, f](VkCommandBuffer cmd, uint32_t) { gtao_pass.record_upsample(cmd, *f); });
  }
  if (options.gi) {
    if (!options.gi_persist)
      g.add_pass("gi reset", {{prb, Use::TransferDst}}, [this](VkCommandBuffer cmd, uint32_t) {
        VkBufferCopy c{0, 0, probes.size()};
        vkCmdCopyBuffer(cmd, probes_initial.handle(), probes.handle(), 1, &c);
      });
    for (uint32_t b = 0; b < options.gi_options.bounces; ++b) {
      g.add_pass("gi light " + std::to_string(b),
                 {{atlas, Use::SampledRead}, {prb, Use::StorageRead}, {rad, Use::StorageWrite}},
                 [this, f, b](VkCommandBuffer cmd, uint32_t) { gi_pass.record_light(cmd, *f, b); });
      g.add_pass("gi gather " + std::to_string(b), {{rad, Use::StorageRead}, {prb, Use::StorageWrite}},
                 [this, f, b](VkCommandBuffer cmd, uint32_t) { gi_pass.record_gather(cmd, *f, b); });
    }
  }
  std::vector<ResourceUse> lighting_uses = {
      {alb, Use::StorageRead},   {nrm, Use::StorageRead}, {cel, Use::StorageRead},     {dep, Use::SampledRead},
      {atlas, Use::SampledRead}, {occ, Use::StorageRead}, {hdr_id, Use::StorageWrite}, {emi, Use::StorageRead}};
  // The probes are read only with GI on (the shader tests size.z); without GI no pass writes them.
  if (options.gi) lighting_uses.push_back({prb, Use::StorageRead});
  g.add_pass("lighting", lighting_uses, [this, f](VkCommandBuffer cmd, uint32_t) { lighting_pass.record(cmd, *f); });
  const ResourceId expo = g.import_buffer("exposure", exposure_value.handle());
  if (options.auto_exposure) {
    g.add_pass("exposure histogram", {{hdr_id, Use::StorageRead}, {cel, Use::StorageRead}, {expo, Use::StorageWrite}},
               [this, f](VkCommandBuffer cmd, uint32_t) { exposure_pass.record_histogram(cmd, *f); });
    g.add_pass("exposure", {{expo, Use::StorageWrite}},
               [this, f](VkCommandBuffer cmd, uint32_t) { exposure_pass.record_resolve(cmd, *f); });
  }
  std::vector<ResourceUse> tonemap_uses = {{hdr_id, Use::StorageRead}, {alb, Use::StorageRead},
                                           {nrm, Use::StorageRead},    {cel, Use::StorageRead},
                                           {dep, Use::SampledRead},    {ldr_id, Use::StorageWrite}};
  if (options.auto_exposure) tonemap_uses.push_back({expo, Use::StorageRead});
  g.add_pass("tonemap", tonemap_uses, [this, f](VkCommandBuffer cmd, uint32_t) { tonemap_pass.record(cmd, *f); });

  // Readback (Renderer::render only): copies, then the host reads them after the fence.
  const ResourceId ldr_host = g.import_buffer("ldr readback", readback_pass.ldr());
  std::vector<ResourceUse> out_uses = {{ldr_id, Use::TransferSrc}, {ldr_host, Use::TransferDst}};
  std::vector<ResourceUse> host_uses = {{ldr_host, Use::HostRead}};
  auto read_back = [&](const char* name, ResourceId source, VkBuffer host) {
    const ResourceId h = g.import_buffer(name, host);
    out_uses.push_back({source, Use::TransferSrc});
    out_uses.push_back({h, Use::TransferDst});
    host_uses.push_back({h, Use::HostRead});
  };
  if (options.readback_hdr) read_back("hdr readback", hdr_id, readback_pass.hdr());
  if (options.readback_cells) read_back("cell readback", cel, readback_pass.cells());
  if (options.count_fragments) read_back("counts readback", counts, readback_pass.counts());
  if (hiz) host_uses.push_back({hiz_counters_host, Use::HostRead});
  g.add_pass(
      "readback", out_uses, [this](VkCommandBuffer cmd, uint32_t) { readback_pass.record(cmd); }, PassKind::Readback);
  g.add_pass(
      "host read", host_uses, [](VkCommandBuffer, uint32_t) {}, PassKind::Readback);
}

}  // namespace lintel::render
