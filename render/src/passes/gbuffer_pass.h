// The g-buffer: albedo, normal, cell id and depth, drawn only through indirect commands: the GPU
// cull's of the frame slot, or (CameraCull::None) a static list that draws everything.
#pragma once

#include "pass_common.h"

#include <lintel/gpu/buffer.h>
#include <lintel/gpu/context.h>
#include "gpu_image.h"

namespace lintel::render {

struct GBufferImages {
  GpuImage albedo, normal, cell_ids, depth;
  GpuImage emission;  // rgba16f: what the surface gives off by itself (Mesh::emissive), lit or not
};

// Where a frame slot's draws come from.
struct DrawSource {
  VkBuffer commands = VK_NULL_HANDLE;  // DrawIndexedCommand per draw group
  VkBuffer ids = VK_NULL_HANDLE;       // what the vertex shader reads at gl_InstanceIndex
  uint32_t command_count = 0;
  VkBufferView link_clip = VK_NULL_HANDLE;  // the slot's GpuLinkClip buffer (linked_draws.h)
};

// Which draws one recording makes (two-phase occlusion, hiz_pass.h, records the g-buffer twice).
enum class GBufferPhase {
  All,    // clear, the source's commands, the linked views
  Early,  // clear, the source's first command_count commands (drawn last frame)
  Late,   // keep what Early drew, the next command_count commands (newly visible), the linked views
};

class GBufferPass {
 public:
  // `sources` empty: the pass builds the static draw-everything list and uses it for every slot.
  // `sets`: one draw set per frame slot (written here), `link_clips` one GpuLinkClip buffer each.
  static Status create(gpu::Context& ctx, const RenderScene& scene, const DrawShared& shared,
                       std::vector<DrawSource> sources, std::vector<VkDescriptorSet> sets,
                       std::vector<VkBufferView> link_clips, const GBufferImages& images, bool count_fragments,
                       GBufferPass& out);
  void record(VkCommandBuffer cmd, const FrameContext& frame, GBufferPhase phase = GBufferPhase::All) const;
  const DrawSource& source(uint32_t slot) const { return sources_[slot % sources_.size()]; }
  size_t source_count() const { return sources_.size(); }

 private:
  Pipeline pipeline_;                   // keeps fragments by the linked views' pyramids (gbuffer.frag's kLinkClip)
  Pipeline plain_pipeline_;             // without them: the plain view of a frame with no linked view
  Pipeline one_sided_pipeline_;         // that, culling back faces in the rasterizer (FrameContext::one_sided)
  gpu::Buffer all_commands_, all_ids_;  // CameraCull::None
  std::vector<DrawSource> sources_;
  std::vector<VkDescriptorSet> sets_;
  const GBufferImages* images_ = nullptr;
  DrawShared shared_;
};

}  // namespace lintel::render
