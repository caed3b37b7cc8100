// The lighting pass's dispatch.
#include "lighting_pass.h"

#include "lintel_render_spirv.h"

namespace lintel::render {

Status LightingPass::create(VkDevice device, const ComputeBinding& binding, uint32_t width, uint32_t height, bool gi,
                            bool ao, bool emission, glm::vec3 environment, LightingPass& out) {
  out.environment_ = environment;
  out.binding_ = &binding;
  out.width_ = width;
  out.height_ = height;
  out.gi_ = gi;
  out.ao_ = ao;
  const uint32_t spec[] = {emission ? 1u : 0u};  // lighting.comp's kEmission
  return create_compute_pass_pipeline(device, binding, gpu::spirv::lighting_comp(), "lighting.comp", out.pipeline_,
                                      spec);
}

void LightingPass::record(VkCommandBuffer cmd, const FrameContext& frame) const {
  LightingPush p{};
  p.clip_to_world = glm::inverse(frame.view_proj);
  p.size = glm::uvec4(width_, height_, gi_ ? 1u : 0u, ao_ ? 1u : 0u);
  p.mode = glm::uvec4(uint32_t(frame.lights.size()), frame.debug_view, 0, 0);
  p.environment = glm::vec4(environment_, 0.0f);
  binding_->dispatch(cmd, frame.slot, pipeline_.handle(), &p, sizeof(p), groups_for(width_, kTileSize),
                     groups_for(height_, kTileSize));
}

}  // namespace lintel::render
