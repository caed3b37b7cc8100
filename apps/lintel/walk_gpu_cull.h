// The GPU cull as a walk uses it: one Vulkan context and cull pass for the whole timeline, the
// scene uploaded once, each frame's VisibleSet culled and its draws counted.
#pragma once

#include <lintel/gpu/context.h>
#include <lintel/gpu/cull_pass.h>
#include <lintel/view.h>
#include <lintel/visible_set.h>
#include <lintel/world.h>

#include <memory>
#include <span>
#include <string>

namespace lintel::cli {

struct GpuFrameDraws {
  uint32_t instances = 0;       // instances drawn, summed over the indirect commands
  uint32_t groups_drawing = 0;  // commands with instanceCount > 0
};

class WalkGpuCull {
 public:
  // Creates the context (device: index or name substring, "" for the default) and uploads `world`.
  Status init(const World& world, const std::string& device);
  // The same on a context the walk already has (the renderer's, with --frames): no second device.
  Status init(const World& world, gpu::Context& shared);
  // Instances the walk moved since the last call (DynamicInstances::taken()): their records are
  // re-packed from `world` and uploaded by small copies (CullPass::update_instances), not the
  // whole scene again.
  Status moved(const World& world, std::span<const uint32_t> ids);
  // Culls one frame on the GPU and reads back its commands.
  Status cull(const World& world, const View& view, const VisibleSet& visible, GpuFrameDraws& out);
  const std::string& device_name() const { return device_name_; }

 private:
  std::unique_ptr<gpu::Context> owned_;  // only when init() created it
  gpu::Context* context_ = nullptr;
  std::unique_ptr<gpu::CullPass> pass_;
  gpu::CullScene scene_;
  gpu::CullFrame frame_;
  gpu::CullReadback readback_;
  std::string device_name_;
};

}  // namespace lintel::cli
