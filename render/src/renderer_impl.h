// The renderer's state: the scene's static data and the resources its passes share (buffers,
// images, layouts, descriptor sets), the passes themselves (render/src/passes/, each owning its
// pipelines) and the graph that orders them. Set up in renderer_setup.cpp, the graph built in
// renderer_graph.cpp, frames in renderer.cpp.
#pragma once

#include <lintel/gpu/buffer.h>
#include <lintel/gpu/context.h>
#include <lintel/gpu/cull_data.h>
#include <lintel/gpu/cull_pass.h>
#include "gi_layout.h"
#include "gpu_image.h"
#include "light_views.h"
#include "linked_draws.h"
#include "render_graph.h"
#include "render_scene.h"
#include "texel_view.h"
#include <lintel/render/renderer.h>
#include <lintel/visibility_builder.h>

#include "passes/exposure_pass.h"
#include "passes/gbuffer_pass.h"
#include "passes/gi_pass.h"
#include "passes/gtao_pass.h"
#include "passes/hiz_pass.h"
#include "passes/lighting_pass.h"
#include "passes/readback_pass.h"
#include "passes/shadow_pass.h"
#include "passes/tonemap_pass.h"
#include "shadow_plan.h"

#include <memory>
#include <vector>

namespace lintel::render {

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
  std::vector<Aabb> cell_bounds_world;

  // CPU visibility (render() only) and the GPU cull: one CullPass per frame slot, so slot k's
  // frame data and outputs are not overwritten while slot k-1 is in flight.
  VisibilityBuilder builder;
  VisibleSet visible;
  gpu::CullFrame cull_frame;
  std::unique_ptr<gpu::CullPass> cull;  // one pass, one set of host-written buffers per frame slot

  // Static buffers.
  gpu::Buffer vertices, indices, draw_instances;
  gpu::Buffer lights, shadow_matrices, light_masks, cell_probes, surfels, probe_visibility, probes_initial;
  // Written by the GPU every frame.
  gpu::Buffer probes, surfel_radiance, fragment_counts;
  gpu::Buffer exposure_value;  // written by the exposure pass, read by the tonemap (one float)
  // Written by the host every frame (mapped, read by shaders directly): one per frame slot.
  // active_lights: per-cell light lists (compute_bindings.glsl); active_cells: per cell 1 = active,
  // then two door flags per portal.
  std::vector<gpu::Buffer> active_lights, active_cells;
  std::vector<TexelView> active_light_texels;  // active_lights as the shaders read them (uvec2 texels)
  TexelView draw_instance_texels;              // draw_instances as the vertex shader reads them
  bool one_sided = false;                      // all_one_sided(scene), kept up to date by update_world
  uint32_t light_list_capacity = 0;            // list entries each active_lights buffer holds past the ranges

  GBufferImages gbuffer;
  GpuImage ao, ao_half, hdr, ldr, shadow_atlas;
  GpuImage base_color_textures;                // static: uploaded once, then read-only
  VkSampler sampler = VK_NULL_HANDLE;          // nearest, clamp (texelFetch of g-buffer and shadows)
  VkSampler texture_sampler = VK_NULL_HANDLE;  // trilinear, repeat (base-colour textures)

  VkDescriptorSetLayout draw_set_layout = VK_NULL_HANDLE, compute_set_layout = VK_NULL_HANDLE;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  std::vector<TexelView> texel_views;      // the compute sets' texel buffers (kBindLights, ...)
  DrawShared draw;                         // the draw passes' layout and geometry
  ComputeBinding compute;                  // the compute passes' layout and per-slot sets
  std::vector<VkDescriptorSet> draw_sets;  // per slot: the camera's; then the shadows'; then per slot the linked views'
  LinkedDraws linked;                      // what mirrors and teleports show, per slot

  ShadowPass shadow_pass;
  GBufferPass gbuffer_pass;
  GtaoPass gtao_pass;
  GiPass gi_pass;
  LightingPass lighting_pass;
  ExposurePass exposure_pass;
  TonemapPass tonemap_pass;
  ReadbackPass readback_pass;
  std::unique_ptr<HizPass> hiz;  // CameraCull::PortalHiz only
  ResourceId hiz_counters_host;

