// Light vertices: where a ray emitted by a point or spot light first lands, with the weight that
// turns a connection to it into an unbiased estimate. The second sampling strategy of
// path_radiance.cpp, the shortest light subpath of bidirectional path tracing.
#pragma once

#include "embree_scene.h"
#include "path_sampling.h"
#include "punctual_light.h"

#include <glm/glm.hpp>

#include <vector>

namespace lintel::pathtrace_detail {

struct LightVertex {
  bool valid = false;  // false: the ray escaped, or the light gives nothing there
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f};  // facing the light
  glm::vec3 albedo{0.0f};
  // albedo / pi * E(y) / pdf_area: the radiance leaving y (towards any x on its lit side), over
  // the density of having landed there.
  glm::vec3 weight{0.0f};
  float pdf_area = 0.0f;  // density of landing at y per unit area: emission_pdf * cos / d^2
};

// One vertex per light (invalid for lights without emission sampling), into `out` (resized).
// `cone_spread`: the light's rays carry a ray cone of this spread from the light (texture
// filtering at the vertex, embree_scene.h).
void sample_light_vertices(const EmbreeScene& scene, const std::vector<PunctualLight>& lights, float cone_spread,
                           PixelRng& rng, std::vector<LightVertex>& out);

}  // namespace lintel::pathtrace_detail
