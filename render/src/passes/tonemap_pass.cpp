// The tonemap pass's dispatch. Whether the exposure pass's value is used is decided when
// recording, so a debug view can be switched between frames (Renderer::set_debug_view).
#include "tonemap_pass.h"

#include "lintel_render_spirv.h"

namespace lintel::render {

Status TonemapPass::create(VkDevice device, const ComputeBinding& binding, uint32_t width, uint32_t height,
                           float exposure, bool auto_exposure, TonemapPass& out) {
  out.binding_ = &binding;
  out.width_ = width;
  out.height_ = height;
  out.exposure_ = exposure;
  out.auto_exposure_ = auto_exposure;
  const uint32_t final_only[] = {0};  // tonemap.comp's kAnyView
  if (Status s = create_compute_pass_pipeline(device, binding, gpu::spirv::tonemap_comp(), "tonemap.comp",
                                              out.final_pipeline_, final_only);
      !s)
    return s;
  return create_compute_pass_pipeline(device, binding, gpu::spirv::tonemap_comp(), "tonemap.comp", out.pipeline_);
}

void TonemapPass::record(VkCommandBuffer cmd, const FrameContext& frame) const {
  TonemapPush p{};
  p.params = glm::vec4(exposure_, frame.view.near_m, frame.view.far_m, 15.0f);
  const bool use_auto = auto_exposure_ && frame.debug_view == kViewFinal;
  p.size = glm::uvec4(width_, height_, frame.debug_view, use_auto ? 1u : 0u);
  const Pipeline& pipeline = frame.debug_view == kViewFinal ? final_pipeline_ : pipeline_;
  binding_->dispatch(cmd, frame.slot, pipeline.handle(), &p, sizeof(p), groups_for(width_, kTileSize),
                     groups_for(height_, kTileSize));
}

}  // namespace lintel::render
