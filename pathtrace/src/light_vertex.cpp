// Emitting one ray per point/spot light and keeping its first hit: the light subpath of length
// one in bidirectional path tracing (Veach, "Robust Monte Carlo Methods for Light Transport
// Simulation", PhD thesis, 1997, ch. 10; Lafortune and Willems, "Bi-directional Path Tracing",
// 1993). Connecting camera vertices to it finds a small, brightly lit patch (the ceiling just
// above a lamp) that a cosine-sampled bounce almost never hits.
#include "light_vertex.h"

namespace lintel::pathtrace_detail {

void sample_light_vertices(const EmbreeScene& scene, const std::vector<PunctualLight>& lights, float cone_spread,
                           PixelRng& rng, std::vector<LightVertex>& out) {
  out.resize(lights.size());
  for (size_t i = 0; i < lights.size(); ++i) {
    LightVertex& v = out[i];
    v.valid = false;
    const PunctualLight& light = lights[i];
    if (!has_emission_sampling(light)) continue;
    const float u1 = rng.uniform(), u2 = rng.uniform();
    const glm::vec3 dir = sample_emission(light, u1, u2);
    SurfaceHit hit;
    if (!scene.intersect(light.position_world, dir, RayCone{0.0f, cone_spread}, hit)) continue;
    LightSample s;
    if (!sample_light(light, hit.position_world, s)) continue;
    const float cos_y = glm::dot(hit.normal_world, s.to_light);  // the normal faces the light
    const float pdf_dir = emission_pdf(light, dir);
    if (!(cos_y > 0.0f) || !(pdf_dir > 0.0f)) continue;
    const float d2 = s.distance * s.distance;
    v.valid = true;
    v.position = hit.position_world;
    v.normal = hit.normal_world;
    v.albedo = hit.albedo;
    v.pdf_area = pdf_dir * cos_y / d2;
    // E(y) / pdf_area = (I_eff / d^2 * cos_y) / (pdf_dir * cos_y / d^2) = I_eff / pdf_dir: the
    // 1 / d^2 that makes the ceiling above a lamp a firefly source cancels here.
    v.weight = hit.albedo * (1.0f / kPi) * s.irradiance * (d2 / pdf_dir);
  }
}

}  // namespace lintel::pathtrace_detail
