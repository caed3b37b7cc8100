// Brute force on purpose: the tests check the generators, so the checks stay simple enough to
// trust by reading.
#include "gen_test_support.h"

#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace lintel::gen_test {

bool load(const SceneDesc& scene, const std::string& label, World& out, bool lone_cell) {
  std::vector<std::string> warnings;
  const Status s = build_world(scene, label, out, &warnings);
  if (!s) {
    ADD_FAILURE() << s.message();
    return false;
  }
  bool clean = true;
  for (const std::string& w : warnings) {
    if (lone_cell && out.cells.size() == 1 && w.find("has no portals") != std::string::npos) continue;
    ADD_FAILURE() << label << ": warning: " << w;
    clean = false;
  }
  return clean;
}

std::vector<OwnedTriangle> world_triangles(const World& world, bool with_instances) {
  std::vector<OwnedTriangle> out;
  auto add = [&](const Mesh& mesh, const glm::mat4& to_world, uint32_t cell, int instance) {
    const glm::dmat4 m(to_world);
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      OwnedTriangle t;
      t.a = glm::dvec3(m * glm::dvec4(glm::dvec3(mesh.positions[mesh.indices[i]]), 1.0));
      t.b = glm::dvec3(m * glm::dvec4(glm::dvec3(mesh.positions[mesh.indices[i + 1]]), 1.0));
      t.c = glm::dvec3(m * glm::dvec4(glm::dvec3(mesh.positions[mesh.indices[i + 2]]), 1.0));
      t.cell = cell;
      t.instance = instance;
      out.push_back(t);
    }
  };
  for (uint32_t c = 0; c < world.cells.size(); ++c)
    if (world.cells[c].shell_mesh >= 0)
      add(world.meshes[size_t(world.cells[c].shell_mesh)], world.cells[c].cell_to_world, c, -1);
  if (with_instances)
    for (size_t i = 0; i < world.instances.size(); ++i) {
      const Instance& inst = world.instances[i];
      add(world.meshes[inst.mesh], inst.mesh_to_world, inst.cell, int(i));
    }
  return out;
}

double ray_triangle(const glm::dvec3& o, const glm::dvec3& d, const OwnedTriangle& tri) {
  const glm::dvec3 e1 = tri.b - tri.a, e2 = tri.c - tri.a;
  const glm::dvec3 p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  if (std::fabs(det) < 1e-18) return -1.0;
  const double inv = 1.0 / det;
  const glm::dvec3 s = o - tri.a;
  const double u = glm::dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return -1.0;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(d, q) * inv;
  if (v < 0.0 || u + v > 1.0) return -1.0;
  return glm::dot(e2, q) * inv;
}

namespace {

// Distance from a point on the portal's plane to its outline, positive inside, negative outside.
double signed_inside_distance(const Portal& portal, const glm::dvec3& x) {
  const glm::dvec3 n(portal.normal_world);
  const size_t k = portal.polygon_world.size();
  double inside = INFINITY;
  for (size_t i = 0; i < k; ++i) {
    const glm::dvec3 a(portal.polygon_world[i]), b(portal.polygon_world[(i + 1) % k]);
    const glm::dvec3 edge_normal = glm::normalize(glm::cross(n, b - a));  // points inwards (CCW about n)
    inside = std::min(inside, glm::dot(x - a, edge_normal));
  }
  return inside;
}

}  // namespace

double ray_portal(const Portal& portal, const glm::dvec3& origin, const glm::dvec3& dir, double& margin) {
  const glm::dvec3 n(portal.normal_world);
  const double denom = glm::dot(n, dir);
  if (std::fabs(denom) < 1e-12) return -1.0;
  const double t = (double(portal.plane_d_world) - glm::dot(n, origin)) / denom;
  if (t < 0.0) return -1.0;
  margin = signed_inside_distance(portal, origin + t * dir);
  return margin > 0.0 ? t : -1.0;
}

double portal_crossing_margin(const Portal& portal, const glm::dvec3& p, const glm::dvec3& q) {
  double margin = -1.0;
  const double t = ray_portal(portal, p, q - p, margin);
  return (t >= 0.0 && t <= 1.0) ? margin : -1.0;
}

bool in_volume_box(const Cell& cell, const glm::dvec3& p_world) {
  const glm::dvec3 p = glm::dvec3(glm::dmat4(cell.world_to_cell) * glm::dvec4(p_world, 1.0));
  const glm::dvec3 lo(cell.volume_box_cell.min), hi(cell.volume_box_cell.max);
  const double tol = 1e-5 * glm::length(hi - lo);
  return glm::all(glm::greaterThanEqual(p, lo - tol)) && glm::all(glm::lessThanEqual(p, hi + tol));
}

bool in_volume(const Cell& cell, const glm::dvec3& p_world) {
  const glm::dvec3 p = glm::dvec3(glm::dmat4(cell.world_to_cell) * glm::dvec4(p_world, 1.0));
  const glm::dvec3 dir = glm::normalize(glm::dvec3(0.1234, 0.9771, 0.0871));  // off every axis and diagonal
  size_t crossings = 0;
  const auto& v = cell.volume_triangles_cell;
  for (size_t i = 0; i + 2 < v.size(); i += 3) {
    OwnedTriangle t;
    t.a = glm::dvec3(v[i]), t.b = glm::dvec3(v[i + 1]), t.c = glm::dvec3(v[i + 2]);
    crossings += ray_triangle(p, dir, t) > 0.0;
  }
  return crossings % 2 == 1;
}

bool has_odd_rotation(const glm::mat4& m) {
  glm::dmat3 r(m);
  for (int i = 0; i < 3; ++i) r[i] = glm::normalize(r[i]);
  for (int c = 0; c < 3; ++c)
    for (int row = 0; row < 3; ++row) {
      const double v = std::fabs(r[c][row]);
      if (v > 0.01 && v < 0.99) return true;
    }
  return false;
}

}  // namespace lintel::gen_test
