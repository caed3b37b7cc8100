// The GTAO pass: the camera's view space and projection as push constants, one dispatch.
#include "gtao_pass.h"

#include "lintel_render_spirv.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace lintel::render {

Status GtaoPass::create(VkDevice device, const ComputeBinding& binding, const GtaoSettings& settings, GtaoPass& out) {
  out.binding_ = &binding;
  out.settings_ = settings;
  if (Status s = create_compute_pass_pipeline(device, binding, gpu::spirv::gtao_comp(), "gtao.comp", out.pipeline_); !s)
    return s;
  if (!settings.half_resolution) return {};
  return create_compute_pass_pipeline(device, binding, gpu::spirv::ao_upsample_comp(), "ao_upsample.comp",
                                      out.upsample_);
}

void GtaoPass::record(VkCommandBuffer cmd, const FrameContext& frame) const {
  const View& view = frame.view;
  GtaoPush p{};
  p.world_to_view = glm::lookAtRH(view.eye_world, view.target_world, view.up_world);
  const float ty_half = std::tan(glm::radians(view.fov_y_deg) * 0.5f);
  p.projection = glm::vec4(ty_half * view.aspect, ty_half, view.near_m, view.far_m);
  p.params = glm::vec4(settings_.radius_m, float(settings_.slices), float(settings_.steps), 0.4f);
  const uint32_t scale = settings_.half_resolution ? 2u : 1u;
  p.size = glm::uvec4(settings_.width, settings_.height, scale, 0);
  binding_->dispatch(cmd, frame.slot, pipeline_.handle(), &p, sizeof(p),
                     groups_for(groups_for(settings_.width, scale), kTileSize),
                     groups_for(groups_for(settings_.height, scale), kTileSize));
}

void GtaoPass::record_upsample(VkCommandBuffer cmd, const FrameContext& frame) const {
  AoUpsamplePush p{};
  // Samples whose view depth differs from the pixel's by 10 % or more get no weight: adjacent
  // pixels of one surface differ far less at the radii GTAO sees; a silhouette differs more.
  p.params = glm::vec4(0.1f, 0.0f, 0.0f, 0.0f);
  p.projection = glm::vec4(0.0f, 0.0f, frame.view.near_m, frame.view.far_m);
  p.size =
      glm::uvec4(settings_.width, settings_.height, groups_for(settings_.width, 2), groups_for(settings_.height, 2));
  binding_->dispatch(cmd, frame.slot, upsample_.handle(), &p, sizeof(p), groups_for(settings_.width, kTileSize),
                     groups_for(settings_.height, kTileSize));
}

}  // namespace lintel::render
