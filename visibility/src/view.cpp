// Camera validation and the view-projection matrix (right-handed, Vulkan depth range [0, w]).
// Validation returns statuses because cameras come from files and timelines; a NaN eye must not
// reach the traversal, where it would turn every comparison false and silently cull everything.
#include <lintel/view.h>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>

#include <cassert>
#include <cmath>
#include <cstdio>
#include <string>

namespace lintel {
namespace {

bool finite3(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string vec_text(const glm::vec3& v) {
  char buf[96];
  std::snprintf(buf, sizeof(buf), "(%g, %g, %g)", double(v.x), double(v.y), double(v.z));
  return buf;
}

}  // namespace

Status validate_view(const View& view) {
  if (!finite3(view.eye_world)) return Status::error("view: eye is not finite " + vec_text(view.eye_world));
  if (!finite3(view.target_world)) return Status::error("view: target is not finite " + vec_text(view.target_world));
  if (!finite3(view.up_world)) return Status::error("view: up is not finite " + vec_text(view.up_world));
  const glm::dvec3 forward = glm::dvec3(view.target_world) - glm::dvec3(view.eye_world);
  const double distance = glm::length(forward);
  if (!(distance > 1e-6))
    return Status::error("view: eye " + vec_text(view.eye_world) + " equals target " + vec_text(view.target_world));
  const double up_length = glm::length(glm::dvec3(view.up_world));
  if (!(up_length > 0.0)) return Status::error("view: up vector is zero");
  const double sin_angle = glm::length(glm::cross(forward / distance, glm::dvec3(view.up_world) / up_length));
  if (!(sin_angle > 1e-6))
    return Status::error("view: up " + vec_text(view.up_world) + " is parallel to the view direction");
  if (!(view.fov_y_deg > 0.0f && view.fov_y_deg <= 179.0f))
    return Status::error("view: fov_y_deg " + std::to_string(view.fov_y_deg) + " is outside (0, 179]");
  if (!(view.aspect > 0.0f && view.aspect <= 1e4f))
    return Status::error("view: aspect " + std::to_string(view.aspect) + " is outside (0, 1e4]");
  if (!(view.near_m > 0.0f && std::isfinite(view.near_m)))
    return Status::error("view: near " + std::to_string(view.near_m) + " is not a positive distance");
  if (!(view.far_m > view.near_m && std::isfinite(view.far_m)))
    return Status::error("view: far " + std::to_string(view.far_m) + " is not beyond near " +
                         std::to_string(view.near_m));
  return {};
}

glm::dmat4 view_to_clip_d(const View& view) {
  return glm::perspectiveRH_ZO(glm::radians(double(view.fov_y_deg)), double(view.aspect), double(view.near_m),
                               double(view.far_m));
}

glm::dmat4 world_to_view_d(const View& view) {
  return glm::lookAtRH(glm::dvec3(view.eye_world), glm::dvec3(view.target_world), glm::dvec3(view.up_world));
}

glm::dmat4 view_projection_d(const View& view) {
  assert(validate_view(view).ok());
  return view_to_clip_d(view) * world_to_view_d(view);
}

glm::mat4 view_projection(const View& view) { return glm::mat4(view_projection_d(view)); }

glm::dvec3 view_forward_d(const View& view) {
  return glm::normalize(glm::dvec3(view.target_world) - glm::dvec3(view.eye_world));
}

double near_half_extent(const View& view) {
  const double half_height = double(view.near_m) * std::tan(glm::radians(double(view.fov_y_deg)) * 0.5);
  return half_height * std::sqrt(1.0 + double(view.aspect) * double(view.aspect));
}

}  // namespace lintel
