// Brute force over the hit surface's triangles, in double: only run for the few pixels a test
// has to explain.
#include "ray_hit_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lintel::render::test {
namespace {

template <typename V>
double segment_distance(const V& p, const V& a, const V& b) {
  const V ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

// Distance from p to the (closed) triangle abc.
double triangle_distance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const double n2 = glm::dot(n, n);
  if (n2 > 0.0) {
    const glm::dvec3 q = p - n * (glm::dot(p - a, n) / n2);  // projection onto the plane
    const double u = glm::dot(glm::cross(b - q, c - q), n), v = glm::dot(glm::cross(c - q, a - q), n),
                 w = glm::dot(glm::cross(a - q, b - q), n);
    if (u >= 0.0 && v >= 0.0 && w >= 0.0) return glm::length(p - q);
  }
  return std::min({segment_distance(p, a, b), segment_distance(p, b, c), segment_distance(p, c, a)});
}

// The edge ab in pixel coordinates of the R x R grid (x right, y down, pixel centres at +0.5),
// clipped at the near plane (clip z >= 0); false when it lies wholly behind it.
bool project_edge(const glm::dmat4& view_proj, const glm::dvec3& a, const glm::dvec3& b, double resolution,
                  glm::dvec2& pa, glm::dvec2& pb) {
  glm::dvec4 ca = view_proj * glm::dvec4(a, 1.0), cb = view_proj * glm::dvec4(b, 1.0);
  if (ca.z < 0.0 && cb.z < 0.0) return false;
  if (ca.z < 0.0) ca = ca + (cb - ca) * (ca.z / (ca.z - cb.z));
  if (cb.z < 0.0) cb = cb + (ca - cb) * (cb.z / (cb.z - ca.z));
  const auto to_pixels = [resolution](const glm::dvec4& c) {
    const glm::dvec2 ndc(c.x / c.w, c.y / c.w);
    return glm::dvec2((ndc.x + 1.0) * 0.5 * resolution, (1.0 - ndc.y) * 0.5 * resolution);
  };
  pa = to_pixels(ca);
  pb = to_pixels(cb);
  return true;
}

}  // namespace

RayCamera ray_camera(const View& view) {
  RayCamera c;
  c.eye_world = view.eye_world;
  c.target_world = view.target_world;
  c.up_world = view.up_world;
  c.fov_y_deg = view.fov_y_deg;
  c.aspect = view.aspect;
  c.near_m = view.near_m;
  return c;
}

glm::vec3 pixel_ray_direction(const RayCamera& camera, uint32_t i, uint32_t j, uint32_t resolution) {
  // The same float arithmetic as RayGroundTruth::cast, so the ray is the one it cast.
  const glm::vec3 forward = glm::normalize(camera.target_world - camera.eye_world);
  const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up_world));
  const glm::vec3 up = glm::cross(right, forward);
  const float tan_half = std::tan(glm::radians(camera.fov_y_deg) * 0.5f);
  const glm::vec2 ndc = pixel_center_ndc(i, j, resolution);
  return forward + (ndc.x * tan_half * camera.aspect) * right + (ndc.y * tan_half) * up;
}

glm::dvec3 hit_point(const RayCamera& camera, uint32_t i, uint32_t j, uint32_t resolution, float depth) {
  return glm::dvec3(camera.eye_world) + glm::dvec3(pixel_ray_direction(camera, i, j, resolution)) * double(depth);
}

RayHitId raw_pixel_hit(const RayGroundTruth& truth, const RayCamera& camera, uint32_t i, uint32_t j,
                       uint32_t resolution) {
  return truth.cast_ray(camera.eye_world, pixel_ray_direction(camera, i, j, resolution), camera.near_m,
                        std::numeric_limits<float>::infinity());
}

double pixels_to_triangle_edge(const World& world, const View& view, const RayHitId& hit, uint32_t i, uint32_t j,
                               uint32_t resolution) {
  const double none = std::numeric_limits<double>::infinity();
  if (hit.cell == RayHitId::kNone) return none;
  const bool shell = hit.instance == RayHitId::kNone;
  const int mesh_index = shell ? world.cells[hit.cell].shell_mesh : int(world.instances[hit.instance].mesh);
  if (mesh_index < 0) return none;
  const glm::dmat4 to_world(shell ? world.cells[hit.cell].cell_to_world : world.instances[hit.instance].mesh_to_world);
  const Mesh& mesh = world.meshes[size_t(mesh_index)];
  const glm::dvec3 point = hit_point(ray_camera(view), i, j, resolution, hit.depth);
  double best = none;
  glm::dvec3 tri[3];
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    glm::dvec3 v[3];
    for (int k = 0; k < 3; ++k)
      v[k] = glm::dvec3(to_world * glm::dvec4(glm::dvec3(mesh.positions[mesh.indices[t + k]]), 1.0));
    const double d = triangle_distance(point, v[0], v[1], v[2]);
    if (d < best) {
      best = d;
      std::copy(v, v + 3, tri);
    }
  }
  if (best == none) return none;
  const glm::dmat4 view_proj = view_projection_d(view);
  const glm::dvec2 centre(i + 0.5, j + 0.5);
  double pixels = none;
  for (int k = 0; k < 3; ++k) {
    glm::dvec2 a, b;
    if (project_edge(view_proj, tri[k], tri[(k + 1) % 3], double(resolution), a, b))
      pixels = std::min(pixels, segment_distance(centre, a, b));
  }
  return pixels;
}

}  // namespace lintel::render::test
