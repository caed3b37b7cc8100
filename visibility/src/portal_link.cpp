// Link transforms of teleport and mirror portals: the reflection in a plane, and the rigid map of
// one convex polygon onto a congruent one found by trying each vertex correspondence (a polygon
// has few vertices; the orthonormal frames make each try exact up to rounding).
#include <lintel/portal_link.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace lintel {
namespace {

// Orthonormal frame (columns) at `origin`: u along `toward` made orthogonal to `normal`.
glm::dmat4 frame(const glm::dvec3& origin, const glm::dvec3& toward, const glm::dvec3& normal) {
  const glm::dvec3 n = glm::normalize(normal);
  const glm::dvec3 u = glm::normalize(toward - glm::dot(toward, n) * n);
  const glm::dvec3 v = glm::cross(n, u);
  return glm::dmat4(glm::dvec4(u, 0.0), glm::dvec4(v, 0.0), glm::dvec4(n, 0.0), glm::dvec4(origin, 1.0));
}

double polygon_size(const std::vector<glm::vec3>& poly) {
  glm::dvec3 lo(poly[0]), hi(poly[0]);
  for (const glm::vec3& p : poly) {
    lo = glm::min(lo, glm::dvec3(p));
    hi = glm::max(hi, glm::dvec3(p));
  }
  return glm::length(hi - lo);
}

double largest_coordinate(const std::vector<glm::vec3>& poly) {
  double m = 0.0;
  for (const glm::vec3& p : poly)
    m = std::max({m, double(std::abs(p.x)), double(std::abs(p.y)), double(std::abs(p.z))});
  return m;
}

}  // namespace

glm::dmat4 mirror_transform(const Portal& portal) {
  const glm::dvec3 n = glm::normalize(glm::dvec3(portal.normal_world));
  // Plane through the centroid (the stored plane_d is a float rounding of the same plane).
  const double d = glm::dot(n, glm::dvec3(portal.centroid_world));
  glm::dmat4 m(1.0);
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) m[c][r] = (c == r ? 1.0 : 0.0) - 2.0 * n[c] * n[r];
  m[3] = glm::dvec4(2.0 * d * n, 1.0);
  return m;
}

std::string link_onto_target(const Portal& source, const Portal& target, glm::dmat4& link_world) {
  const size_t n = source.polygon_world.size();
  if (target.polygon_world.size() != n)
    return "has " + std::to_string(n) + " vertices, the target " + std::to_string(target.polygon_world.size());
  const glm::dvec3 cs(source.centroid_world), ct(target.centroid_world);
  const glm::dmat4 from_frame = frame(cs, glm::dvec3(source.polygon_world[0]) - cs, glm::dvec3(source.normal_world));
  const double tolerance =
      1e-4 * std::max(polygon_size(source.polygon_world), polygon_size(target.polygon_world)) +
      1e-6 * std::max(largest_coordinate(source.polygon_world), largest_coordinate(target.polygon_world));
  double best_up = -2.0, best_miss = INFINITY;
  bool found = false;
  for (size_t j = 0; j < n; ++j) {
    const glm::dmat4 to_frame = frame(ct, glm::dvec3(target.polygon_world[j]) - ct, -glm::dvec3(target.normal_world));
    const glm::dmat4 m = to_frame * glm::inverse(from_frame);
    double miss = 0.0;
    for (size_t i = 0; i < n; ++i) {
      const glm::dvec3 mapped(m * glm::dvec4(glm::dvec3(source.polygon_world[i]), 1.0));
      miss = std::max(miss, glm::length(mapped - glm::dvec3(target.polygon_world[(j + n - i) % n])));
    }
    best_miss = std::min(best_miss, miss);
    if (!(miss <= tolerance)) continue;
    const double up = m[1][1];  // world +Y mapped, its Y component
    if (up > best_up + 1e-9) {
      best_up = up;
      link_world = m;
      found = true;
    }
  }
  if (!found) return "is not congruent to the target (off by " + std::to_string(best_miss) + " m)";
  return {};
}

bool is_rigid(const glm::dmat4& m, double& determinant) {
  determinant = 0.0;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0) return false;
  const glm::dmat3 a(m);
  determinant = glm::determinant(a);
  const glm::dmat3 gram = glm::transpose(a) * a;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      if (std::abs(gram[c][r] - (c == r ? 1.0 : 0.0)) > 1e-5) return false;
  return true;
}

std::string check_portal_link(const World& world, uint32_t portal_index) {
  const Portal& p = world.portals[portal_index];
  if (!p.linked()) return {};
  if (p.two_way) return "a linked portal is one-way (give the way back its own portal)";
  double det = 0.0;
  if (!is_rigid(p.link_world, det)) return "link matrix is not rigid (rotation + translation, or a reflection)";
  if (p.link == PortalLinkKind::Teleport) {
    if (!(det > 0.0)) return "teleport link matrix mirrors (determinant " + std::to_string(det) + ")";
    return {};
  }
  if (p.to != p.from) return "a mirror must lead back into its own cell (to == from)";
  const glm::dmat4 expected = mirror_transform(p);
  const double scale = 1.0 + glm::length(glm::dvec3(p.centroid_world));
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 3; ++r)
      if (std::abs(p.link_world[c][r] - expected[c][r]) > 1e-5 * scale)
        return "mirror link is not the reflection in the portal's plane";
  return {};
}

int linked_portal_on_ray(std::span<const Portal> portals, const glm::dvec3& o, const glm::dvec3& d, double t_max,
                         double& t_out) {
  int best = -1;
  for (size_t p = 0; p < portals.size(); ++p) {
    const Portal& portal = portals[p];
    if (!portal.linked()) continue;
    const glm::dvec3 n(portal.normal_world);
    const double along = glm::dot(n, d);
    if (!(along > 0.0)) continue;  // seen from behind (the normal points out of `from`)
    const double t = (double(portal.plane_d_world) - glm::dot(n, o)) / along;
    if (!(t > 0.0) || t > t_max + 1e-3 * (1.0 + t_max) || (best >= 0 && t >= t_out)) continue;
    const glm::dvec3 x = o + t * d;
    bool inside = true;
    const size_t k = portal.polygon_world.size();
    for (size_t i = 0; i < k && inside; ++i) {
      const glm::dvec3 a(portal.polygon_world[i]), b(portal.polygon_world[(i + 1) % k]);
      inside = glm::dot(glm::cross(b - a, x - a), n) >= -1e-9 * glm::length(b - a);
    }
    if (!inside) continue;
    best = int(p);
    t_out = t;
  }
  return best;
}

}  // namespace lintel
