// The viewer's fly camera: WASD along the view and its right vector, Q/E down/up along world +Y,
// shift four times faster, mouse look (yaw about +Y, pitch clamped short of the poles) while the
// right button is held. It keeps the View it was given untouched until an input moves it, so a
// camera that has not moved renders exactly like `lintel render` with the same eye and target.
#pragma once

#include "view_input.h"

#include <lintel/view.h>

namespace lintel::view {

struct FlyCameraOptions {
  float speed_mps = 2.0f;    // walking speed (meters per second)
  float fast_factor = 4.0f;  // with shift held
  float look_deg_per_pixel = 0.15f;
  float max_pitch_deg = 89.0f;
};

class FlyCamera {
 public:
  explicit FlyCamera(const View& start, FlyCameraOptions options = {}) : view_(start), options_(options) {}

  // Moves by the held keys for `dt_s` seconds and turns by this frame's mouse look.
  // Returns whether the view changed.
  bool update(const InputState& input, float dt_s);
  // Jumps to `view` (timeline playback).
  void set(const View& view) { view_ = view; }
  const View& view() const { return view_; }

 private:
  View view_;
  FlyCameraOptions options_;
};

}  // namespace lintel::view
