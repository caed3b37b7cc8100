// The ray-walk oracle of the traversal tests (see ray_walk.h).
#include "ray_walk.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lintel::testing {
namespace {

// Ray-triangle distance (Möller-Trumbore), or +inf.
double ray_triangle(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a, const glm::dvec3& b,
                    const glm::dvec3& c) {
  const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  if (std::abs(det) < 1e-14) return std::numeric_limits<double>::infinity();
  const glm::dvec3 s = o - a;
  const double u = glm::dot(s, p) / det;
  if (u < -1e-9 || u > 1.0 + 1e-9) return std::numeric_limits<double>::infinity();
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(d, q) / det;
  if (v < -1e-9 || u + v > 1.0 + 1e-9) return std::numeric_limits<double>::infinity();
  return glm::dot(e2, q) / det;
}

// First exit of the ray from the cell's volume after parameter t0.
double volume_exit(const Cell& cell, const glm::dvec3& o, const glm::dvec3& d, double t0) {
  const glm::dmat4 m(cell.cell_to_world);
  double best = std::numeric_limits<double>::infinity();
  const auto& t = cell.volume_triangles_cell;
  for (size_t i = 0; i + 2 < t.size(); i += 3) {
    const double h = ray_triangle(o, d, glm::dvec3(m * glm::dvec4(t[i], 1.0)),
                                  glm::dvec3(m * glm::dvec4(t[i + 1], 1.0)), glm::dvec3(m * glm::dvec4(t[i + 2], 1.0)));
    if (h > t0 + 1e-7 && h < best) best = h;
  }
  return best;
}

// Signed distance (m) of p inside the convex portal polygon (> 0 inside, distance to the nearest edge).
double inside_margin(const Portal& portal, const glm::dvec3& p) {
  const auto& poly = portal.polygon_world;
  glm::dvec3 n(0.0);
  for (size_t i = 0; i < poly.size(); ++i) {
    const glm::dvec3 a(poly[i]), b(poly[(i + 1) % poly.size()]);
    n += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  n = glm::normalize(n);
  double margin = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < poly.size(); ++i) {
    const glm::dvec3 a(poly[i]), b(poly[(i + 1) % poly.size()]);
    const glm::dvec3 out = glm::normalize(glm::cross(b - a, n));
    margin = std::min(margin, -glm::dot(p - a, out));
  }
  return margin;
}

}  // namespace

RayWalk walk_view_ray(const World& world, const View& view, uint32_t start_cell, const glm::dvec2& ndc) {
  RayWalk walk;
  const glm::dmat4 inv = glm::inverse(view_projection_d(view));
  auto unproject = [&](double z) {
    const glm::dvec4 p = inv * glm::dvec4(ndc.x, ndc.y, z, 1.0);
    return glm::dvec3(p) / p.w;
  };
  const glm::dvec3 eye(view.eye_world);
  const glm::dvec3 on_near = unproject(0.0), on_far = unproject(1.0);
  const glm::dvec3 dir = glm::normalize(on_far - eye);
  const double t_near = glm::length(on_near - eye), t_far = glm::length(on_far - eye);

  uint32_t cell = start_cell;
  double t = 0.0;
  walk.seen_cells.push_back(cell);
  walk.origin = eye;
  walk.direction = dir;
  walk.t_near = t_near;
  for (int step = 0; step < 10000; ++step) {
    const double t_exit = volume_exit(world.cells[cell], eye, dir, t);
    double best_t = std::numeric_limits<double>::infinity();
    uint32_t best_next = 0;
    for (const PortalLink& link : world.cells[cell].links) {
      const Portal& portal = world.portals[link.portal];
      // A closed door is a wall for the ray.
      if (!world.portal_open(link.portal, portal.from == cell ? PortalDirection::FromTo : PortalDirection::ToFrom))
        continue;
      const double sign = portal.from == cell ? 1.0 : -1.0;
      const glm::dvec3 n = sign * glm::dvec3(portal.normal_world);
      const double d = sign * double(portal.plane_d_world);
      const double s0 = glm::dot(n, eye + dir * t) - d;
      const double rate = glm::dot(n, dir);
      if (!(rate > 0.0) || s0 > 1e-9) continue;  // must cross from this cell's side to the other
      const double hit = t + (-s0) / rate;
      if (hit < t - 1e-9 || hit >= best_t) continue;
      const double margin = inside_margin(portal, eye + dir * hit);
      if (std::abs(margin) < 1e-3) walk.ambiguous = true;
      if (margin <= 0.0) continue;
      best_t = hit;
      best_next = link.neighbour;
    }
    if (best_t == std::numeric_limits<double>::infinity() || best_t > t_exit + 1e-4 || best_t > t_far) {
      walk.stretches.push_back({cell, t, std::min(t_exit, t_far)});
      break;
    }
    walk.stretches.push_back({cell, t, best_t});
    cell = best_next;
    t = best_t;
    // Seen if some of its stretch of the ray lies beyond the near plane.
    const double exit_next = volume_exit(world.cells[cell], eye, dir, t);
    if (t >= t_near || exit_next > t_near) walk.seen_cells.push_back(cell);
  }
  return walk;
}

}  // namespace lintel::testing
