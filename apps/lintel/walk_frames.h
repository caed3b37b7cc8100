// `lintel walk --frames DIR`: every (or every Nth) frame of the timeline rendered to
// DIR/frame_NNNNN.png, then DIR/contact_sheet.png and, where ffmpeg is on PATH, DIR/walk.mp4.
// Probes persist between frames (GI converges along the walk). Door events and moving instances
// reach the renderer before each rendered frame.
#pragma once

#include "render_args.h"

#include <lintel/view.h>
#include <lintel/visible_set.h>
#include <lintel/world.h>

#include <span>
#include <string>
#include <vector>

namespace lintel::cli {

class WalkFrames {
 public:
  // Creates DIR if needed (its parent must exist) and the renderer.
  Status init(const World& world, const std::string& dir, const RenderArgs& args, const std::string& device);
  // Instances moved since the last call (DynamicInstances::taken()): kept until the next render().
  void note_moved(std::span<const uint32_t> moved);
  // Renders one frame of `world` as it is now (its doors, and the instances noted as moved, reach
  // the renderer first: Renderer::update_world) from the walk's own `visible`, built for `view`:
  // visibility is built once per frame. `view.aspect` must be aspect() (the walk builds with it).
  Status render(size_t frame, const View& view, const VisibleSet& visible, const World& world);
  // The rendered image's width / height: the walk's views use it, so the regions it builds are
  // the ones the renderer's camera sees.
  float aspect() const { return float(args_.width) / float(args_.height); }
  // The renderer's Vulkan context: `walk --gpu-cull --frames` culls on it (one device per walk).
  gpu::Context& context() { return *session_.context; }
  // Contact sheet (and MP4 at `fps` if ffmpeg exists). Prints what it wrote unless quiet.
  Status finish(double fps, bool quiet);
  double total_ms() const { return total_ms_; }
  size_t frames_written() const { return written_.size(); }

 private:
  std::string dir_;
  RenderArgs args_;
  RenderSession session_;
  std::vector<std::string> written_;
  std::vector<uint32_t> moved_;  // since the last rendered frame, ascending, each once
  double total_ms_ = 0.0;
};

}  // namespace lintel::cli
