// Point-in-cell-volume tests: generalized winding number for triangle volumes, box otherwise.
// Learns from: Jacobson, Kavan & Sorkine-Hornung 2013 "Robust inside-outside segmentation using
// generalized winding numbers" (sum of signed solid angles, Van Oosterom & Strackee 1983) and
// Ericson 2005 "Real-Time Collision Detection" 5.1.5 (closest point on a triangle).
#include <lintel/cell_locate.h>

#include "point_in_volume.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <optional>

namespace lintel {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Calls fn(a, b, c) for each volume triangle, in cell space.
template <typename Fn>
void for_each_volume_triangle(const Cell& cell, Fn&& fn) {
  if (!cell.volume_triangles_cell.empty()) {
    const auto& t = cell.volume_triangles_cell;
    assert(t.size() % 3 == 0);
    for (size_t i = 0; i + 2 < t.size(); i += 3) fn(glm::dvec3(t[i]), glm::dvec3(t[i + 1]), glm::dvec3(t[i + 2]));
    return;
  }
  const Aabb& b = cell.volume_box_cell;
  if (b.empty()) return;
  glm::dvec3 c[8];
  for (int i = 0; i < 8; ++i)
    c[i] = {(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z};
  static constexpr int kQuads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : kQuads) {
    fn(c[q[0]], c[q[1]], c[q[2]]);
    fn(c[q[0]], c[q[2]], c[q[3]]);
  }
}

glm::dvec3 closest_point_on_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                     const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + ab * (d1 / (d1 - d3));
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denom = va + vb + vc;
  if (denom == 0.0) return a;  // degenerate triangle
  return a + ab * (vb / denom) + ac * (vc / denom);
}

}  // namespace

double volume_winding_exact(const Cell& cell, const glm::dvec3& p) {
  double solid_angle = 0.0;
  for_each_volume_triangle(cell, [&](const glm::dvec3& a0, const glm::dvec3& b0, const glm::dvec3& c0) {
    const glm::dvec3 a = a0 - p, b = b0 - p, c = c0 - p;
    const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    const double numerator = glm::dot(a, glm::cross(b, c));
    const double denominator = la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
    solid_angle += 2.0 * std::atan2(numerator, denominator);
  });
  return solid_angle / (4.0 * kPi);
}

ContainmentRay containment_ray(const Cell& cell, const glm::dvec3& p) {
  const glm::dvec3 extent = glm::dvec3(cell.volume_box_cell.max) - glm::dvec3(cell.volume_box_cell.min);
  const double size = std::max({extent.x, extent.y, extent.z, 1e-6});
  const glm::dvec2 puv = sheared(p);
  return {p, puv.x, puv.y, 1e-7 * size, 1e-7 * size * size};
}

RayStep ray_meets_triangle(const ContainmentRay& r, const glm::vec3& a_f, const glm::vec3& b_f, const glm::vec3& c_f) {
  const glm::dvec3 a(a_f), b(b_f), c(c_f);
  // Only triangles that reach past p in x and whose (u, v) shadow holds (pu, pv) can cross it.
  if (std::max({a.x, b.x, c.x}) < r.p.x - r.margin_x) return RayStep::Miss;
  const glm::dvec2 a_uv = sheared(a), b_uv = sheared(b), c_uv = sheared(c);
  const double au = a_uv.x, bu = b_uv.x, cu = c_uv.x;
  if (r.pu < std::min({au, bu, cu}) || r.pu > std::max({au, bu, cu})) return RayStep::Miss;
  const double av = a_uv.y, bv = b_uv.y, cv = c_uv.y;
  if (r.pv < std::min({av, bv, cv}) || r.pv > std::max({av, bv, cv})) return RayStep::Miss;
  // Twice the signed (u, v) areas of the sub-triangles opposite a, b and c.
  const double pu = r.pu, pv = r.pv, margin_area = r.margin_area;
  const double wa = (cu - bu) * (pv - bv) - (cv - bv) * (pu - bu);
  const double wb = (au - cu) * (pv - cv) - (av - cv) * (pu - cu);
  const double wc = (bu - au) * (pv - av) - (bv - av) * (pu - au);
  const double area = wa + wb + wc;
  if (std::fabs(area) <= margin_area) {
    // Edge-on to the ray: it crosses nothing, unless the ray runs inside it (then its
    // neighbours' edges are hit too; be exact rather than clever).
    if (std::fabs(wa) <= margin_area && std::fabs(wb) <= margin_area && std::fabs(wc) <= margin_area)
      return RayStep::Ambiguous;
    return RayStep::Miss;
  }
  const double sa = wa / area, sb = wb / area, sc = wc / area;  // barycentric, sum 1
  const double edge = margin_area / std::fabs(area);
  if (sa < -edge || sb < -edge || sc < -edge) return RayStep::Miss;       // clearly outside the shadow
  if (sa <= edge || sb <= edge || sc <= edge) return RayStep::Ambiguous;  // through an edge or vertex
  const double x_hit = sa * a.x + sb * b.x + sc * c.x;
  if (std::fabs(x_hit - r.p.x) <= r.margin_x) return RayStep::Ambiguous;  // p on (or at) the surface
  if (!(x_hit > r.p.x)) return RayStep::Miss;
  return area > 0.0 ? RayStep::Up : RayStep::Down;
}

