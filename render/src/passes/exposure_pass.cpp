// The exposure pass's two dispatches: the per-workgroup histograms, then the resolve.
#include "exposure_pass.h"

#include "lintel_render_spirv.h"

#include <algorithm>

namespace lintel::render {

Status ExposurePass::create(VkDevice device, const ComputeBinding& binding, uint32_t width, uint32_t height,
                            float multiplier, ExposurePass& out) {
  out.binding_ = &binding;
  out.width_ = width;
  out.height_ = height;
  out.multiplier_ = multiplier;
  const uint64_t per_group = uint64_t(kExposureGroupSize) * kExposurePixelsPerThread;
  const uint64_t pixels = uint64_t(width) * height;
  out.groups_ = uint32_t(std::clamp<uint64_t>((pixels + per_group - 1) / per_group, 1, kExposureMaxGroups));
  return create_compute_pass_pipeline(device, binding, gpu::spirv::exposure_comp(), "exposure.comp", out.pipeline_);
}

VkDeviceSize ExposurePass::buffer_bytes() { return 4 * (4 + VkDeviceSize(kExposureMaxGroups) * kExposureSlotFloats); }

void ExposurePass::record_stage(VkCommandBuffer cmd, const FrameContext& frame, uint32_t stage, uint32_t groups) const {
  ExposurePush p{};
  p.params = glm::vec4(multiplier_, 0.0f, 0.0f, 0.0f);
  p.size = glm::uvec4(width_, height_, groups_, stage);
  binding_->dispatch(cmd, frame.slot, pipeline_.handle(), &p, sizeof(p), groups, 1);
}

void ExposurePass::record_histogram(VkCommandBuffer cmd, const FrameContext& frame) const {
  record_stage(cmd, frame, 0, groups_);
}

void ExposurePass::record_resolve(VkCommandBuffer cmd, const FrameContext& frame) const {
  record_stage(cmd, frame, 1, 1);
}

}  // namespace lintel::render
