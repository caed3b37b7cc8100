// Camera generators for the visibility properties (see camera_samples.h).
#include "camera_samples.h"

#include <lintel/doorway_rule.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lintel::fuzz {
namespace {

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5).
glm::dvec3 closest_on_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

glm::dvec3 unit_from_angles(double azimuth, double cos_polar) {
  const double s = std::sqrt(std::max(0.0, 1.0 - cos_polar * cos_polar));
  return {s * std::cos(azimuth), cos_polar, s * std::sin(azimuth)};
}

}  // namespace

glm::dvec3 point_in_portal(const Portal& portal, double u, double v, double shrink) {
  // A fan triangle chosen by u, a point in it by (u', v) folded into the triangle.
  const auto& poly = portal.polygon_world;
  const size_t fans = poly.size() - 2;
  const size_t k = std::min(fans - 1, static_cast<size_t>(u * double(fans)));
  double a = u * double(fans) - double(k), b = v;
  if (a + b > 1.0) {
    a = 1.0 - a;
    b = 1.0 - b;
  }
  const glm::dvec3 p0(poly[0]), p1(poly[k + 1]), p2(poly[k + 2]);
  const glm::dvec3 p = p0 + (p1 - p0) * a + (p2 - p0) * b;
  const glm::dvec3 centroid(portal.centroid_world);
  return centroid + (p - centroid) * shrink;
}

glm::vec3 pick_layout_look() {
  const glm::vec3 look(*rc::gen::inRange(-100, 101), *rc::gen::inRange(-60, 61), *rc::gen::inRange(-100, 101));
  RC_PRE(glm::length(look) > 10.0f);
  RC_PRE(look.x != 0.0f || look.z != 0.0f);
  return look;
}

double distance_to_nearest_shell(const World& world, const glm::dvec3& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const Cell& cell : world.cells) {
    if (cell.shell_mesh < 0) continue;
    const Mesh& mesh = world.meshes[size_t(cell.shell_mesh)];
    const glm::dmat4 m(cell.cell_to_world);
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const glm::dvec3 a(m * glm::dvec4(glm::dvec3(mesh.positions[mesh.indices[t]]), 1.0));
      const glm::dvec3 b(m * glm::dvec4(glm::dvec3(mesh.positions[mesh.indices[t + 1]]), 1.0));
      const glm::dvec3 c(m * glm::dvec4(glm::dvec3(mesh.positions[mesh.indices[t + 2]]), 1.0));
      best = std::min(best, glm::length(p - closest_on_triangle(p, a, b, c)));
    }
  }
  return best;
}

bool ray_runs_in_portal_plane(const World& world, const glm::dvec3& eye, const glm::dvec3& dir) {
  const glm::dvec3 unit = glm::normalize(dir);
  for (const Portal& p : world.portals) {
    const glm::dvec3 n(p.normal_world);
    if (std::abs(glm::dot(n, eye) - p.plane_d_world) < 1e-3 && std::abs(glm::dot(n, unit)) < 1e-3) return true;
  }
  return false;
}

double geometry_error_bound(const World& world) {
  constexpr double kUlps = 8.0 * 1.1920929e-7;  // 8 float ulps relative (transform + storage)
  double worst = 0.0, world_extent = 0.0;
  for (const Cell& cell : world.cells) {
    if (cell.shell_mesh < 0) continue;
    double local = 0.0;
    for (const glm::vec3& p : world.meshes[size_t(cell.shell_mesh)].positions)
      local = std::max({local, double(std::abs(p.x)), double(std::abs(p.y)), double(std::abs(p.z))});
    const glm::dmat3 m(cell.cell_to_world);
    const double scale = std::max({glm::length(m[0]), glm::length(m[1]), glm::length(m[2])});
    worst = std::max(worst, local * scale * kUlps);
    world_extent = std::max(world_extent, glm::length(glm::dvec3(cell.cell_to_world[3])) + local * scale);
  }
  return worst + world_extent * kUlps;
}

bool on_portal_seam(const World& world, uint32_t cell, const glm::dvec3& p_world, double tolerance_m) {
  for (const PortalLink& link : world.cells[cell].links) {
    const Portal& portal = world.portals[link.portal];
    const double s = glm::dot(glm::dvec3(portal.normal_world), p_world) - double(portal.plane_d_world);
    if (std::abs(s) <= tolerance_m && projects_inside_portal(portal, p_world, tolerance_m)) return true;
  }
  // One-way portals appear only in `from`'s links; their `to` side meets them too.
  for (const Portal& portal : world.portals) {
    if (portal.two_way || portal.to != cell) continue;
    const double s = glm::dot(glm::dvec3(portal.normal_world), p_world) - double(portal.plane_d_world);
    if (std::abs(s) <= tolerance_m && projects_inside_portal(portal, p_world, tolerance_m)) return true;
  }
  return false;
}

