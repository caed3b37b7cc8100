// One context and pass per walk, not per frame: creating a Vulkan device costs milliseconds.
#include "walk_gpu_cull.h"

#include <lintel/gpu/cull_data.h>

namespace lintel::cli {

Status WalkGpuCull::init(const World& world, const std::string& device) {
  gpu::ContextOptions options;
  options.device = device;
  if (Status s = gpu::Context::create(options, owned_); !s) return s;
  return init(world, *owned_);
}

Status WalkGpuCull::init(const World& world, gpu::Context& shared) {
  context_ = &shared;
  device_name_ = context_->info().name;
  if (Status s = gpu::CullPass::create(*context_, {}, pass_); !s) return s;
  if (Status s = gpu::pack_scene(world, {}, scene_); !s) return s;
  return pass_->set_scene(scene_);
}

Status WalkGpuCull::moved(const World& world, std::span<const uint32_t> ids) {
  if (ids.empty()) return {};
  // Re-packing is the simple way to get the moved records (bounds, cell, reach) exactly as
  // set_scene would; only `ids` travel to the GPU.
  if (Status s = gpu::pack_scene(world, {}, scene_); !s) return s;
  return pass_->update_instances(ids, scene_);
}

Status WalkGpuCull::cull(const World& world, const View& view, const VisibleSet& visible, GpuFrameDraws& out) {
  gpu::pack_visible_set(visible, view, uint32_t(world.cells.size()), frame_);
  if (Status s = pass_->set_frame(frame_); !s) return s;
  if (Status s = pass_->run(&readback_); !s) return s;
  out = {};
  for (const gpu::DrawIndexedCommand& c : readback_.commands) {
    out.instances += c.instance_count;
    out.groups_drawing += c.instance_count > 0;
  }
  return {};
}

}  // namespace lintel::cli