std::optional<bool> box_decides(const Cell& cell, const glm::dvec3& p_world, glm::dvec3& p) {
  const Aabb& box = cell.volume_box_cell;
  if (box.empty()) return false;
  p = glm::dvec3(glm::dmat4(cell.world_to_cell) * glm::dvec4(p_world, 1.0));
  const glm::dvec3 slack = 1e-9 * (glm::dvec3(box.max) - glm::dvec3(box.min)) + 1e-12;
  if (glm::any(glm::lessThan(p, glm::dvec3(box.min) - slack)) ||
      glm::any(glm::greaterThan(p, glm::dvec3(box.max) + slack)))
    return false;
  if (cell.volume_triangles_cell.empty()) return true;
  return std::nullopt;
}

std::optional<int> volume_winding_by_ray(const Cell& cell, const glm::dvec3& p) {
  const ContainmentRay r = containment_ray(cell, p);
  const auto& t = cell.volume_triangles_cell;
  int crossings = 0;
  for (size_t i = 0; i + 2 < t.size(); i += 3)
    if (!count_step(ray_meets_triangle(r, t[i], t[i + 1], t[i + 2]), crossings)) return std::nullopt;
  return crossings;
}

bool cell_volume_contains(const World& world, uint32_t cell_index, const glm::dvec3& p_world) {
  assert(cell_index < world.cells.size());
  const Cell& cell = world.cells[cell_index];
  glm::dvec3 p;
  if (const std::optional<bool> decided = box_decides(cell, p_world, p)) return *decided;
  // A closed volume's winding number is the signed count of a ray's crossings, an integer; the
  // ray is cheap (most triangles are rejected by their y-z bounds) and used wherever it is
  // unambiguous; the solid-angle sum decides the rest (Cell volumes are closed: the loader
  // refuses open edges).
  if (const std::optional<int> w = volume_winding_by_ray(cell, p)) return *w != 0;
  return std::abs(volume_winding_exact(cell, p)) > 0.5;
}

double cell_volume_distance_m(const World& world, uint32_t cell_index, const glm::dvec3& p_world) {
  assert(cell_index < world.cells.size());
  if (cell_volume_contains(world, cell_index, p_world)) return 0.0;
  return cell_volume_clearance_m(world, cell_index, p_world);
}

double cell_volume_clearance_m(const World& world, uint32_t cell_index, const glm::dvec3& p_world) {
  assert(cell_index < world.cells.size());
  const Cell& cell = world.cells[cell_index];
  const glm::dmat4 to_world(cell.cell_to_world);
  double best_sq = std::numeric_limits<double>::infinity();
  for_each_volume_triangle(cell, [&](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 q =
        closest_point_on_triangle(p_world, glm::dvec3(to_world * glm::dvec4(a, 1.0)),
                                  glm::dvec3(to_world * glm::dvec4(b, 1.0)), glm::dvec3(to_world * glm::dvec4(c, 1.0)));
    const glm::dvec3 d = q - p_world;
    best_sq = std::min(best_sq, glm::dot(d, d));
  });
  return std::sqrt(best_sq);
}

double cell_volume_m3(const World& world, uint32_t cell_index) {
  assert(cell_index < world.cells.size());
  const Cell& cell = world.cells[cell_index];
  const double scale = std::abs(glm::determinant(glm::dmat3(glm::dmat4(cell.cell_to_world))));
  if (cell.volume_triangles_cell.empty()) {
    if (cell.volume_box_cell.empty()) return 0.0;
    const glm::dvec3 e = glm::dvec3(cell.volume_box_cell.max) - glm::dvec3(cell.volume_box_cell.min);
    return e.x * e.y * e.z * scale;
  }
  double six_volume = 0.0;  // divergence theorem: sum of signed tetrahedra from the origin
  for_each_volume_triangle(cell, [&](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    six_volume += glm::dot(a, glm::cross(b, c));
  });
  return std::abs(six_volume) / 6.0 * scale;
}

std::vector<double> cell_volumes_m3(const World& world) {
  std::vector<double> volumes(world.cells.size());
  for (uint32_t c = 0; c < world.cells.size(); ++c) volumes[c] = cell_volume_m3(world, c);
  return volumes;
}

CellLocation locate_cell(const World& world, const glm::dvec3& p_world, std::span<const double> volumes_m3) {
  assert(!world.cells.empty());
  assert(volumes_m3.empty() || volumes_m3.size() == world.cells.size());
  const uint32_t n = static_cast<uint32_t>(world.cells.size());
  auto volume = [&](uint32_t c) { return volumes_m3.empty() ? cell_volume_m3(world, c) : volumes_m3[c]; };
  bool found = false;
  CellLocation best;
  double best_volume = 0.0;
  for (uint32_t c = 0; c < n; ++c) {
    if (!cell_volume_contains(world, c, p_world)) continue;
    const double v = volume(c);
    if (!found || v < best_volume) {
      found = true;
      best = {c, LocateReason::Containment, 0.0};
      best_volume = v;
    }
  }
  if (found) return best;
  best = {0, LocateReason::Nearest, std::numeric_limits<double>::infinity()};
  for (uint32_t c = 0; c < n; ++c) {
    const double d = cell_volume_distance_m(world, c, p_world);
    if (d < best.distance_m) best = {c, LocateReason::Nearest, d};
  }
  return best;
}

}  // namespace lintel
