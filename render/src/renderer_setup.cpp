// Everything static: geometry, lights and their casters, the GI layout, images, pipelines and
// descriptors. Runs once per Renderer.
#include "renderer_impl.h"
#include "vk_helpers.h"

#include <lintel/gpu/shader_pipeline.h>
#include <lintel/gpu/vk_status.h>

#include "lintel_render_spirv.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <cmath>
#include <cstring>

namespace lintel::render {
namespace {

constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
constexpr VkBufferUsageFlags kIndirect = VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;

// Indirect commands drawing `drawables` (ascending) grouped by draw group: one command per group
// that has any, firstInstance = where its ids start in `ids`.
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

}  // namespace

Renderer::Impl::~Impl() {
  VkDevice d = ctx.device();
  vkDeviceWaitIdle(d);
  for (VkPipeline p : {gbuffer_pipeline, shadow_pipeline, gtao_pipeline, surfel_light_pipeline, probe_gather_pipeline,
                       lighting_pipeline, tonemap_pipeline, exposure_pipeline})
    if (p) vkDestroyPipeline(d, p, nullptr);
  if (draw_layout) vkDestroyPipelineLayout(d, draw_layout, nullptr);
  if (compute_layout) vkDestroyPipelineLayout(d, compute_layout, nullptr);
  if (draw_set_layout) vkDestroyDescriptorSetLayout(d, draw_set_layout, nullptr);
  if (compute_set_layout) vkDestroyDescriptorSetLayout(d, compute_set_layout, nullptr);
  if (pool) vkDestroyDescriptorPool(d, pool, nullptr);
  if (sampler) vkDestroySampler(d, sampler, nullptr);
  if (texture_sampler) vkDestroySampler(d, texture_sampler, nullptr);
  if (timestamps) vkDestroyQueryPool(d, timestamps, nullptr);
}

Status Renderer::Impl::setup(const World& world, const RenderOptions& opts) {
  options = opts;
  if (options.width == 0 || options.height == 0 || options.width > 8192 || options.height > 8192)
    return Status::error("render size " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                         " is outside 1..8192");
  // The library checks its numbers itself (not only the CLI): NaN spacing is undefined behaviour
  // in the probe layout, a non-finite or non-positive exposure a black or inverted image.
  if (!(std::isfinite(options.exposure) && options.exposure > 0.0f && options.exposure <= 1e4f))
    return Status::error("render exposure " + std::to_string(options.exposure) + " is not a finite number in (0, 1e4]");
  if (!(std::isfinite(options.gi_options.probe_spacing_m) && options.gi_options.probe_spacing_m >= 0.01f))
    return Status::error("GI probe spacing " + std::to_string(options.gi_options.probe_spacing_m) +
                         " m is not a finite number >= 0.01");
  if (options.shadow_resolution < 16)
    return Status::error("shadow resolution " + std::to_string(options.shadow_resolution) + " is below 16");
  if (options.gi_options.bounces == 0) options.gi_options.bounces = 1;
  if (Status s = build_render_scene(world, scene); !s) return s;
  // Plan the shadow atlas before creating anything: one slot per view when every light is active
  // at once (point 6, spot 1 or 6, sun 2 at most), within the device's limits and the budget.
  uint32_t views_wanted = 0;
  for (const Light& l : world.lights) views_wanted += max_shadow_views(l);
  ShadowDeviceLimits limits;
  if (Status s = query_shadow_device_limits(ctx, limits); !s) return s;
  if (Status s = plan_shadow_atlas(limits, options.shadow_resolution, views_wanted,
                                   uint64_t(options.shadow_memory_budget_mib) << 20, shadow_plan);
      !s)
    return s;
  options.shadow_resolution = shadow_plan.resolution;
  LightViewOptions lvo;
  lvo.shadow_resolution = options.shadow_resolution;
  if (Status s = build_light_views(scene, lvo, light_views); !s) return s;
  gi = build_gi_layout(scene, options.gi_options);

  const World& w = scene.drawables;
  cell_neighbours.assign(w.cells.size(), {});
  for (const Portal& p : w.portals) {
    cell_neighbours[p.from].push_back(p.to);
    cell_neighbours[p.to].push_back(p.from);
  }
  for (const Cell& c : w.cells) {
    Aabb b;
    for (uint32_t i : c.instances) b.extend(w.instances[i].bounds_world);
    b.extend(transform_aabb(c.cell_to_world, c.volume_box_cell));
    cell_bounds_world.push_back(b);
  }
  for (uint32_t l = 0; l < w.lights.size(); ++l) {
    const Light& light = w.lights[l];
    GpuLight g{};
    g.position_type = glm::vec4(light.position_world, float(uint32_t(light.type)));
    g.direction_range = glm::vec4(glm::normalize(light.direction_world), light.range);
    g.color = glm::vec4(light.color * light.intensity, 0.0f);
    const float cos_outer = std::cos(light.outer_cone_rad), cos_inner = std::cos(light.inner_cone_rad);
    const float scale = 1.0f / std::max(0.001f, cos_inner - cos_outer);
    g.cone = glm::vec4(scale, -cos_outer * scale, light_views.views[light_views.first_view[l]].texel_scale, 0.0f);
    g.shadow_view = light_views.first_view[l];
    g.shadow_view_count = light_views.view_count[l];
    g.mask_offset = l * light_views.words_per_light;
    gpu_lights.push_back(g);
  }

  if (options.camera_cull != CameraCull::None) {
    gpu::CullPassOptions cpo;
    if (Status s = gpu::CullPass::create(ctx, cpo, cull); !s) return s;
    if (Status s = cull->set_scene(scene.cull_scene); !s) return s;
  }
  if (Status s = check_validation("cull setup"); !s) return s;
  if (Status s = create_static_buffers(); !s) return s;
  if (Status s = check_validation("buffers"); !s) return s;
  if (Status s = create_images(); !s) return s;
  if (Status s = check_validation("images"); !s) return s;
  if (Status s = upload_textures(); !s) return s;
  if (Status s = check_validation("textures"); !s) return s;
  if (Status s = create_pipelines(); !s) return s;
  if (Status s = create_descriptors(); !s) return s;
  if (Status s = check_validation("pipelines and descriptors"); !s) return s;
  build_graph();
  if (options.timestamps && ctx.info().timestamps) {
    VkQueryPoolCreateInfo q{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    q.queryType = VK_QUERY_TYPE_TIMESTAMP;
    q.queryCount = uint32_t(2 * graph.pass_count());
    if (Status s = gpu::vk_check(vkCreateQueryPool(ctx.device(), &q, nullptr, &timestamps), "vkCreateQueryPool",
                                 "render timestamps");
        !s)
      return s;
  }
  return graph.validate(preloaded);
}

Status Renderer::Impl::create_static_buffers() {
  Status s = upload_vector(ctx, scene.vertices, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, "vertices", vertices);
  if (s) s = upload_vector(ctx, scene.indices, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, "indices", indices);
  if (s) s = upload_vector(ctx, scene.draw_instances, kStorage, "draw instances", draw_instances);

  std::vector<gpu::DrawIndexedCommand> commands;
  std::vector<uint32_t> ids;
  for (const ShadowView& v : light_views.views) shadow_ranges.push_back(append_commands(scene, v.casters, commands, ids));
  if (s) s = upload_vector(ctx, commands, kIndirect, "shadow commands", shadow_commands);
  if (s) s = upload_vector(ctx, ids, kStorage, "shadow caster ids", shadow_ids);
  if (options.camera_cull == CameraCull::None) {
    commands.clear();
    ids.clear();
    std::vector<uint32_t> everything(scene.drawables.instances.size());
    for (uint32_t i = 0; i < everything.size(); ++i) everything[i] = i;
    append_commands(scene, everything, commands, ids);
    if (s) s = upload_vector(ctx, commands, kIndirect, "all commands", all_commands);
    if (s) s = upload_vector(ctx, ids, kStorage, "all ids", all_ids);
  }

  std::vector<glm::mat4> matrices;
  for (const ShadowView& v : light_views.views) matrices.push_back(v.world_to_clip);
  if (s) s = upload_vector(ctx, gpu_lights, kStorage, "lights", lights);
  if (s) s = upload_vector(ctx, matrices, kStorage, "shadow matrices", shadow_matrices);
  if (s) s = upload_vector(ctx, light_views.cell_mask, kStorage, "light cell masks", light_masks);
  if (s) s = upload_vector(ctx, gi.cells, kStorage, "cell probes", cell_probes);
  if (s) s = upload_vector(ctx, gi.surfels, kStorage, "surfels", surfels);
  const VkBufferUsageFlags copyable = kStorage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  if (s) s = upload_vector(ctx, gi.probes, copyable, "probes (initial)", probes_initial);
  if (s) s = upload_vector(ctx, gi.probes, copyable, "probes", probes);
  std::vector<glm::vec4> zero_radiance(gi.surfels.size(), glm::vec4(0.0f));
  if (s) s = upload_vector(ctx, zero_radiance, kStorage, "surfel radiance", surfel_radiance);
  std::vector<uint32_t> zero_counts(scene.drawables.instances.size(), 0u);
  if (s) s = upload_vector(ctx, zero_counts, copyable, "fragment counts", fragment_counts);
  if (!s) return s;

  const VkDeviceSize pixels = VkDeviceSize(options.width) * options.height;
  using gpu::MemoryUse;
  s = gpu::Buffer::create(ctx, std::max<VkDeviceSize>(16, 8 * gpu_lights.size()), kStorage, MemoryUse::Upload,
                          "active lights", active_lights);
  if (s) s = gpu::Buffer::create(ctx, std::max<VkDeviceSize>(16, 4 * scene.drawables.cells.size()), kStorage,
                                 MemoryUse::Upload, "active cells", active_cells);
  if (s) s = gpu::Buffer::create(ctx, 16, kStorage, MemoryUse::Device, "exposure", exposure_value);
  const VkBufferUsageFlags dst = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  if (s) s = gpu::Buffer::create(ctx, pixels * 4, dst, MemoryUse::Readback, "ldr readback", ldr_readback);
  if (s && options.readback_hdr)
    s = gpu::Buffer::create(ctx, pixels * 16, dst, MemoryUse::Readback, "hdr readback", hdr_readback);
  if (s && options.readback_cells)
    s = gpu::Buffer::create(ctx, pixels * 4, dst, MemoryUse::Readback, "cell readback", cell_readback);
  if (s && options.count_fragments)
    s = gpu::Buffer::create(ctx, fragment_counts.size(), dst, MemoryUse::Readback, "counts readback", counts_readback);
  return s;
}

Status Renderer::Impl::create_images() {
  Status s;
  const uint32_t w = options.width, h = options.height;
  const VkImageUsageFlags storage = VK_IMAGE_USAGE_STORAGE_BIT;
  const VkImageUsageFlags color = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | storage;
  s = GpuImage::create(ctx, {VK_FORMAT_R8G8B8A8_UNORM, w, h, 1, color}, "g-buffer albedo", albedo);
  if (s) s = GpuImage::create(ctx, {VK_FORMAT_R16G16B16A16_SFLOAT, w, h, 1, color}, "g-buffer normal", normal);
  if (s)
    s = GpuImage::create(ctx, {VK_FORMAT_R32_UINT, w, h, 1, color | VK_IMAGE_USAGE_TRANSFER_SRC_BIT}, "g-buffer cell",
                         cell_ids);
  if (s)
    s = GpuImage::create(ctx,
                         {VK_FORMAT_D32_SFLOAT, w, h, 1,
                          VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT},
                         "g-buffer depth", depth);
  if (s) s = GpuImage::create(ctx, {VK_FORMAT_R32_SFLOAT, w, h, 1, storage | VK_IMAGE_USAGE_TRANSFER_DST_BIT}, "ao", ao);
  if (s)
    s = GpuImage::create(ctx, {VK_FORMAT_R32G32B32A32_SFLOAT, w, h, 1, storage | VK_IMAGE_USAGE_TRANSFER_SRC_BIT}, "hdr",
                         hdr);
  if (s)
    s = GpuImage::create(ctx, {VK_FORMAT_R8G8B8A8_UNORM, w, h, 1, storage | VK_IMAGE_USAGE_TRANSFER_SRC_BIT}, "ldr", ldr);
  const uint32_t layers = shadow_plan.slots;  // planned against the device (shadow_plan.h)
  const uint32_t res = shadow_plan.resolution;
  if (s)
    s = GpuImage::create(ctx,
                         {VK_FORMAT_D32_SFLOAT, res, res, layers,
                          VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, true, true},
                         "shadow atlas", shadow_atlas);
  if (!s) return s;
  VkSamplerCreateInfo si{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  si.magFilter = si.minFilter = VK_FILTER_NEAREST;
  si.addressModeU = si.addressModeV = si.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  if (s = gpu::vk_check(vkCreateSampler(ctx.device(), &si, nullptr, &sampler), "vkCreateSampler", "renderer"); !s)
    return s;
  si.magFilter = si.minFilter = VK_FILTER_LINEAR;
  si.addressModeU = si.addressModeV = si.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  return gpu::vk_check(vkCreateSampler(ctx.device(), &si, nullptr, &texture_sampler), "vkCreateSampler", "textures");
}

Status Renderer::Impl::upload_textures() {
  const TextureLayers& t = scene.textures;
  Status s = GpuImage::create(
      ctx,
      {VK_FORMAT_R8G8B8A8_SRGB, t.size, t.size, t.count, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
       false, true},
      "base-colour textures", base_color_textures);
  gpu::Buffer staging;
  if (s) s = gpu::Buffer::create(ctx, t.rgba8.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryUse::Upload,
                                 "texture staging", staging);
  if (!s) return s;
  std::memcpy(staging.mapped(), t.rgba8.data(), t.rgba8.size());
  return ctx.submit_and_wait(
      [&](VkCommandBuffer cmd) {
        VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
        b.srcStageMask = VK_PIPELINE_STAGE_2_NONE;
        b.dstStageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
        b.dstAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        b.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.image = base_color_textures.handle();
        b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, t.count};
        VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dep.imageMemoryBarrierCount = 1;
        dep.pImageMemoryBarriers = &b;
        vkCmdPipelineBarrier2(cmd, &dep);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, t.count};
        copy.imageExtent = {t.size, t.size, 1};
        vkCmdCopyBufferToImage(cmd, staging.handle(), base_color_textures.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                               1, &copy);
        b.srcStageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
        b.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        b.dstStageMask = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
        b.dstAccessMask = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
        b.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        b.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        vkCmdPipelineBarrier2(cmd, &dep);
      },
      "base-colour textures");
}

Status Renderer::Impl::create_pipelines() {
  VkDevice d = ctx.device();
  const BindingDesc draw_bindings[4] = {
      {0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_VERTEX_BIT},
      {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_VERTEX_BIT},
      {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT},
      {3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT}};
  if (Status s = create_set_layout(d, draw_bindings, "draw set", draw_set_layout); !s) return s;
  std::vector<BindingDesc> compute_bindings;
  const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
  for (uint32_t b = 0; b <= 17; ++b) {
    VkDescriptorType t = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    if (b == 4 || b == 13) t = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    if (b >= 10 && b <= 16 && b != 13) t = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    compute_bindings.push_back({b, t, cs});
  }
  if (Status s = create_set_layout(d, compute_bindings, "compute set", compute_set_layout); !s) return s;

  VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(GBufferPush)};
  VkPipelineLayoutCreateInfo li{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  li.setLayoutCount = 1;
  li.pSetLayouts = &draw_set_layout;
  li.pushConstantRangeCount = 1;
  li.pPushConstantRanges = &push;
  if (Status s = gpu::vk_check(vkCreatePipelineLayout(d, &li, nullptr, &draw_layout), "vkCreatePipelineLayout", "draw");
      !s)
    return s;
  VkPushConstantRange cpush{cs, 0, 128};
  li.pSetLayouts = &compute_set_layout;
  li.pPushConstantRanges = &cpush;
  if (Status s = gpu::vk_check(vkCreatePipelineLayout(d, &li, nullptr, &compute_layout), "vkCreatePipelineLayout",
                               "compute");
      !s)
    return s;

  GraphicsPipelineDesc g;
  g.vertex_spirv = gpu::spirv::gbuffer_vert();
  g.fragment_spirv = gpu::spirv::gbuffer_frag();
  g.color_formats = {VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_R32_UINT};
  g.depth_format = VK_FORMAT_D32_SFLOAT;
  g.fragment_spec = {options.count_fragments ? 1u : 0u};
  if (Status s = create_graphics_pipeline(d, draw_layout, g, "g-buffer pipeline", gbuffer_pipeline); !s) return s;
  GraphicsPipelineDesc sh;
  sh.vertex_spirv = gpu::spirv::gbuffer_vert();
  sh.depth_format = VK_FORMAT_D32_SFLOAT;
  sh.depth_bias = true;
  if (Status s = create_graphics_pipeline(d, draw_layout, sh, "shadow pipeline", shadow_pipeline); !s) return s;

  struct Compute {
    std::span<const uint32_t> spirv;
    const char* label;
    VkPipeline* out;
  } computes[] = {{gpu::spirv::gtao_comp(), "gtao.comp", &gtao_pipeline},
                  {gpu::spirv::surfel_light_comp(), "surfel_light.comp", &surfel_light_pipeline},
                  {gpu::spirv::probe_gather_comp(), "probe_gather.comp", &probe_gather_pipeline},
                  {gpu::spirv::lighting_comp(), "lighting.comp", &lighting_pipeline},
                  {gpu::spirv::tonemap_comp(), "tonemap.comp", &tonemap_pipeline},
                  {gpu::spirv::exposure_comp(), "exposure.comp", &exposure_pipeline}};
  for (const Compute& c : computes)
    if (Status s = gpu::create_compute_pipeline(d, compute_layout, c.spirv, {}, c.label, *c.out); !s) return s;
  return {};
}

Status Renderer::Impl::create_descriptors() {
  VkDevice d = ctx.device();
  const VkDescriptorPoolSize sizes[3] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 32},
                                         {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 8},
                                         {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 6}};
  VkDescriptorPoolCreateInfo pi{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pi.maxSets = 3;
  pi.poolSizeCount = 3;
  pi.pPoolSizes = sizes;
  if (Status s = gpu::vk_check(vkCreateDescriptorPool(d, &pi, nullptr, &pool), "vkCreateDescriptorPool", "renderer"); !s)
    return s;
  const VkDescriptorSetLayout layouts[3] = {draw_set_layout, draw_set_layout, compute_set_layout};
  VkDescriptorSet sets[3];
  VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  ai.descriptorPool = pool;
  ai.descriptorSetCount = 3;
  ai.pSetLayouts = layouts;
  if (Status s = gpu::vk_check(vkAllocateDescriptorSets(d, &ai, sets), "vkAllocateDescriptorSets", "renderer"); !s)
    return s;
  camera_set = sets[0];
  shadow_set = sets[1];
  compute_set = sets[2];

  std::vector<VkDescriptorBufferInfo> buffer_infos;
  std::vector<VkDescriptorImageInfo> image_infos;
  buffer_infos.reserve(32);
  image_infos.reserve(16);
  std::vector<VkWriteDescriptorSet> writes;
  auto buffer = [&](VkDescriptorSet set, uint32_t binding, VkBuffer b) {
    buffer_infos.push_back({b, 0, VK_WHOLE_SIZE});
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set;
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    w.pBufferInfo = &buffer_infos.back();
    writes.push_back(w);
  };
  auto image = [&](uint32_t binding, const GpuImage& img, bool sampled) {
    image_infos.push_back({sampled ? sampler : VK_NULL_HANDLE, img.view(),
                           sampled ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_GENERAL});
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = compute_set;
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = sampled ? VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER : VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    w.pImageInfo = &image_infos.back();
    writes.push_back(w);
  };
  buffer(camera_set, 0, cull ? cull->instance_ids() : all_ids.handle());
  buffer(camera_set, 1, draw_instances.handle());
  buffer(camera_set, 2, fragment_counts.handle());
  buffer(shadow_set, 0, shadow_ids.handle());
  buffer(shadow_set, 1, draw_instances.handle());
  buffer(shadow_set, 2, fragment_counts.handle());
  for (VkDescriptorSet set : {camera_set, shadow_set}) {
    image_infos.push_back({texture_sampler, base_color_textures.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set;
    w.dstBinding = 3;
    w.descriptorCount = 1;
    w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    w.pImageInfo = &image_infos.back();
    writes.push_back(w);
  }
  const VkBuffer compute_buffers[10] = {lights.handle(),      active_lights.handle(), shadow_matrices.handle(),
                                        light_masks.handle(), VK_NULL_HANDLE,         cell_probes.handle(),
                                        probes.handle(),      surfels.handle(),       surfel_radiance.handle(),
                                        active_cells.handle()};
  for (uint32_t b = 0; b < 10; ++b)
    if (b != 4) buffer(compute_set, b, compute_buffers[b]);
  buffer(compute_set, 17, exposure_value.handle());
  image(4, shadow_atlas, true);
  image(10, albedo, false);
  image(11, normal, false);
  image(12, cell_ids, false);
  image(13, depth, true);
  image(14, ao, false);
  image(15, hdr, false);
  image(16, ldr, false);
  vkUpdateDescriptorSets(d, uint32_t(writes.size()), writes.data(), 0, nullptr);
  return {};
}

}  // namespace lintel::render
