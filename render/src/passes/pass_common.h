// What the renderer's passes share: the frame being recorded (camera, active lights, frame slot),
// the compute passes' one pipeline layout with a descriptor set per frame slot, the draw passes'
// geometry and set layout, and the small recording helpers both kinds repeat. Each pass lives in
// its own file (render/src/passes/*_pass.cpp) and records only its own commands: every barrier
// between passes comes from the render graph (render_graph.h).
#pragma once

#include "../vk_helpers.h"

#include <lintel/gpu/cull_data.h>
#include "render_scene.h"
#include <lintel/render/render_shared.h>
#include <lintel/view.h>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <vector>

namespace lintel::render {

struct LinkedViewDraw;  // linked_draws.h

// The frame being recorded: set by Renderer::record_frame before the graph records.
struct FrameContext {
  View view;
  glm::mat4 view_proj{1.0f};
  uint32_t slot = 0;                 // frame slot (RenderOptions::frames_in_flight)
  uint32_t debug_view = kViewFinal;  // kView*
  bool one_sided = false;            // every drawable single-sided and unmirrored: the rasterizer may cull back faces
  std::span<const uint32_t> lights;  // active lights, most important first
  std::span<const uint32_t> light_slots;  // per active light: first shadow-atlas slot or kNoShadowSlot
  std::span<const uint8_t> light_redraw;  // per active light: 1 = draw its shadow layers (0: cached)
  uint32_t gi_bounces = 0;                // GI iterations this frame (<= GiOptions::bounces; the rest record nothing)
  // Draws through linked portals (mirrors, teleports; linked_draws.h): a draw set whose ids and
  // records are the slot's, its commands, and per linked view its push constants and commands.
  VkDescriptorSet linked_set = VK_NULL_HANDLE;
  VkBuffer linked_commands = VK_NULL_HANDLE;
  std::span<const LinkedViewDraw> linked_views;
};

// The compute passes' shared binding: one pipeline layout (set 0 = compute_set_bindings(), 128
// bytes of push constants) and one descriptor set per frame slot (they differ only in the
// host-written buffers).
struct ComputeBinding {
  VkPipelineLayout layout = VK_NULL_HANDLE;
  std::vector<VkDescriptorSet> sets;  // per frame slot
  // Binds `pipeline` and the slot's set, pushes `push`, dispatches x * y groups (none if either is 0).
  void dispatch(VkCommandBuffer cmd, uint32_t slot, VkPipeline pipeline, const void* push, uint32_t push_bytes,
                uint32_t x, uint32_t y) const;
};

// A compute pipeline on `binding.layout`, after checking that the shader's declarations match the
// compute set's table (Internal error naming the binding otherwise).
// `spec`: the shader's specialization constants by constant_id 0, 1, ... (bools as 0/1): variants
// of one shader.
Status create_compute_pass_pipeline(VkDevice device, const ComputeBinding& binding, std::span<const uint32_t> spirv,
                                    const char* label, Pipeline& out, std::span<const uint32_t> spec = {});

// What the g-buffer and shadow passes draw with.
struct DrawShared {
  VkPipelineLayout layout = VK_NULL_HANDLE;  // set 0 = draw_set_bindings(), GBufferPush for both stages
  VkBuffer vertices = VK_NULL_HANDLE, indices = VK_NULL_HANDLE;
  VkBufferView draw_instances = VK_NULL_HANDLE;  // GpuDrawInstance as texels (texel_view.h says why)
  VkBuffer fragment_counts = VK_NULL_HANDLE;
  VkImageView textures = VK_NULL_HANDLE;
  VkSampler texture_sampler = VK_NULL_HANDLE;
  VkBufferView shadow_link_clip = VK_NULL_HANDLE;  // what the shadow set binds at kDrawBindLinkClip (never read)
};

// A graphics pipeline on `shared.layout`, each stage checked against the draw set's table.
Status create_draw_pass_pipeline(VkDevice device, const DrawShared& shared, const GraphicsPipelineDesc& desc,
                                 const char* label, Pipeline& out);
// Writes a draw set: `ids` at kDrawBindIds, the shared instances, counts and textures, and
// `link_clip` (the frame slot's GpuLinkClip buffer; any for the shadow set, which never reads it).
void write_draw_set(VkDevice device, VkDescriptorSet set, const DrawShared& shared, VkBuffer ids,
                    VkBufferView link_clip);
// Binds the pipeline, `set`, vertex and index buffers, and pushes `push`.
void bind_draw(VkCommandBuffer cmd, const DrawShared& shared, VkPipeline pipeline, VkDescriptorSet set,
               const GBufferPush& push);

struct CommandRange {
  uint32_t first = 0, count = 0;  // commands in a shared indirect buffer
};
// Indirect commands drawing `drawables` (ascending) grouped by draw group: one command per group
// that has any, firstInstance = where its ids start in `ids`.
CommandRange append_commands(const RenderScene& scene, const std::vector<uint32_t>& drawables,
                             std::vector<gpu::DrawIndexedCommand>& commands, std::vector<uint32_t>& ids);

inline uint32_t groups_for(uint32_t n, uint32_t size) { return (n + size - 1) / size; }
VkRenderingAttachmentInfo cleared_attachment(VkImageView view, VkImageLayout layout, VkClearValue clear);
// Vulkan's framebuffer y points down; Lintel's NDC y points up (lintel/view.h): flip the viewport.
void set_flipped_viewport(VkCommandBuffer cmd, uint32_t w, uint32_t h);

}  // namespace lintel::render
