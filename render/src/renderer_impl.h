// The renderer's state, shared by its setup (renderer_setup.cpp), its graph
// (renderer_graph.cpp) and its frame (renderer.cpp).
#pragma once

#include <lintel/gpu/buffer.h>
#include <lintel/gpu/context.h>
#include <lintel/gpu/cull_data.h>
#include <lintel/gpu/cull_pass.h>
#include <lintel/render/gi_layout.h>
#include <lintel/render/gpu_image.h>
#include <lintel/render/light_views.h>
#include <lintel/render/render_graph.h>
#include <lintel/render/render_scene.h>
#include <lintel/render/renderer.h>
#include <lintel/visibility_builder.h>

#include "shadow_plan.h"

#include <memory>
#include <vector>

namespace lintel::render {

struct CommandRange {
  uint32_t first = 0, count = 0;  // commands in a shared indirect buffer
};

struct Renderer::Impl {
  explicit Impl(gpu::Context& c) : ctx(c) {}
  ~Impl();

  gpu::Context& ctx;
  RenderOptions options;
  RenderScene scene;
  LightViews light_views;
  ShadowPlan shadow_plan;
  GiLayout gi;
  std::vector<GpuLight> gpu_lights;
  std::vector<std::vector<uint32_t>> cell_neighbours;  // via portal links, both ways
  std::vector<Aabb> cell_bounds_world;

  // CPU visibility and the GPU cull.
  VisibilityBuilder builder;
  VisibleSet visible;
  gpu::CullFrame frame;
  std::unique_ptr<gpu::CullPass> cull;

  // Static buffers.
  gpu::Buffer vertices, indices, draw_instances;
  gpu::Buffer shadow_commands, shadow_ids;   // every shadow view's casters, grouped by view
  std::vector<CommandRange> shadow_ranges;   // per shadow view
  gpu::Buffer all_commands, all_ids;         // CameraCull::None: everything
  gpu::Buffer lights, shadow_matrices, light_masks, cell_probes, surfels, probes_initial;
  // Written by the GPU every frame.
  gpu::Buffer probes, surfel_radiance, fragment_counts;
  // Written by the host every frame (mapped, read by shaders directly).
  gpu::Buffer active_lights, active_cells;
  gpu::Buffer exposure_value;  // written by the exposure pass, read by the tonemap (one float)
  // Read back.
  gpu::Buffer ldr_readback, hdr_readback, cell_readback, counts_readback;

  GpuImage albedo, normal, cell_ids, depth, ao, hdr, ldr, shadow_atlas;
  GpuImage base_color_textures;  // static: uploaded once, then read-only
  VkSampler sampler = VK_NULL_HANDLE;          // nearest, clamp (texelFetch of g-buffer and shadows)
  VkSampler texture_sampler = VK_NULL_HANDLE;  // linear, repeat (base-colour textures)

  VkDescriptorSetLayout draw_set_layout = VK_NULL_HANDLE, compute_set_layout = VK_NULL_HANDLE;
  VkPipelineLayout draw_layout = VK_NULL_HANDLE, compute_layout = VK_NULL_HANDLE;
  VkPipeline gbuffer_pipeline = VK_NULL_HANDLE, shadow_pipeline = VK_NULL_HANDLE;
  VkPipeline gtao_pipeline = VK_NULL_HANDLE, surfel_light_pipeline = VK_NULL_HANDLE,
             probe_gather_pipeline = VK_NULL_HANDLE, lighting_pipeline = VK_NULL_HANDLE,
             tonemap_pipeline = VK_NULL_HANDLE, exposure_pipeline = VK_NULL_HANDLE;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkDescriptorSet camera_set = VK_NULL_HANDLE, shadow_set = VK_NULL_HANDLE, compute_set = VK_NULL_HANDLE;
  VkQueryPool timestamps = VK_NULL_HANDLE;
  RenderGraph graph;
  std::vector<ResourceId> preloaded;  // resources filled at setup (persistent probes)

  // This frame (set by render() before recording).
  View view;
  glm::mat4 view_proj{1.0f};
  std::vector<uint32_t> frame_lights;  // active light indices, most important first
  std::vector<uint32_t> frame_slots;   // per frame light: first shadow-atlas slot or kNoShadowSlot
  std::vector<uint32_t> active_entries;  // (light, slot) pairs as the shaders read them
  std::vector<uint8_t> drawn;          // per cell: the camera's cull draws from it (reused)
  std::vector<uint32_t> active_words;  // the active cells as a bitmask, like LightViews::cell_mask
  // pick_frame_lights' scratch, kept so a frame does not allocate once the largest was seen.
  struct LightCandidate {
    bool neighbour_only;
    float distance;
    uint32_t light;
  };
  std::vector<uint32_t> drawn_words;  // the drawn cells as a bitmask
  std::vector<LightCandidate> light_candidates;
  uint32_t frame_shadow_views = 0;

  Status setup(const World& world, const RenderOptions& opts);
  // With a validated context: any message since the last check fails `step` (Internal).
  Status check_validation(const char* step);
  void pick_frame_lights(const uint32_t* active);  // per cell: 1 = active
  Status create_static_buffers();
  Status create_images();
  Status upload_textures();
  Status create_pipelines();
  Status create_descriptors();
  void build_graph();

  // Recording helpers used by the graph's passes.
  void record_shadows(VkCommandBuffer cmd) const;
  void record_gbuffer(VkCommandBuffer cmd) const;
  void dispatch(VkCommandBuffer cmd, VkPipeline pipeline, const void* push, uint32_t push_bytes, uint32_t x,
                uint32_t y) const;
  void record_readback(VkCommandBuffer cmd) const;
};

}  // namespace lintel::render
