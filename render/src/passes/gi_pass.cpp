// The GI passes' dispatches.
#include "gi_pass.h"

#include "lintel_render_spirv.h"

namespace lintel::render {

Status GiPass::create(VkDevice device, const ComputeBinding& binding, uint32_t surfels, uint32_t probes, bool persist,
                      GiPass& out) {
  out.binding_ = &binding;
  out.surfels_ = surfels;
  out.probes_ = probes;
  out.persist_ = persist;
  if (Status s = create_compute_pass_pipeline(device, binding, gpu::spirv::surfel_light_comp(), "surfel_light.comp",
                                              out.light_);
      !s)
    return s;
  return create_compute_pass_pipeline(device, binding, gpu::spirv::probe_gather_comp(), "probe_gather.comp",
                                      out.gather_);
}

void GiPass::record_light(VkCommandBuffer cmd, const FrameContext& frame, uint32_t bounce) const {
  if (bounce >= frame.gi_bounces) return;  // an amortised frame runs fewer iterations
  SurfelLightPush p{};
  // Bounce 0 of a fresh frame reads no probes (they are zero); with persistence every iteration
  // builds on the previous frame's.
  p.counts = glm::uvec4(surfels_, uint32_t(frame.lights.size()), persist_ ? bounce + 1 : bounce, 0);
  binding_->dispatch(cmd, frame.slot, light_.handle(), &p, sizeof(p), groups_for(surfels_, kLinearGroupSize), 1);
}

void GiPass::record_gather(VkCommandBuffer cmd, const FrameContext& frame, uint32_t bounce) const {
  if (bounce >= frame.gi_bounces) return;
  ProbeGatherPush p{};
  p.counts = glm::uvec4(probes_, 0, 0, 0);
  binding_->dispatch(cmd, frame.slot, gather_.handle(), &p, sizeof(p), groups_for(probes_, kLinearGroupSize), 1);
}

}  // namespace lintel::render
