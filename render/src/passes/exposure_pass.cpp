// The exposure pass's dispatch.
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
  return create_compute_pass_pipeline(device, binding, gpu::spirv::exposure_comp(), "exposure.comp", out.pipeline_);
}

void ExposurePass::record(VkCommandBuffer cmd, const FrameContext& frame) const {
  ExposurePush p{};
  p.params = glm::vec4(multiplier_, 0.0f, 0.0f, 0.0f);
  // Up to about 256 K samples: a strided subset of big frames says the same.
  const uint32_t pixels = width_ * height_;
  p.size = glm::uvec4(width_, height_, std::max(1u, pixels / (1u << 18)), 0);
  binding_->dispatch(cmd, frame.slot, pipeline_.handle(), &p, sizeof(p), 1, 1);
}

}  // namespace lintel::render
