// Tonemapping into the 8-bit sRGB image: the final image with the exposure pass's value (or a
// fixed exposure), or one pass shown as it is (debug views kViewAlbedo ... kViewAo; tonemap.comp).
#pragma once

#include "pass_common.h"

namespace lintel::render {

class TonemapPass {
 public:
  static Status create(VkDevice device, const ComputeBinding& binding, uint32_t width, uint32_t height, float exposure,
                       bool auto_exposure, TonemapPass& out);
  void record(VkCommandBuffer cmd, const FrameContext& frame) const;

 private:
  Pipeline pipeline_;        // any view (tonemap.comp's kAnyView)
  Pipeline final_pipeline_;  // the final image only: what every frame but a debug view records
  const ComputeBinding* binding_ = nullptr;
  uint32_t width_ = 0, height_ = 0;
  float exposure_ = 1.0f;
  bool auto_exposure_ = true;
};

}  // namespace lintel::render
