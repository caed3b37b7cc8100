// Point, spot and directional lights as glTF's KHR_lights_punctual defines them: intensity in
// candela (point, spot) or lux (directional), the recommended range window
// clamp(1 - (d / range)^4, 0, 1)^2 from the extension's README, and the spot cone attenuation of
// its reference implementation (smooth between cos(outer) and cos(inner), squared).
#include "punctual_light.h"

#include "path_sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace lintel::pathtrace_detail {
namespace {

bool finite3(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

Status prepare_light(const Light& light, size_t index, PunctualLight& out) {
  const std::string name = "light " + std::to_string(index) + " '" + light.name + "'";
  if (!finite3(light.color) || !std::isfinite(light.intensity) || light.intensity < 0.0f)
    return Status::error(name + ": color or intensity is not a finite non-negative value");
  if (!std::isfinite(light.range) || light.range < 0.0f) return Status::error(name + ": range is not finite and >= 0");
  if (!finite3(light.position_world) || !finite3(light.direction_world) || glm::length(light.direction_world) <= 0.0f)
    return Status::error(name + ": position or direction is not finite, or the direction is zero");
  out.type = light.type;
  out.intensity = light.color * light.intensity;
  out.position_world = light.position_world;
  out.direction_world = glm::normalize(light.direction_world);
  out.range = light.range;
  const float cos_outer = std::cos(light.outer_cone_rad);
  out.spot_scale = 1.0f / std::max(0.001f, std::cos(light.inner_cone_rad) - cos_outer);
  out.spot_offset = -cos_outer * out.spot_scale;
  out.cos_outer = light.type == Light::Type::Spot ? cos_outer : -1.0f;
  return {};
}

bool sample_light(const PunctualLight& light, const glm::vec3& x, LightSample& out) {
  if (light.type == Light::Type::Directional) {
    out.to_light = -light.direction_world;
    out.distance = std::numeric_limits<float>::infinity();
    out.irradiance = light.intensity;
    return true;
  }
  const glm::vec3 delta = light.position_world - x;
  const float d2 = glm::dot(delta, delta);
  if (!(d2 > 0.0f)) return false;
  const float d = std::sqrt(d2);
  out.to_light = delta / d;
  out.distance = d;
  float factor = 1.0f / d2;
  if (light.range > 0.0f) {
    const float ratio2 = d2 / (light.range * light.range);
    const float window = std::clamp(1.0f - ratio2 * ratio2, 0.0f, 1.0f);
    factor *= window * window;
  }
  if (light.type == Light::Type::Spot) {
    const float cd = glm::dot(light.direction_world, -out.to_light);
    const float cone = std::clamp(cd * light.spot_scale + light.spot_offset, 0.0f, 1.0f);
    factor *= cone * cone;
  }
  if (!(factor > 0.0f)) return false;
  out.irradiance = light.intensity * factor;
  return true;
}

bool has_emission_sampling(const PunctualLight& light) {
  // A directional light would need a disk over the whole scene, where most rays land outside
  // (the ground around a house): the plain bounce already samples it well.
  // A spot with a (nearly) zero outer cone has no solid angle to sample from.
  if (light.type == Light::Type::Directional || (light.type == Light::Type::Spot && !(1.0f - light.cos_outer > 1e-6f)))
    return false;
  return light.intensity.x > 0.0f || light.intensity.y > 0.0f || light.intensity.z > 0.0f;
}

glm::vec3 sample_emission(const PunctualLight& light, float u1, float u2) {
  // Uniform in the cap cos(theta) in [cos_outer, 1] about the axis (the whole sphere for a point
  // light, cos_outer = -1).
  const float cos_theta = 1.0f - u1 * (1.0f - light.cos_outer);
  const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
  const float phi = 2.0f * kPi * u2;
  glm::vec3 t, b;
  const glm::vec3 axis = light.type == Light::Type::Spot ? light.direction_world : glm::vec3(0.0f, 0.0f, 1.0f);
  orthonormal_basis(axis, t, b);
  return glm::normalize(sin_theta * std::cos(phi) * t + sin_theta * std::sin(phi) * b + cos_theta * axis);
}

float emission_pdf(const PunctualLight& light, const glm::vec3& dir) {
  if (!has_emission_sampling(light)) return 0.0f;
  if (light.type == Light::Type::Spot && glm::dot(dir, light.direction_world) < light.cos_outer) return 0.0f;
  return 1.0f / (2.0f * kPi * (1.0f - light.cos_outer));
}

}  // namespace lintel::pathtrace_detail
