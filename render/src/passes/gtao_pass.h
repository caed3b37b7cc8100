// Ground-truth ambient occlusion (Jimenez et al. 2016) from the g-buffer's depth and normals,
// within the pixel's own cell (gtao.comp); by default at half resolution (one pixel per 2x2 block)
// followed by a depth- and cell-aware upsample to full resolution (ao_upsample.comp).
#pragma once

#include "pass_common.h"

namespace lintel::render {

struct GtaoSettings {
  uint32_t width = 0, height = 0;
  float radius_m = 0.6f;
  uint32_t slices = 3, steps = 6;
  bool half_resolution = true;
};

class GtaoPass {
 public:
  static Status create(VkDevice device, const ComputeBinding& binding, const GtaoSettings& settings, GtaoPass& out);
  void record(VkCommandBuffer cmd, const FrameContext& frame) const;
  // Half resolution only: the upsample into the full-resolution AO image.
  void record_upsample(VkCommandBuffer cmd, const FrameContext& frame) const;

 private:
  Pipeline pipeline_, upsample_;
  const ComputeBinding* binding_ = nullptr;
  GtaoSettings settings_;
};

}  // namespace lintel::render