glm::dvec3 pixel_ray_direction(const View& view, const glm::vec2& ndc) {
  const glm::dvec3 forward = glm::normalize(glm::dvec3(view.target_world) - glm::dvec3(view.eye_world));
  const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(view.up_world)));
  const glm::dvec3 up = glm::cross(right, forward);
  const double tan_half = std::tan(glm::radians(double(view.fov_y_deg)) * 0.5);
  return forward + (ndc.x * tan_half * view.aspect) * right + (ndc.y * tan_half) * up;
}

double near_corner_distance(const View& view) {
  const double half_h = view.near_m * std::tan(glm::radians(double(view.fov_y_deg)) * 0.5);
  const double half_w = half_h * view.aspect;
  return std::sqrt(double(view.near_m) * view.near_m + half_h * half_h + half_w * half_w);
}

rc::Gen<CameraSample> gen_camera_at_portal(const World& world, bool two_way_only) {
  std::vector<uint32_t> candidates;
  for (uint32_t p = 0; p < world.portals.size(); ++p)
    if (!two_way_only || world.portals[p].two_way) candidates.push_back(p);
  RC_ASSERT(!candidates.empty());
  return rc::gen::exec([&world, candidates] {
    CameraSample s;
    s.portal = *rc::gen::elementOf(candidates);
    const Portal& portal = world.portals[s.portal];
    const double u = *rc::gen::inRange(0, 1000000) / 1e6, v = *rc::gen::inRange(0, 1000000) / 1e6;
    const glm::dvec3 on_plane = point_in_portal(portal, u, v, 0.6);
    // Offsets spread over 1e-7 m .. 1 m on a log scale (continuous mantissa, so that an offset
    // lands exactly on the near distance — where the doorway rule switches — only by chance), or
    // exactly on the plane.
    const int decade = *rc::gen::inRange(-7, 1);
    const double mantissa = 1.0 + 9.0 * (*rc::gen::inRange(0, 1000000) / 1e6);
    const double magnitude = *rc::gen::element(0, 1) ? 0.0 : std::pow(10.0, decade) * mantissa;
    s.offset_m = (*rc::gen::element(-1.0, 1.0)) * std::min(1.0, magnitude);
    if (!portal.two_way) s.offset_m = -std::abs(s.offset_m);  // a one-way portal is entered from `from` only
    // The side decides the cell: on `to`'s side (> 0) the eye is in `to`, else in `from`.
    s.start_cell = s.offset_m > 0.0 ? portal.to : portal.from;
    const glm::dvec3 n(portal.normal_world);
    const glm::dvec3 eye_final = on_plane + n * s.offset_m;

    glm::dvec3 dir;
    if (*rc::gen::inRange(0, 3) == 0) {
      // Grazing: almost in the portal plane, tilted by 1e-6 .. 1e-1 rad.
      const glm::dvec3 helper = std::abs(n.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
      const glm::dvec3 t1 = glm::normalize(glm::cross(n, helper)), t2 = glm::cross(n, t1);
      const double phi = *rc::gen::inRange(0, 6283) / 1000.0;
      const double tilt = std::pow(10.0, -double(*rc::gen::inRange(1, 7))) * (*rc::gen::element(-1.0, 1.0));
      dir = glm::normalize(std::cos(phi) * t1 + std::sin(phi) * t2 + tilt * n);
    } else {
      dir = unit_from_angles(*rc::gen::inRange(0, 6283) / 1000.0, *rc::gen::inRange(-999, 1000) / 1000.0);
    }
    s.view.eye_world = glm::vec3(eye_final);
    s.view.target_world = glm::vec3(eye_final + dir * 3.0);
    const glm::dvec3 up_candidate =
        unit_from_angles(*rc::gen::inRange(0, 6283) / 1000.0, *rc::gen::inRange(-999, 1000) / 1000.0);
    s.view.up_world = std::abs(glm::dot(up_candidate, dir)) > 0.95
                          ? glm::vec3(glm::cross(dir, glm::dvec3(0.6, 0.0, 0.8)))
                          : glm::vec3(up_candidate);
    s.view.fov_y_deg = float(*rc::gen::inRange(30, 121));
    s.view.aspect = float(*rc::gen::inRange(50, 251) / 100.0);
    s.view.near_m = 0.05f;
    return s;
  });
}

}  // namespace lintel::fuzz
