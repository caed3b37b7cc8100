// The renderer's set layouts (from binding_tables.h), its descriptor sets (the compute set once
// per frame slot; the draw sets are written by their passes) and the passes themselves.
#include "binding_tables.h"
#include "render_bindings.h"
#include "renderer_impl.h"

#include "vk_status.h"

#include <deque>

namespace lintel::render {

Status Renderer::Impl::create_layouts() {
  VkDevice d = ctx.device();
  if (Status s = create_set_layout(d, draw_set_bindings(), "draw set", draw_set_layout); !s) return s;
  if (Status s = create_set_layout(d, compute_set_bindings(), "compute set", compute_set_layout); !s) return s;
  VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(GBufferPush)};
  VkPipelineLayoutCreateInfo li{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  li.setLayoutCount = 1;
  li.pSetLayouts = &draw_set_layout;
  li.pushConstantRangeCount = 1;
  li.pPushConstantRanges = &push;
  if (Status s = gpu::vk_check(vkCreatePipelineLayout(d, &li, nullptr, &draw.layout), "vkCreatePipelineLayout", "draw");
      !s)
    return s;
  VkPushConstantRange cpush{VK_SHADER_STAGE_COMPUTE_BIT, 0, 128};
  li.pSetLayouts = &compute_set_layout;
  li.pPushConstantRanges = &cpush;
  return gpu::vk_check(vkCreatePipelineLayout(d, &li, nullptr, &compute.layout), "vkCreatePipelineLayout", "compute");
}

Status Renderer::Impl::create_descriptors() {
  VkDevice d = ctx.device();
  const uint32_t n = slots();
  // Per slot: a camera draw set, a linked-views draw set and a compute set; one shadow draw set.
  const uint32_t draw_count = 2 * n + 1, sets = draw_count + n;
  const VkDescriptorPoolSize sizes[4] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, draw_count * 3 + n * 6},
                                         {VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, draw_count * 2 + n * 8},
                                         {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, n * 7},
                                         {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, draw_count + n * 2}};
  VkDescriptorPoolCreateInfo pi{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pi.maxSets = sets;
  pi.poolSizeCount = 4;
  pi.pPoolSizes = sizes;
  if (Status s = gpu::vk_check(vkCreateDescriptorPool(d, &pi, nullptr, &pool), "vkCreateDescriptorPool", "renderer");
      !s)
    return s;
  std::vector<VkDescriptorSetLayout> layouts(draw_count, draw_set_layout);
  layouts.insert(layouts.end(), n, compute_set_layout);
  std::vector<VkDescriptorSet> allocated(sets);
  VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  ai.descriptorPool = pool;
  ai.descriptorSetCount = sets;
  ai.pSetLayouts = layouts.data();
  if (Status s =
          gpu::vk_check(vkAllocateDescriptorSets(d, &ai, allocated.data()), "vkAllocateDescriptorSets", "renderer");
      !s)
    return s;
  draw_sets.assign(allocated.begin(), allocated.begin() + draw_count);
  compute.sets.assign(allocated.begin() + draw_count, allocated.end());
  draw.vertices = vertices.handle();
  draw.indices = indices.handle();
  if (Status s = TexelView::create(ctx, draw_instances, "draw instances", draw_instance_texels); !s) return s;
  draw.draw_instances = draw_instance_texels.handle();
  draw.fragment_counts = fragment_counts.handle();
  draw.textures = base_color_textures.view();
  draw.texture_sampler = texture_sampler;
  // The linked views' sets (and the link views the compute sets below point at).
  if (Status s = linked.create(ctx, draw, std::vector<VkDescriptorSet>(draw_sets.begin() + n + 1, draw_sets.end())); !s)
    return s;
  draw.shadow_link_clip = linked.link_clip(0);

  // The compute sets: the same resources but for the host-written per-slot buffers.
  std::vector<VkDescriptorBufferInfo> buffer_infos;
  std::vector<VkDescriptorImageInfo> image_infos;
  buffer_infos.reserve(size_t(n) * kComputeBindingCount);
  image_infos.reserve(size_t(n) * kComputeBindingCount);
  std::vector<VkWriteDescriptorSet> writes;
  std::deque<VkBufferView> view_handles;  // what the writes point at (a deque: never moved)
  Status view_status;
  for (uint32_t k = 0; k < n; ++k) {
    const VkDescriptorSet set = compute.sets[k];
    // One descriptor of `type` at `binding`; the caller points it at its info.
    auto write = [&](uint32_t binding, VkDescriptorType type) -> VkWriteDescriptorSet& {
      VkWriteDescriptorSet& w = writes.emplace_back(VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET});
      w.dstSet = set;
      w.dstBinding = binding;
      w.descriptorCount = 1;
      w.descriptorType = type;
      return w;
    };
    auto buffer = [&](uint32_t binding, VkBuffer b) {
      buffer_infos.push_back({b, 0, VK_WHOLE_SIZE});
      write(binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER).pBufferInfo = &buffer_infos.back();
    };
    auto image = [&](uint32_t binding, const GpuImage& img, bool sampled) {
      image_infos.push_back({sampled ? sampler : VK_NULL_HANDLE, img.view(),
                             sampled ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_GENERAL});
      write(binding, sampled ? VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER : VK_DESCRIPTOR_TYPE_STORAGE_IMAGE)
          .pImageInfo = &image_infos.back();
    };
    auto texel_view = [&](uint32_t binding, VkBufferView view) {
      view_handles.push_back(view);
      write(binding, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER).pTexelBufferView = &view_handles.back();
    };
    // A read-only buffer as rgba32ui texels (texel_view.h says why), its view kept in texel_views.
    auto texels = [&](uint32_t binding, const gpu::Buffer& b, const char* what) {
      TexelView view;
      if (view_status) view_status = TexelView::create(ctx, b, what, view);
      if (!view_status) return;
      texel_view(binding, view.handle());
      texel_views.push_back(std::move(view));
    };
    texels(kBindLights, lights, "lights");
    texel_view(kBindActiveLights, active_light_texels[k].handle());  // uvec2 texels, made with the lists
    texels(kBindShadowViews, shadow_matrices, "shadow matrices");
    buffer(kBindLightMasks, light_masks.handle());
    image(kBindShadowAtlas, shadow_atlas, true);
    texels(kBindCellProbes, cell_probes, "cell probe grids");
    buffer(kBindProbes, probes.handle());
    texels(kBindProbeTexels, probes, "probes");
    texels(kBindSurfels, surfels, "surfels");
    buffer(kBindSurfelRadiance, surfel_radiance.handle());
    texels(kBindSurfelRadianceTexels, surfel_radiance, "surfel radiance");
    texels(kBindProbeVisibility, probe_visibility, "probe visibility");
    buffer(kBindActiveCells, active_cells[k].handle());
    image(kBindAlbedo, gbuffer.albedo, false);
    image(kBindNormal, gbuffer.normal, false);
    image(kBindCell, gbuffer.cell_ids, false);
    image(kBindEmission, gbuffer.emission, false);
    image(kBindDepth, gbuffer.depth, true);
    image(kBindAo, ao, false);
    image(kBindHdr, hdr, false);
    image(kBindLdr, ldr, false);
    buffer(kBindExposure, exposure_value.handle());
    image(kBindAoHalf, ao_half, false);
    texels(kBindLinkViews, linked.link_views(k), "link views");
  }
  if (!view_status) return view_status;
  vkUpdateDescriptorSets(d, uint32_t(writes.size()), writes.data(), 0, nullptr);
  return {};
}

