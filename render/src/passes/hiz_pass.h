// Two-phase hierarchical-Z occlusion of the camera's draws (CameraCull::PortalHiz; hiz.glsl):
// the portal cull's output split into what passed last frame's occlusion test and the visible
// cells' shells (drawn first), a
// depth pyramid built from that depth by a compute max reduction, and the late test of every
// draw of the portal cull against it (drawn second when it passes and was not drawn first). The
// g-buffer draws hiz commands 0..groups-1, then groups..2 groups-1 (GBufferPass::record's phases);
// its ids binding is ids(). Its own descriptor set and layout (storage buffers and the depth
// image), so the compute passes' shared set stays as it is.
#pragma once

#include "gbuffer_pass.h"
#include "pass_common.h"

#include <lintel/gpu/buffer.h>
#include <lintel/gpu/context.h>

namespace lintel::render {

// What the last read-back frame's occlusion did (counts of drawables).
struct HizStats {
  uint32_t drawn_early = 0;  // drawn first: passed last frame's test and the portal cull now
  uint32_t drawn_late = 0;   // drawn second: passed this frame's test, not drawn first
  uint32_t tested = 0;       // the portal cull's draws, all tested against the pyramid
  uint32_t passed = 0;       // of those, not occluded
};

class HizPass {
 public:
  HizPass() = default;
  ~HizPass();
  HizPass(const HizPass&) = delete;
  HizPass& operator=(const HizPass&) = delete;

  // cull_commands / cull_ids: the portal cull's outputs (CullPass::draw_commands, instance_ids);
  // depth: the g-buffer's depth image, read through `sampler` (nearest).
  static Status create(gpu::Context& ctx, const RenderScene& scene, VkBuffer cull_commands, VkBuffer cull_ids,
                       const GpuImage& depth, VkSampler sampler, HizPass& out);
  // The instances' bounds again (update_world moved some; the device is idle).
  Status update_bounds(gpu::Context& ctx, const RenderScene& scene);

  // The frame's stages, one graph pass each (renderer_graph.cpp declares what each touches).
  void record_reset(VkCommandBuffer cmd) const;                            // counters to 0 (transfer)
  void record_early(VkCommandBuffer cmd) const;                            // phase-1 ids
  void record_commands(VkCommandBuffer cmd, uint32_t phase) const;         // phase 0 or 1 commands
  void record_pyramid(VkCommandBuffer cmd, uint32_t level) const;          // one level
  void record_late(VkCommandBuffer cmd, const FrameContext& frame) const;  // the test, phase-2 ids
  void record_readback(VkCommandBuffer cmd) const;  // counters to the host buffer (render() only)
  HizStats read_stats() const;                      // after the read-back frame's fence

  uint32_t levels() const { return levels_; }
  uint32_t groups() const { return groups_; }
  VkBuffer commands() const { return commands_.handle(); }
  VkBuffer ids() const { return ids_.handle(); }
  VkBuffer counters() const { return counters_.handle(); }
  VkBuffer visibility() const { return visibility_.handle(); }
  VkBuffer pyramid() const { return pyramid_.handle(); }
  VkBuffer counters_readback() const { return counters_host_.handle(); }

 private:
  void dispatch(VkCommandBuffer cmd, uint32_t stage, const void* push, uint32_t groups) const;

  VkDevice device_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  Pipeline stages_[4];
  gpu::Buffer commands_, ids_, counters_, counters_host_, visibility_, pyramid_, instances_, slot_groups_;
  uint32_t capacity_ = 0, groups_ = 0, width_ = 0, height_ = 0, levels_ = 0;
  uint32_t first_shell_ = 0;  // RenderScene::world_instance_count: drawables from it on are shells
};

}  // namespace lintel::render
