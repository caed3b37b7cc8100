// Deferred lighting: per pixel, the active lights that reach its cell (PCF shadows from the
// atlas), its cell's probes and the AO, into the HDR image (lighting.comp).
#pragma once

#include "pass_common.h"

namespace lintel::render {

class LightingPass {
 public:
  // emission: whether the scene has emissive surfaces (the pass then adds the g-buffer's emission).
  static Status create(VkDevice device, const ComputeBinding& binding, uint32_t width, uint32_t height, bool gi,
                       bool ao, bool emission, glm::vec3 environment, LightingPass& out);
  void record(VkCommandBuffer cmd, const FrameContext& frame) const;

 private:
  Pipeline pipeline_;
  const ComputeBinding* binding_ = nullptr;
  uint32_t width_ = 0, height_ = 0;
  bool gi_ = false, ao_ = false;
  glm::vec3 environment_{0.0f};  // World::environment: the sky's radiance
};

}  // namespace lintel::render
