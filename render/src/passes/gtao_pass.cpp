// The GTAO pass: the camera's view space and projection as push constants, one dispatch.
#include "gtao_pass.h"

#include "lintel_render_spirv.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace lintel::render {

Status GtaoPass::create(VkDevice device, const ComputeBinding& binding, const GtaoSettings& settings, GtaoPass& out) {
  out.binding_ = &binding;
  out.settings_ = settings;
  return create_compute_pass_pipeline(device, binding, gpu::spirv::gtao_comp(), "gtao.comp", out.pipeline_);
}

void GtaoPass::record(VkCommandBuffer cmd, const FrameContext& frame) const {
  const View& view = frame.view;
  GtaoPush p{};
  p.world_to_view = glm::lookAtRH(view.eye_world, view.target_world, view.up_world);
  const float ty_half = std::tan(glm::radians(view.fov_y_deg) * 0.5f);
  p.projection = glm::vec4(ty_half * view.aspect, ty_half, view.near_m, view.far_m);
  p.params = glm::vec4(settings_.radius_m, float(settings_.slices), float(settings_.steps), 0.4f);
  p.size = glm::uvec4(settings_.width, settings_.height, 0, 0);
  binding_->dispatch(cmd, frame.slot, pipeline_.handle(), &p, sizeof(p), groups_for(settings_.width, kTileSize),
                     groups_for(settings_.height, kTileSize));
}

}  // namespace lintel::render
