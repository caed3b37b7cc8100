// The radiance estimate of one camera ray: a diffuse path with next-event estimation of every
// punctual light at every vertex, optionally combined with connections to light vertices by
// multiple importance sampling (the integrator of path_tracer.h's conventions).
#pragma once

#include "embree_scene.h"
#include "light_vertex.h"
#include "path_sampling.h"
#include "punctual_light.h"

#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace lintel::pathtrace_detail {

struct PathSettings {
  uint32_t max_bounces = 4;
  bool light_connections = true;
  glm::vec3 environment{0.0f};  // radiance of every ray that leaves the scene (World::environment)
  // The pixel's angle (radians): every ray of a path, and of its light vertices, carries a cone
  // of this spread from where the path starts (the eye, or the light), for texture filtering.
  float cone_spread = 0.0f;
  // Linked portals (mirrors, teleports): camera rays go through them (path_tracer.h).
  std::span<const Portal> linked_portals;
};

// Radiance arriving at `origin` from direction -dir (unit). Unbiased for the light transport
// truncated after max_bounces diffuse bounces, with or without light connections.
// `light_vertices` is scratch reused between calls (one per thread).
glm::vec3 path_radiance(const EmbreeScene& scene, const std::vector<PunctualLight>& lights, const glm::vec3& origin,
                        const glm::vec3& dir, const PathSettings& settings, PixelRng& rng,
                        std::vector<LightVertex>& light_vertices);

}  // namespace lintel::pathtrace_detail
