// The link-following ray walk of the linked-portal tests (see link_ray_walk.h). Deliberately
// independent of the traversal: no clipping, no regions, only ray-plane hits in world space.
#include "link_ray_walk.h"

#include <cmath>
#include <limits>

namespace lintel::testing {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double ray_triangle(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a, const glm::dvec3& b,
                    const glm::dvec3& c) {
  const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  if (std::abs(det) < 1e-14) return kInf;
  const glm::dvec3 s = o - a;
  const double u = glm::dot(s, p) / det;
  if (u < -1e-9 || u > 1.0 + 1e-9) return kInf;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(d, q) / det;
  if (v < -1e-9 || u + v > 1.0 + 1e-9) return kInf;
  return glm::dot(e2, q) / det;
}

// Distance along the ray (o, d) to the cell volume's exit more than 0.1 mm after t0 (triangles,
// else the box).
double volume_exit(const Cell& cell, const glm::dvec3& o, const glm::dvec3& d, double t0) {
  const glm::dmat4 m(cell.cell_to_world);
  double best = kInf;
  std::vector<glm::vec3> box;
  const std::vector<glm::vec3>* tris = &cell.volume_triangles_cell;
  if (tris->empty()) {
    const glm::vec3 lo = cell.volume_box_cell.min, hi = cell.volume_box_cell.max;
    const glm::vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z},
                            {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}};
    const int f[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                          {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    for (const auto& t : f)
      for (int k = 0; k < 3; ++k) box.push_back(c[t[k]]);
    tris = &box;
  }
  for (size_t i = 0; i + 2 < tris->size(); i += 3) {
    const double h =
        ray_triangle(o, d, glm::dvec3(m * glm::dvec4((*tris)[i], 1.0)), glm::dvec3(m * glm::dvec4((*tris)[i + 1], 1.0)),
                     glm::dvec3(m * glm::dvec4((*tris)[i + 2], 1.0)));
    if (h > t0 + 1e-4 && h < best) best = h;  // skip the face it enters by (float geometry: a mirror on it)
  }
  return best;
}

// Signed distance of p inside the convex portal polygon (> 0 inside).
double inside_margin(const Portal& portal, const glm::dvec3& p) {
  const auto& poly = portal.polygon_world;
  const glm::dvec3 n = glm::normalize(glm::dvec3(portal.normal_world));
  double margin = kInf;
  double sign = 0.0;
  for (size_t i = 0; i < poly.size() && sign == 0.0; ++i) {  // winding: normal by the right-hand rule or not
    const glm::dvec3 a(poly[i]), b(poly[(i + 1) % poly.size()]), c(poly[(i + 2) % poly.size()]);
    const double turn = glm::dot(glm::cross(b - a, c - b), n);
    if (std::abs(turn) > 1e-12) sign = turn > 0.0 ? 1.0 : -1.0;
  }
  for (size_t i = 0; i < poly.size(); ++i) {
    const glm::dvec3 a(poly[i]), b(poly[(i + 1) % poly.size()]);
    const glm::dvec3 out = glm::normalize(sign * glm::cross(b - a, n));
    margin = std::min(margin, -glm::dot(p - a, out));
  }
  return margin;
}

}  // namespace

LinkedRayWalk walk_linked_view_ray(const World& world, const View& view, uint32_t start_cell, const glm::dvec2& ndc,
                                   uint32_t max_depth) {
  LinkedRayWalk walk;
  const glm::dmat4 inv = glm::inverse(view_projection_d(view));
  auto unproject = [&](double z) {
    const glm::dvec4 p = inv * glm::dvec4(ndc.x, ndc.y, z, 1.0);
    return glm::dvec3(p) / p.w;
  };
  const glm::dvec3 eye(view.eye_world);
  const glm::dvec3 on_near = unproject(0.0), on_far = unproject(1.0);
  glm::dvec3 dir = glm::normalize(on_far - eye);
  const double t_near = glm::length(on_near - eye), t_far = glm::length(on_far - eye);

  // The ray in the current cell's own space: origin + (t - t_origin) * dir.
  glm::dvec3 origin = eye;
  double t_origin = 0.0, t = 0.0;
  uint32_t cell = start_cell, depth = 0;
  glm::dmat4 seen(1.0);
  walk.seen.push_back({cell, seen, depth});
  for (int step = 0; step < 10000; ++step) {
    const glm::dvec3 o = origin - dir * t_origin;  // the ray's point at t = 0 in this space
    const double t_exit = volume_exit(world.cells[cell], o, dir, t);
    double best_t = kInf;
    uint32_t best_portal = 0, best_next = 0;
    auto consider = [&](uint32_t pi, uint32_t next) {
      const Portal& portal = world.portals[pi];
      if (!world.portal_open(pi, portal.from == cell ? PortalDirection::FromTo : PortalDirection::ToFrom)) return;
      const double sign = portal.from == cell ? 1.0 : -1.0;
      const glm::dvec3 n = sign * glm::dvec3(portal.normal_world);
      const double d = sign * double(portal.plane_d_world);
      const double s0 = glm::dot(n, o + dir * t) - d;
      const double rate = glm::dot(n, dir);
      if (!(rate > 0.0) || s0 > 1e-9) return;
      const double hit = t + (-s0) / rate;
      if (hit < t - 1e-9 || hit >= best_t) return;
      const double margin = inside_margin(portal, o + dir * hit);
      if (std::abs(margin) < 1e-3) walk.ambiguous = true;
      if (margin <= 0.0) return;
      best_t = hit;
      best_portal = pi;
      best_next = next;
    };
    for (const PortalLink& link : world.cells[cell].links) consider(link.portal, link.neighbour);
    for (uint32_t pi : world.cells[cell].linked_portals) consider(pi, world.portals[pi].to);
    if (best_t == kInf || best_t > t_exit + 1e-4 || best_t > t_far) break;
    const Portal& crossed = world.portals[best_portal];
    t = best_t;
    if (crossed.linked()) {
      if (depth == max_depth) {
        walk.beyond_depth = t >= t_near;  // a link crossed before the near plane is not on screen
        break;
      }
      const glm::dvec3 at = o + dir * t;
      origin = glm::dvec3(crossed.link_world * glm::dvec4(at, 1.0));
      dir = glm::normalize(glm::dvec3(crossed.link_world * glm::dvec4(dir, 0.0)));
      t_origin = t;
      seen = seen * glm::inverse(crossed.link_world);
      ++depth;
    }
    cell = best_next;
    const glm::dvec3 o_next = origin - dir * t_origin;
    const double exit_next = volume_exit(world.cells[cell], o_next, dir, t);
    if (t >= t_near || exit_next > t_near) walk.seen.push_back({cell, seen, depth});
  }
  return walk;
}

}  // namespace lintel::testing
