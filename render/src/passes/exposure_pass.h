// Automatic exposure: the frame's log-average luminance to middle grey, held down so that only
// the brightest 0.5 % of lit pixels can reach white; one workgroup writes one float (exposure.comp).
#pragma once

#include "pass_common.h"

namespace lintel::render {

class ExposurePass {
 public:
  // `multiplier`: RenderOptions::exposure, applied on top.
  static Status create(VkDevice device, const ComputeBinding& binding, uint32_t width, uint32_t height,
                       float multiplier, ExposurePass& out);
  void record(VkCommandBuffer cmd, const FrameContext& frame) const;

 private:
  Pipeline pipeline_;
  const ComputeBinding* binding_ = nullptr;
  uint32_t width_ = 0, height_ = 0;
  float multiplier_ = 1.0f;
};

}  // namespace lintel::render
