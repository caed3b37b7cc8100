// KHR_lights_punctual lights in the form the path tracer samples them: the irradiance a light
// delivers at a point, before the cosine and the shadow ray. The formulas are the ones written in
// path_tracer.h, which the realtime renderer shares.
#pragma once

#include <lintel/status.h>
#include <lintel/world.h>

#include <glm/glm.hpp>

namespace lintel::pathtrace_detail {

// A World light with the per-light constants folded in once.
struct PunctualLight {
  Light::Type type = Light::Type::Point;
  glm::vec3 intensity{0.0f};  // color * intensity: cd (point/spot) or lux (directional)
  glm::vec3 position_world{0.0f};
  glm::vec3 direction_world{0.0f};  // unit, the way the light shines
  float range = 0.0f;               // 0: no window
  float spot_scale = 0.0f, spot_offset = 0.0f;
  float cos_outer = -1.0f;  // spot: emission directions are sampled inside this cone
};

// Fails, naming the light, on non-finite values, a zero direction or a negative range/intensity.
Status prepare_light(const Light& light, size_t index, PunctualLight& out);

// What one light delivers at x, to be multiplied by max(0, n.l) and the shadow ray's visibility.
struct LightSample {
  glm::vec3 to_light{0.0f};    // unit l
  float distance = 0.0f;       // to the light; infinity for a directional light
  glm::vec3 irradiance{0.0f};  // on a surface facing the light (n == l)
};

// False when the light delivers nothing at x (beyond its range, outside its cone, or x at the
// light itself), so no shadow ray is needed.
bool sample_light(const PunctualLight& light, const glm::vec3& x, LightSample& out);

// Emission sampling, for light-vertex connections (path_radiance.cpp): point lights emit
// uniformly over the sphere, spot lights uniformly over their outer cone; directional lights are
// not sampled this way. emission_pdf is the solid-angle density of emitting towards unit `dir`
// (0 outside a spot's cone and for directional lights).
bool has_emission_sampling(const PunctualLight& light);
glm::vec3 sample_emission(const PunctualLight& light, float u1, float u2);
float emission_pdf(const PunctualLight& light, const glm::vec3& dir);

}  // namespace lintel::pathtrace_detail
