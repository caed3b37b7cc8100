// Shadow maps: every active light's views (cube faces, spot, sun) into the atlas layers the frame
// gave it, depth only, drawing each view's casters from static indirect lists built once from the
// light's own portal visibility (light_views.h).
#pragma once

#include "pass_common.h"

#include <lintel/gpu/buffer.h>
#include <lintel/gpu/context.h>
#include "gpu_image.h"
#include "light_views.h"

namespace lintel::render {

class ShadowPass {
 public:
  // `set` is this pass's draw set (written here); `atlas` has one layer per slot, `resolution`^2.
  static Status create(gpu::Context& ctx, const RenderScene& scene, const LightViews& views, const DrawShared& shared,
                       VkDescriptorSet set, const GpuImage& atlas, uint32_t resolution, ShadowPass& out);
  // Renders the views of frame.lights that have atlas slots (frame.light_slots) and are to be
  // redrawn (frame.light_redraw).
  void record(VkCommandBuffer cmd, const FrameContext& frame) const;
  // New caster lists for `views` (doors or movers changed): re-uploads the commands and ids and
  // rewrites the draw set. The device must be idle.
  Status set_casters(gpu::Context& ctx, const RenderScene& scene, const LightViews& views);

 private:
  Pipeline pipeline_;
  gpu::Buffer commands_, ids_;        // every shadow view's casters, grouped by view
  std::vector<CommandRange> ranges_;  // per shadow view
  const LightViews* views_ = nullptr;
  const GpuImage* atlas_ = nullptr;
  DrawShared shared_;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  uint32_t resolution_ = 0;
};

}  // namespace lintel::render
