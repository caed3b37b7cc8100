// What a frame's visibility work derives from the camera's lens alone (field of view, aspect,
// near, far): the view-to-clip matrix, the near plane's half extent (the doorway rule) and the
// portal clip depth. Computing them takes tan, atan, sin and cos, whose code and tables are out of
// cache in a game's frame, yet a game's lens rarely changes: a ViewLens keeps the last lens's
// terms and recomputes them only when one of the four fields differs (docs/perf.md, "Cold
// builds"). The terms are the same doubles, bit for bit, as the functions that make them.
#pragma once

#include <lintel/view.h>

#include <glm/glm.hpp>

namespace lintel {

struct ViewLens {
  float fov_y_deg = 0.0f, aspect = 0.0f, near_m = 0.0f, far_m = 0.0f;  // all 0: nothing kept yet
  glm::dmat4 view_to_clip{1.0};                                        // view_to_clip_d()
  double near_extent = 0.0;                                            // near_half_extent()
  double clip_depth = 0.0;                                             // portal_clip_depth()

  // Makes the terms `view`'s (precondition: validate_view(view).ok()).
  void update(const View& view);
  // view_projection_d(view), bit for bit, after update(view).
  glm::dmat4 view_projection(const View& view) const { return view_to_clip * world_to_view_d(view); }
};

}  // namespace lintel
