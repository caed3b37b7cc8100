// Automatic exposure: the frame's log-average luminance to middle grey, held down so that only
// the brightest 0.5 % of lit pixels can reach white (exposure.comp). A two-level reduction in two
// graph passes: many workgroups write per-workgroup histograms, one workgroup resolves them.
#pragma once

#include "pass_common.h"

namespace lintel::render {

class ExposurePass {
 public:
  // `multiplier`: RenderOptions::exposure, applied on top.
  static Status create(VkDevice device, const ComputeBinding& binding, uint32_t width, uint32_t height,
                       float multiplier, ExposurePass& out);
  // Bytes the exposure buffer needs: the value and one slot per histogram workgroup.
  static VkDeviceSize buffer_bytes();
  void record_histogram(VkCommandBuffer cmd, const FrameContext& frame) const;
  void record_resolve(VkCommandBuffer cmd, const FrameContext& frame) const;

 private:
  void record_stage(VkCommandBuffer cmd, const FrameContext& frame, uint32_t stage, uint32_t groups) const;

  Pipeline pipeline_;
  const ComputeBinding* binding_ = nullptr;
  uint32_t width_ = 0, height_ = 0;
  uint32_t groups_ = 1;  // histogram workgroups: one per kExposureGroupSize x kExposurePixelsPerThread pixels, capped
  float multiplier_ = 1.0f;
};

}  // namespace lintel::render
