// Point-in-volume and the sampled overlap test of the rooms importer (see rooms_volume.h).
// Mesh volumes use ray parity (Moller-Trumbore) along a fixed direction chosen off the axes, so
// that axis-aligned rooms do not put the ray through their edges.
#include "rooms/rooms_volume.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lintel::rooms {
namespace {

// Distance from p to triangle abc (Ericson, Real-Time Collision Detection, 5.1.5).
double point_triangle_distance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return glm::length(p - a);
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return glm::length(p - b);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return glm::length(p - (a + ab * (d1 / (d1 - d3))));
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return glm::length(p - c);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return glm::length(p - (a + ac * (d2 / (d2 - d6))));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
    return glm::length(p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))));
  const double denom = 1.0 / (va + vb + vc);
  return glm::length(p - (a + ab * (vb * denom) + ac * (vc * denom)));
}

bool ray_hits_triangle(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& a, const glm::dvec3& b,
                       const glm::dvec3& c) {
  const glm::dvec3 e1 = b - a, e2 = c - a;
  const glm::dvec3 pv = glm::cross(dir, e2);
  const double det = glm::dot(e1, pv);
  if (std::fabs(det) < 1e-300) return false;
  const double inv = 1.0 / det;
  const glm::dvec3 tv = origin - a;
  const double u = glm::dot(tv, pv) * inv;
  if (u < 0.0 || u > 1.0) return false;
  const glm::dvec3 qv = glm::cross(tv, e1);
  const double v = glm::dot(dir, qv) * inv;
  if (v < 0.0 || u + v > 1.0) return false;
  return glm::dot(e2, qv) * inv > 0.0;
}

bool mesh_contains(const RoomVolume& volume, const glm::dvec3& p, double margin) {
  const std::vector<glm::dvec3>& t = volume.triangles_world;
  double nearest = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i + 2 < t.size(); i += 3)
    nearest = std::min(nearest, point_triangle_distance(p, t[i], t[i + 1], t[i + 2]));
  if (margin >= 0.0 && nearest <= margin) return true;
  if (margin < 0.0 && nearest < -margin) return false;
  const glm::dvec3 dir = glm::normalize(glm::dvec3(0.5377, 0.7071, 0.4594));
  size_t crossings = 0;
  for (size_t i = 0; i + 2 < t.size(); i += 3) crossings += ray_hits_triangle(p, dir, t[i], t[i + 1], t[i + 2]) ? 1 : 0;
  return crossings % 2 == 1;
}

bool box_contains(const RoomVolume& volume, const glm::dvec3& p, double margin) {
  const glm::dvec3 q = glm::dvec3(volume.world_to_room * glm::dvec4(p, 1.0));
  for (int i = 0; i < 3; ++i) {
    const double m = margin / glm::length(glm::dvec3(volume.room_to_world[i]));
    if (q[i] < volume.box_min[i] - m || q[i] > volume.box_max[i] + m) return false;
  }
  return true;
}

}  // namespace

void set_box_volume(const glm::dmat4& room_to_world, const glm::dvec3& box_min, const glm::dvec3& box_max,
                    RoomVolume& out) {
  out.room_to_world = room_to_world;
  out.world_to_room = glm::inverse(room_to_world);
  out.box_min = box_min;
  out.box_max = box_max;
  out.triangles_world.clear();
  out.bounds_min = glm::dvec3(std::numeric_limits<double>::infinity());
  out.bounds_max = -out.bounds_min;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 c((corner & 1) ? box_max.x : box_min.x, (corner & 2) ? box_max.y : box_min.y,
                       (corner & 4) ? box_max.z : box_min.z);
    const glm::dvec3 w = glm::dvec3(room_to_world * glm::dvec4(c, 1.0));
    out.bounds_min = glm::min(out.bounds_min, w);
    out.bounds_max = glm::max(out.bounds_max, w);
  }
}

void set_mesh_volume(std::vector<glm::dvec3> triangles_world, RoomVolume& out) {
  out.triangles_world = std::move(triangles_world);
  out.bounds_min = glm::dvec3(std::numeric_limits<double>::infinity());
  out.bounds_max = -out.bounds_min;
  for (const glm::dvec3& p : out.triangles_world) {
    out.bounds_min = glm::min(out.bounds_min, p);
    out.bounds_max = glm::max(out.bounds_max, p);
  }
}

bool volume_contains(const RoomVolume& volume, const glm::dvec3& p, double margin) {
  for (int i = 0; i < 3; ++i)
    if (p[i] < volume.bounds_min[i] - std::max(margin, 0.0) || p[i] > volume.bounds_max[i] + std::max(margin, 0.0))
      return false;
  return volume.triangles_world.empty() ? box_contains(volume, p, margin) : mesh_contains(volume, p, margin);
}

double volume_size(const RoomVolume& volume) { return glm::length(volume.bounds_max - volume.bounds_min); }

bool volumes_overlap(const RoomVolume& a, const RoomVolume& b, double tolerance, glm::dvec3& witness) {
  const glm::dvec3 lo = glm::max(a.bounds_min, b.bounds_min);
  const glm::dvec3 hi = glm::min(a.bounds_max, b.bounds_max);
  for (int i = 0; i < 3; ++i)
    if (hi[i] - lo[i] <= 2.0 * tolerance) return false;
  constexpr int kSteps = 7;
  for (int i = 0; i < kSteps; ++i)
    for (int j = 0; j < kSteps; ++j)
      for (int k = 0; k < kSteps; ++k) {
        const glm::dvec3 f((i + 0.5) / kSteps, (j + 0.5) / kSteps, (k + 0.5) / kSteps);
        const glm::dvec3 p = lo + (hi - lo) * f;
        if (volume_contains(a, p, -tolerance) && volume_contains(b, p, -tolerance)) {
          witness = p;
          return true;
        }
      }
  return false;
}

}  // namespace lintel::rooms
