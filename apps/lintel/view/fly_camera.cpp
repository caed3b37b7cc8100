// Fly camera (see fly_camera.h). The target is kept one view-distance ahead of the eye, so moving
// translates both and turning rotates the target about the eye.
#include "fly_camera.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace lintel::view {

bool FlyCamera::update(const InputState& in, float dt_s) {
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  glm::vec3 forward = view_.target_world - view_.eye_world;
  const float distance = std::max(glm::length(forward), 1e-3f);
  forward /= distance;
  bool changed = false;

  if (in.look_dx != 0.0f || in.look_dy != 0.0f) {
    const float to_rad = glm::pi<float>() / 180.0f;
    float yaw = std::atan2(forward.x, -forward.z);
    float pitch = std::asin(std::clamp(forward.y, -1.0f, 1.0f));
    yaw += in.look_dx * options_.look_deg_per_pixel * to_rad;
    const float limit = options_.max_pitch_deg * to_rad;
    pitch = std::clamp(pitch - in.look_dy * options_.look_deg_per_pixel * to_rad, -limit, limit);
    forward = {std::cos(pitch) * std::sin(yaw), std::sin(pitch), -std::cos(pitch) * std::cos(yaw)};
    view_.target_world = view_.eye_world + forward * distance;
    view_.up_world = up;
    changed = true;
  }

  auto held = [&](int key) { return in.down[size_t(key)]; };
  glm::vec3 move(0.0f);
  // Looking straight up or down (a given start view may), "right" falls back to +X.
  const glm::vec3 side = glm::cross(forward, up);
  const glm::vec3 right = glm::length(side) > 1e-6f ? glm::normalize(side) : glm::vec3(1.0f, 0.0f, 0.0f);
  if (held('W')) move += forward;
  if (held('S')) move -= forward;
  if (held('D')) move += right;
  if (held('A')) move -= right;
  if (held('E')) move += up;
  if (held('Q')) move -= up;
  if (move != glm::vec3(0.0f) && dt_s > 0.0f) {
    const float speed = options_.speed_mps * (held(kKeyShift) ? options_.fast_factor : 1.0f);
    const glm::vec3 step = glm::normalize(move) * speed * dt_s;
    view_.eye_world += step;
    view_.target_world += step;
    changed = true;
  }
  return changed;
}

}  // namespace lintel::view