Status Renderer::Impl::create_passes() {
  VkDevice d = ctx.device();
  const uint32_t n = slots();
  std::vector<DrawSource> sources;  // empty with CameraCull::None: the pass draws everything
  if (cull && options.camera_cull == CameraCull::PortalHiz) {
    // Two-phase occlusion: the g-buffer draws the hiz pass's two command sets from its ids.
    hiz = std::make_unique<HizPass>();
    if (Status s =
            HizPass::create(ctx, scene, cull->draw_commands(), cull->instance_ids(), gbuffer.depth, sampler, *hiz);
        !s)
      return s;
    for (uint32_t k = 0; k < n; ++k) sources.push_back({hiz->commands(), hiz->ids(), hiz->groups()});
  } else if (cull) {  // every slot draws from the cull's shared outputs
    for (uint32_t k = 0; k < n; ++k)
      sources.push_back({cull->draw_commands(), cull->instance_ids(), cull->group_count()});
  }
  std::vector<VkDescriptorSet> camera_sets(draw_sets.begin(), draw_sets.begin() + n);
  std::vector<VkBufferView> link_clips;
  for (uint32_t k = 0; k < n; ++k) link_clips.push_back(linked.link_clip(k));
  if (Status s = GBufferPass::create(ctx, scene, draw, std::move(sources), std::move(camera_sets),
                                     std::move(link_clips), gbuffer, options.count_fragments, gbuffer_pass);
      !s)
    return s;
  if (!full()) return {};
  if (Status s = ShadowPass::create(ctx, scene, light_views, draw, draw_sets[n], shadow_atlas, shadow_plan.resolution,
                                    shadow_pass);
      !s)
    return s;
  const uint32_t w = options.width, h = options.height;
  if (options.ao)
    if (Status s = GtaoPass::create(
            d, compute, {w, h, options.ao_radius_m, options.ao_slices, options.ao_steps, options.ao_half_resolution},
            gtao_pass);
        !s)
      return s;
  if (options.gi)
    if (Status s = GiPass::create(d, compute, uint32_t(gi.surfels.size()), uint32_t(gi.probes.size()),
                                  options.gi_persist, gi_pass);
        !s)
      return s;
  if (Status s = LightingPass::create(d, compute, w, h, options.gi, options.ao, any_emission(scene),
                                      scene.drawables.environment, lighting_pass);
      !s)
    return s;
  if (options.auto_exposure)
    if (Status s = ExposurePass::create(d, compute, w, h, options.exposure, exposure_pass); !s) return s;
  if (Status s = TonemapPass::create(d, compute, w, h, options.exposure, options.auto_exposure, tonemap_pass); !s)
    return s;
  ReadbackSources rs;
  rs.ldr = &ldr;
  rs.hdr = options.readback_hdr ? &hdr : nullptr;
  rs.cell_ids = options.readback_cells ? &gbuffer.cell_ids : nullptr;
  rs.fragment_counts = options.count_fragments ? &fragment_counts : nullptr;
  rs.fragment_count_entries = uint32_t(scene.drawables.instances.size());
  return ReadbackPass::create(ctx, rs, readback_pass);
}

}  // namespace lintel::render
