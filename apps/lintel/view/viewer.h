// The `lintel view` frame loop, as a game would write it around Lintel: per frame, input (window
// or script) -> camera (fly or timeline) -> viewer cell (ViewerTracker) -> visibility
// (VisibilityBuilder, for the overlays and the HUD) -> Renderer::render -> overlays on the RGBA8
// -> upload + present (Presenter, 2 frames in flight). Key toggles rebuild the renderer where
// RenderOptions cannot change at run time (culling method, GI, AO).
#pragma once

#include "fly_camera.h"
#include "presenter.h"
#include "view_input.h"
#include "window_device.h"

#include <lintel/gpu/context.h>
#include <lintel/render/renderer.h>
#include <lintel/viewer_tracker.h>
#include <lintel/visibility_builder.h>
#include <lintel/world.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lintel::view {

struct ViewerOptions {
  render::RenderOptions render;  // width, height, view, gi, ao, camera_cull at the start
  bool overlays = true;
  bool play_timeline = false;
  uint64_t max_frames = 0;  // 0: until the window closes, Escape, or the script ends
  std::string screenshot;   // --screenshot: default path of script screenshots; else the last frame
  bool quiet = false;
};

struct ViewerSummary {
  uint64_t frames = 0;
  View last_view;
  uint32_t last_cell = 0;
  double median_frame_ms = 0.0;
  std::vector<std::string> screenshots;  // written, in order
};

// What the GLFW callbacks collect between two frames (the window's user pointer).
struct WindowInputQueue {
  std::vector<InputEvent> events;
  double cursor_x = 0.0, cursor_y = 0.0;  // the last cursor position, to turn positions into moves
  bool cursor_known = false;
};

class Viewer {
 public:
  // `script` empty: input from the window. The device must outlive the viewer.
  Viewer(World& world, WindowDevice& device, const ViewerOptions& options, const View& start,
         std::optional<std::vector<ScriptEvent>> script);
  ~Viewer();
  // Wraps the device for Lintel, builds the renderer and the presenter.
  Status open();
  // Runs until done. Errors: Vulkan failures, validation messages (Internal), unwritable screenshots.
  Status run(ViewerSummary& summary);

 private:
  Status rebuild_renderer();
  Status handle_toggles(const InputState& input);
  void update_camera(const InputState& input, float dt_s);
  std::vector<std::string> hud_lines(double build_us, double frame_ms) const;
  Status save_screenshot(const std::string& path, const std::vector<uint8_t>& rgba8, ViewerSummary& summary);
  Status check_validation();
  void gather_window_input(InputState& state);

  World& world_;
  WindowDevice& device_;
  ViewerOptions options_;
  FlyCamera camera_;
  std::optional<ScriptPlayer> script_;
  std::unique_ptr<gpu::Context> context_;
  std::unique_ptr<render::Renderer> renderer_;
  std::unique_ptr<Presenter> presenter_;
  ViewerTracker tracker_;
  VisibilityBuilder builder_;
  VisibleSet visible_;
  const Timeline* timeline_ = nullptr;
  double timeline_t_ = 0.0;
  std::string last_transition_ = "none";
  WindowInputQueue window_input_;
};

}  // namespace lintel::view
