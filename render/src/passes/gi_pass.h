// Diffuse GI in two compute passes repeated per bounce: surfel light (each surfel's direct light
// through the shadow atlas plus its cell's probes, surfel_light.comp) and probe gather (each
// probe's SH from its cell's surfels and portal surfels, probe_gather.comp). docs/rendering.md.
#pragma once

#include "pass_common.h"

namespace lintel::render {

class GiPass {
 public:
  // `persist`: probes carry over between frames, so every bounce builds on the previous frame.
  static Status create(VkDevice device, const ComputeBinding& binding, uint32_t surfels, uint32_t probes, bool persist,
                       GiPass& out);
  void record_light(VkCommandBuffer cmd, const FrameContext& frame, uint32_t bounce) const;
  void record_gather(VkCommandBuffer cmd, const FrameContext& frame, uint32_t bounce) const;

 private:
  Pipeline light_, gather_;
  const ComputeBinding* binding_ = nullptr;
  uint32_t surfels_ = 0, probes_ = 0;
  bool persist_ = false;
};

}  // namespace lintel::render
