// Everything static: geometry, lights and their casters, the GI layout, buffers, images and
// textures (layouts, descriptors and passes: renderer_passes.cpp). Runs once per Renderer.
#include "renderer_impl.h"
#include "texture_upload.h"
#include "vk_helpers.h"

#include "shader_pipeline.h"
#include "vk_status.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <bit>
#include <cmath>
#include <cstring>

namespace lintel::render {
namespace {

// Every buffer a shader reads may be bound as a storage buffer or as texels (render_bindings.h).
constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;

}  // namespace

Renderer::Impl::~Impl() {
  VkDevice d = ctx.device();
  vkDeviceWaitIdle(d);
  // The passes' pipelines go with the passes (members destroyed after this body).
  if (draw.layout) vkDestroyPipelineLayout(d, draw.layout, nullptr);
  if (compute.layout) vkDestroyPipelineLayout(d, compute.layout, nullptr);
  if (draw_set_layout) vkDestroyDescriptorSetLayout(d, draw_set_layout, nullptr);
  if (compute_set_layout) vkDestroyDescriptorSetLayout(d, compute_set_layout, nullptr);
  if (pool) vkDestroyDescriptorPool(d, pool, nullptr);
  texel_views.clear();
  active_light_texels.clear();
  draw_instance_texels.reset();
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
  if (options.frames_in_flight < 1 || options.frames_in_flight > 4)
    return Status::error("frames in flight " + std::to_string(options.frames_in_flight) + " is outside 1..4");
  if (options.shadow_resolution < 16)
    return Status::error("shadow resolution " + std::to_string(options.shadow_resolution) + " is below 16");
  if (options.gi_options.bounces == 0) options.gi_options.bounces = 1;
  if (Status s = build_render_scene(world, scene); !s) return s;
  one_sided = all_one_sided(scene);
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
  gi = build_gi_layout(scene, options.gi_options, options.gi);

  const World& w = scene.drawables;
  for (const Cell& c : w.cells) {
    Aabb b;
    for (uint32_t i : c.instances) b.extend(w.instances[i].bounds_world);
    b.extend(transform_aabb(c.cell_to_world, c.volume_box_cell));
    cell_bounds_world.push_back(b);
  }
  fill_gpu_lights();

  if (options.camera_cull != CameraCull::None) {
    // One cull with a slot per frame in flight (its host-written frame data); its outputs are
    // shared by the slots, and the render graph places the barrier between the cull and the
    // draws (output_barrier off), as an engine's graph would.
    gpu::CullPassOptions cpo;
    cpo.frames_in_flight = slots();
    cpo.output_barrier = false;
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
  if (Status s = create_layouts(); !s) return s;
  if (Status s = create_descriptors(); !s) return s;
  if (Status s = create_passes(); !s) return s;
  if (Status s = check_validation("pipelines and descriptors"); !s) return s;
  build_graph();
  if (options.timestamps && ctx.info().timestamps) {
    VkQueryPoolCreateInfo q{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    q.queryType = VK_QUERY_TYPE_TIMESTAMP;
    q.queryCount = uint32_t(2 * graph.pass_count() * slots());
    if (Status s = gpu::vk_check(vkCreateQueryPool(ctx.device(), &q, nullptr, &timestamps), "vkCreateQueryPool",
                                 "render timestamps");
        !s)
      return s;
  }
  return graph.validate(preloaded);
}

void Renderer::Impl::fill_gpu_lights() {
  const World& w = scene.drawables;
  gpu_lights.clear();
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
}

uint32_t Renderer::Impl::light_list_entries() const {
  uint32_t n = 0;
  for (uint32_t word : light_views.cell_mask) n += uint32_t(std::popcount(word));
  return n;
}

Status Renderer::Impl::create_light_lists(uint32_t entries) {
  using gpu::MemoryUse;
  light_list_capacity = entries;
  const uint32_t cell_count = uint32_t(scene.drawables.cells.size());
  active_lights.resize(slots());
  active_light_texels.resize(slots());
  for (uint32_t k = 0; k < slots(); ++k) {
    if (Status s = gpu::Buffer::create(ctx, std::max<VkDeviceSize>(16, 8 * VkDeviceSize(cell_count + entries)),
                                       kStorage, MemoryUse::Upload, "per-cell light lists", active_lights[k]);
        !s)
      return s;
    if (Status s = TexelView::create(ctx, active_lights[k], "per-cell light lists", active_light_texels[k],
                                     VK_FORMAT_R32G32_UINT);
        !s)
      return s;
  }
  return {};
}

Status Renderer::Impl::create_static_buffers() {
  Status s = upload_vector(ctx, scene.vertices, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, "vertices", vertices);
  if (s) s = upload_vector(ctx, scene.indices, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, "indices", indices);
  if (s) s = upload_vector(ctx, scene.draw_instances, kStorage, "draw instances", draw_instances);

  // Room for every light's most views: a door change may give the sun its second view.
  std::vector<glm::mat4> matrices;
  for (const ShadowView& v : light_views.views) matrices.push_back(v.world_to_clip);
  uint32_t most_views = 0;
  for (const Light& l : scene.drawables.lights) most_views += max_shadow_views(l);
  matrices.resize(std::max<size_t>(matrices.size(), most_views), glm::mat4(1.0f));
  if (s) s = upload_vector(ctx, gpu_lights, kStorage, "lights", lights);
  if (s) s = upload_vector(ctx, matrices, kStorage, "shadow matrices", shadow_matrices);
  if (s) s = upload_vector(ctx, light_views.cell_mask, kStorage, "light cell masks", light_masks);
  if (s) s = upload_vector(ctx, gi.cells, kStorage, "cell probes", cell_probes);
  if (s) s = upload_vector(ctx, gi.surfels, kStorage, "surfels", surfels);
  if (s) s = upload_vector(ctx, gi.probe_visibility, kStorage, "probe visibility", probe_visibility);
  const VkBufferUsageFlags copyable = kStorage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  if (s) s = upload_vector(ctx, gi.probes, copyable, "probes (initial)", probes_initial);
  if (s) s = upload_vector(ctx, gi.probes, copyable, "probes", probes);
  std::vector<glm::vec4> zero_radiance(gi.surfels.size(), glm::vec4(0.0f));
  if (s) s = upload_vector(ctx, zero_radiance, kStorage, "surfel radiance", surfel_radiance);
  std::vector<uint32_t> zero_counts(scene.drawables.instances.size(), 0u);
  if (s) s = upload_vector(ctx, zero_counts, copyable, "fragment counts", fragment_counts);
  if (!s) return s;

  using gpu::MemoryUse;
  if (s) s = create_light_lists(light_list_entries());
  active_cells.resize(slots());
  const size_t flags = scene.drawables.cells.size() + 2 * scene.drawables.portals.size();  // cells, then doors
  for (uint32_t k = 0; k < slots() && s; ++k)
    s = gpu::Buffer::create(ctx, std::max<VkDeviceSize>(16, 4 * flags), kStorage, MemoryUse::Upload, "active cells",
                            active_cells[k]);
  if (s)
    s = gpu::Buffer::create(ctx, ExposurePass::buffer_bytes(), kStorage, MemoryUse::Device, "exposure", exposure_value);
  return s;
}

Status Renderer::Impl::create_images() {
  Status s;
  const uint32_t w = options.width, h = options.height;
  const VkImageUsageFlags storage = VK_IMAGE_USAGE_STORAGE_BIT;
  const VkImageUsageFlags color = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | storage;
  // The g-buffer is also sampled and copied by engines that bring their own lighting
  // (Renderer::image()).
  const VkImageUsageFlags gcolor = color | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  s = GpuImage::create(ctx, {VK_FORMAT_R8G8B8A8_UNORM, w, h, 1, gcolor}, "g-buffer albedo", gbuffer.albedo);
  if (s) s = GpuImage::create(ctx, {VK_FORMAT_R16G16B16A16_SFLOAT, w, h, 1, gcolor}, "g-buffer normal", gbuffer.normal);
  if (s) s = GpuImage::create(ctx, {VK_FORMAT_R32_UINT, w, h, 1, gcolor}, "g-buffer cell", gbuffer.cell_ids);
  if (s)
    s = GpuImage::create(ctx, {VK_FORMAT_R16G16B16A16_SFLOAT, w, h, 1, gcolor}, "g-buffer emission", gbuffer.emission);
  if (s)
    s = GpuImage::create(
        ctx,
        {VK_FORMAT_D32_SFLOAT, w, h, 1,
         VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT},
        "g-buffer depth", gbuffer.depth);
  if (s)
    s = GpuImage::create(ctx, {VK_FORMAT_R32_SFLOAT, w, h, 1, storage | VK_IMAGE_USAGE_TRANSFER_DST_BIT}, "ao", ao);
  // Half-resolution GTAO's target (bound in every compute set, so created even when unused).
  if (s)
    s = GpuImage::create(ctx, {VK_FORMAT_R32G32B32A32_SFLOAT, (w + 1) / 2, (h + 1) / 2, 1, storage}, "ao (half)",
                         ao_half);
  if (s)
    s = GpuImage::create(ctx, {VK_FORMAT_R32G32B32A32_SFLOAT, w, h, 1, storage | VK_IMAGE_USAGE_TRANSFER_SRC_BIT},
                         "hdr", hdr);
  if (s)
    s = GpuImage::create(
        ctx,
        {VK_FORMAT_R8G8B8A8_UNORM, w, h, 1, storage | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_SAMPLED_BIT},
        "ldr", ldr);
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
  return create_base_color_sampler(ctx.device(), texture_sampler);
}

Status Renderer::Impl::upload_textures() {
  return upload_base_color_textures(ctx, scene.textures, false, base_color_textures);
}

}  // namespace lintel::render