  VkQueryPool timestamps = VK_NULL_HANDLE;  // 2 per graph pass per frame slot
  RenderGraph graph;
  std::vector<ResourceId> preloaded;  // resources filled at setup (persistent probes)
  ResourceId albedo_id, normal_id, cell_id, depth_id, hdr_id, ldr_id, emission_id;  // what image() reports on

  // This frame (set by record_frame before recording; the passes read it).
  FrameContext frame;
  uint32_t cells_drawn = 0;
  std::vector<uint32_t> frame_lights;    // active light indices, most important first
  std::vector<uint32_t> frame_slots;     // per frame light: first shadow-atlas slot or kNoShadowSlot
  std::vector<uint32_t> active_entries;  // (light, slot) pairs as the shaders read them
  std::vector<uint8_t> drawn;            // per cell: the camera's cull draws from it (reused)
  // GI amortisation (GiOptions::amortized_bounces): whether the kept probes are warm, and which
  // cells were active the frame before (a newly active cell's probes are stale: a full frame).
  bool gi_warm = false;
  std::vector<uint8_t> gi_prev_active;
  // The GI iterations the frame being prepared runs.
  uint32_t choose_gi_bounces(const uint32_t* active, uint32_t cell_count);
  std::vector<uint32_t> active_words;  // the active cells as a bitmask, like LightViews::cell_mask
  // pick_frame_lights' scratch, kept so a frame does not allocate once the largest was seen.
  struct LightCandidate {
    bool neighbour_only;
    float distance;
    uint32_t light;
  };
  std::vector<uint32_t> drawn_words;  // the drawn cells as a bitmask
  std::vector<LightCandidate> light_candidates;
  uint32_t frame_shadow_views = 0;        // views of the frame's shadowed lights
  uint32_t frame_shadow_views_drawn = 0;  // of those, drawn this frame (the others are cached)
  // Shadow-map caching: per light, the first atlas slot it last held (kNoShadowSlot: none); per
  // atlas slot, what it holds (light_layer_code(light, view), 0: nothing valid); per frame light,
  // whether its layers are drawn this frame.
  std::vector<uint32_t> held_slot;
  std::vector<uint64_t> layer_content;
  std::vector<uint8_t> frame_redraw, slot_scratch;
  static uint64_t light_layer_code(uint32_t light, uint32_t view) { return (uint64_t(light) + 1) << 8 | view; }

  uint32_t slots() const { return options.frames_in_flight; }
  bool full() const { return options.passes == RenderPasses::All; }

  Status setup(const World& world, const RenderOptions& opts);
  // With a validated context: any message since the last check fails `step` (Internal).
  Status check_validation(const char* step);
  // The host side of a frame: the drawn and active cells, the cull's frame data and the active
  // lights, written into slot `slot`'s buffers.
  Status prepare_frame(const VisibleSet* visible, const View& view, uint32_t slot);
  void pick_frame_lights(const uint32_t* active, uint32_t slot);  // per cell: 1 = active
  // GpuLight per light from the scene and light_views (setup, and after the lights are rebuilt).
  void fill_gpu_lights();
  // Per-cell light list entries a frame can need at most: one per set bit of the cell masks.
  uint32_t light_list_entries() const;
  // (Re)creates every slot's list buffer with room for the cells' ranges and `entries` entries.
  Status create_light_lists(uint32_t entries);
  // Doors or movers changed (renderer_world.cpp): every light's reach, mask and casters again,
  // uploaded in place (the device is idle).
  // The cached layers of a light whose views (matrices, casters) changed, or that has a caster in
  // `moved` (drawables), are forgotten.
  Status rebuild_lights(std::span<const uint32_t> moved);
  Status create_static_buffers();
  Status create_images();
  Status upload_textures();
  Status create_layouts();
  Status create_descriptors();
  Status create_passes();
  void build_graph();
  void add_hiz_passes(std::vector<ResourceUse> gbuffer_uses, ResourceId cull_commands, ResourceId cull_ids);
};

}  // namespace lintel::render
