// Path tracing with next-event estimation (Kajiya, "The Rendering Equation", SIGGRAPH 1986;
// Pharr, Jakob, Humphreys, "Physically Based Rendering", 4th ed., ch. 13) specialised to what
// Lintel's scenes hold: Lambertian surfaces and punctual lights. With cosine-weighted bounces the
// Lambertian BRDF times cosine over pdf is just the albedo.
//
// Light that bounced once, from x via y to a point or spot light L, has two strategies:
//   bounce:  x samples a cosine direction that lands on y, then y samples L (next-event);
//            density of y per area  p_bounce = cos_x / pi * cos_y / |x - y|^2;
//   connect: L emits a ray that lands on y (light_vertex.h), then x connects to y;
//            density p_connect = emission_pdf * cos_yL / |y - L|^2.
// Each is weighted by the power heuristic (Veach and Guibas, "Optimally Combining Sampling
// Techniques for Monte Carlo Rendering", SIGGRAPH 1995), so their sum stays unbiased and the one
// that sees a bright patch well (connect, for the ceiling above a lamp) carries it.
#include "path_radiance.h"

#include <lintel/portal_link.h>

#include <limits>

namespace lintel::pathtrace_detail {
namespace {

// Power heuristic (beta = 2) written as a ratio, so infinite or huge densities cannot overflow.
float power_heuristic(float pdf_self, float pdf_other) {
  if (!(pdf_self > 0.0f)) return 0.0f;
  const float r = pdf_other / pdf_self;
  return 1.0f / (1.0f + r * r);
}

struct PathVertex {
  glm::vec3 position{0.0f}, normal{0.0f}, albedo{0.0f};
};

// Density per unit area at `to` of a cosine-weighted bounce from `from` (0 when behind either).
float bounce_pdf_area(const PathVertex& from, const glm::vec3& to_position, const glm::vec3& to_normal) {
  const glm::vec3 d = to_position - from.position;
  const float dist2 = glm::dot(d, d);
  if (!(dist2 > 0.0f)) return std::numeric_limits<float>::infinity();
  const glm::vec3 u = d * (1.0f / std::sqrt(dist2));
  const float cos_from = glm::dot(from.normal, u), cos_to = -glm::dot(to_normal, u);
  if (cos_from <= 0.0f || cos_to <= 0.0f) return 0.0f;
  return cos_from * (1.0f / kPi) * cos_to / dist2;
}

// albedo / pi * E_direct at vertex y, each light weighted against its connect strategy when y
// was reached by a bounce from `prev` (nullptr: y is the camera's first hit, bounce only).
glm::vec3 next_event(const EmbreeScene& scene, const std::vector<PunctualLight>& lights, const PathVertex& y,
                     const PathVertex* prev, bool light_connections) {
  glm::vec3 e(0.0f);
  const glm::vec3 shadow_origin = offset_from_surface(y.position, y.normal);
  for (const PunctualLight& light : lights) {
    LightSample s;
    if (!sample_light(light, y.position, s)) continue;
    const float cos_theta = glm::dot(y.normal, s.to_light);
    if (cos_theta <= 0.0f) continue;  // behind the shaded side: no light, no ray
    // A ray to a point light stops at the light: geometry beyond it does not shadow.
    const float t_max = light.type == Light::Type::Directional ? std::numeric_limits<float>::infinity()
                                                               : glm::length(light.position_world - shadow_origin);
    if (scene.occluded(shadow_origin, s.to_light, t_max)) continue;
    float weight = 1.0f;
    if (prev && light_connections && has_emission_sampling(light)) {
      const float pdf_connect = emission_pdf(light, -s.to_light) * cos_theta / (s.distance * s.distance);
      weight = power_heuristic(bounce_pdf_area(*prev, y.position, y.normal), pdf_connect);
    }
    e += weight * s.irradiance * cos_theta;
  }
  return y.albedo * (1.0f / kPi) * e;
}

// Radiance reflected at x towards the previous vertex by light that bounced once at each light
// vertex, each weighted against its bounce strategy.
glm::vec3 connect_light_vertices(const EmbreeScene& scene, const PathVertex& x,
                                 const std::vector<LightVertex>& vertices) {
  glm::vec3 sum(0.0f);
  const glm::vec3 origin = offset_from_surface(x.position, x.normal);
  for (const LightVertex& v : vertices) {
    if (!v.valid) continue;
    const glm::vec3 d = v.position - x.position;
    const float dist2 = glm::dot(d, d);
    if (!(dist2 > 0.0f)) continue;
    const glm::vec3 u = d * (1.0f / std::sqrt(dist2));
    const float cos_x = glm::dot(x.normal, u), cos_y = -glm::dot(v.normal, u);
    if (cos_x <= 0.0f || cos_y <= 0.0f) continue;  // y's lit side must face x's shaded side
    const glm::vec3 target = offset_from_surface(v.position, v.normal);
    const glm::vec3 to_target = target - origin;
    const float t_max = glm::length(to_target);
    if (!(t_max > 0.0f) || scene.occluded(origin, to_target / t_max, t_max)) continue;
    const float pdf_bounce = cos_x * (1.0f / kPi) * cos_y / dist2;
    sum += power_heuristic(v.pdf_area, pdf_bounce) * v.weight * (cos_x * cos_y / dist2);
  }
  return x.albedo * (1.0f / kPi) * sum;
}

// The camera ray's first hit, followed through the linked portals it meets before a hit (a
// mirror or teleport shows what lies beyond its link, path_tracer.h); false when it escapes.
// `origin` and `dir` become the ray that made the hit.
bool camera_hit(const EmbreeScene& scene, std::span<const Portal> linked, glm::vec3& origin, glm::vec3& dir,
                RayCone& cone, SurfaceHit& hit) {
  for (uint32_t depth = 0;; ++depth) {
    const bool found = scene.intersect(origin, dir, cone, hit);
    if (linked.empty() || depth == kMaxLinkDepth) return found;
    const double t_hit = found ? double(glm::length(hit.position_world - origin)) : 1e30;
    double t = 0.0;
    const int p = linked_portal_on_ray(linked, glm::dvec3(origin), glm::dvec3(dir), t_hit, t);
    if (p < 0) return found;
    const glm::dmat4& link = linked[size_t(p)].link_world;
    origin = glm::vec3(link * glm::dvec4(glm::dvec3(origin) + t * glm::dvec3(dir), 1.0));
    dir = glm::normalize(glm::vec3(link * glm::dvec4(glm::dvec3(dir), 0.0)));
    cone.width_m += cone.spread * float(t);  // the pixel's footprint goes on growing through the link
  }
}

}  // namespace

glm::vec3 path_radiance(const EmbreeScene& scene, const std::vector<PunctualLight>& lights, const glm::vec3& origin,
                        const glm::vec3& dir, const PathSettings& settings, PixelRng& rng,
                        std::vector<LightVertex>& light_vertices) {
  const bool connect = settings.light_connections && settings.max_bounces > 0;
  if (connect) sample_light_vertices(scene, lights, settings.cone_spread, rng, light_vertices);
  glm::vec3 radiance(0.0f);
  glm::vec3 throughput(1.0f);  // product of the albedos of the vertices before this one
  glm::vec3 ray_origin = origin, ray_dir = dir;
  // The cone keeps the pixel's spread through diffuse bounces (a simple rule: a diffuse lobe
  // would widen it to a hemisphere), so its width grows with the path's length from the eye.
  RayCone cone{0.0f, settings.cone_spread};
  PathVertex prev;
  for (uint32_t vertex = 0;; ++vertex) {
    SurfaceHit hit;
    const bool found = vertex == 0 ? camera_hit(scene, settings.linked_portals, ray_origin, ray_dir, cone, hit)
                                   : scene.intersect(ray_origin, ray_dir, cone, hit);
    if (!found) {  // the sky: World::environment
      radiance += throughput * settings.environment;
      break;
    }
    const PathVertex here{hit.position_world, hit.normal_world, hit.albedo};
    // What the surface gives off, found by the camera ray or a bounce (emissive surfaces are not
    // sampled as lights: a bounce that hits one is the only strategy, so it takes full weight).
    radiance += throughput * hit.emission;
    radiance += throughput * next_event(scene, lights, here, vertex > 0 ? &prev : nullptr, connect);
    if (vertex == settings.max_bounces) break;
    // A connection adds one bounce (here -> light vertex), allowed only below the bounce limit.
    if (connect) radiance += throughput * connect_light_vertices(scene, here, light_vertices);
    // albedo / pi * L_in * cos / (cos / pi) = albedo * L_in for a cosine-weighted direction.
    throughput *= hit.albedo;
    if (throughput.x <= 0.0f && throughput.y <= 0.0f && throughput.z <= 0.0f) break;
    const float u1 = rng.uniform(), u2 = rng.uniform();
    ray_dir = cosine_hemisphere(hit.normal_world, u1, u2);
    ray_origin = offset_from_surface(hit.position_world, hit.normal_world);
    cone.width_m = hit.cone_width_m;
    prev = here;
  }
  return radiance;
}

}  // namespace lintel::pathtrace_detail
