// Incremental 3D convex hull (the textbook algorithm, e.g. de Berg et al., "Computational
// Geometry", ch. 11, without the conflict graph: each point scans the faces). A point within
// `tolerance` of the hull is inside; the horizon is the set of visible faces' edges whose reverse
// is not also visible, so the new faces close the surface again.
#include "rooms/rooms_hull.h"

#include <algorithm>
#include <set>
#include <utility>

namespace lintel::rooms {
namespace {

struct Face {
  size_t a, b, c;
  glm::dvec3 normal;  // unit, outwards
  double offset;      // dot(normal, p) == offset on the face
  bool alive = true;
};

bool make_face(const std::vector<glm::dvec3>& p, size_t a, size_t b, size_t c, Face& out) {
  const glm::dvec3 n = glm::cross(p[b] - p[a], p[c] - p[a]);
  const double length = glm::length(n);
  if (!(length > 0.0)) return false;
  out = {a, b, c, n / length, glm::dot(n / length, p[a])};
  return true;
}

bool lex_less(const glm::dvec3& l, const glm::dvec3& r) {
  return l.x < r.x || (l.x == r.x && (l.y < r.y || (l.y == r.y && l.z < r.z)));
}

}  // namespace

bool convex_hull_3d(const std::vector<glm::dvec3>& points, double tolerance, std::vector<glm::dvec3>& triangles) {
  std::vector<glm::dvec3> p = points;
  std::sort(p.begin(), p.end(), lex_less);
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 4 || p.size() > kMaxHullPoints) return false;
  // A first tetrahedron from extreme points: p[0] (lexicographic minimum), the farthest from it,
  // the farthest from their line, the farthest from their plane.
  size_t i1 = 0, i2 = 0, i3 = 0;
  double best = 0.0;
  for (size_t i = 1; i < p.size(); ++i)
    if (double d = glm::length(p[i] - p[0]); d > best) best = d, i1 = i;
  if (best <= tolerance) return false;
  const glm::dvec3 axis = (p[i1] - p[0]) / best;
  best = 0.0;
  for (size_t i = 1; i < p.size(); ++i)
    if (double d = glm::length(glm::cross(p[i] - p[0], axis)); d > best) best = d, i2 = i;
  if (best <= tolerance) return false;
  const glm::dvec3 normal = glm::normalize(glm::cross(p[i1] - p[0], p[i2] - p[0]));
  best = 0.0;
  double signed_best = 0.0;
  for (size_t i = 1; i < p.size(); ++i)
    if (double d = glm::dot(p[i] - p[0], normal); std::abs(d) > best) best = std::abs(d), signed_best = d, i3 = i;
  if (best <= tolerance) return false;
  std::vector<Face> faces(4);
  bool ok = true;
  if (signed_best < 0.0) {  // i3 below the plane (0, i1, i2): that face looks up, away from it
    ok = make_face(p, 0, i1, i2, faces[0]) && make_face(p, 0, i3, i1, faces[1]) && make_face(p, i1, i3, i2, faces[2]) &&
         make_face(p, i2, i3, 0, faces[3]);
  } else {
    ok = make_face(p, 0, i2, i1, faces[0]) && make_face(p, 0, i1, i3, faces[1]) && make_face(p, i1, i2, i3, faces[2]) &&
         make_face(p, i2, 0, i3, faces[3]);
  }
  if (!ok) return false;
  for (size_t i = 1; i < p.size(); ++i) {
    if (i == i1 || i == i2 || i == i3) continue;
    std::set<std::pair<size_t, size_t>> visible_edges;
    std::vector<size_t> visible;
    for (size_t f = 0; f < faces.size(); ++f)
      if (faces[f].alive && glm::dot(faces[f].normal, p[i]) - faces[f].offset > tolerance) {
        visible.push_back(f);
        const Face& v = faces[f];
        visible_edges.insert({{v.a, v.b}, {v.b, v.c}, {v.c, v.a}});
      }
    if (visible.empty()) continue;
    for (size_t f : visible) faces[f].alive = false;
    for (const auto& [a, b] : visible_edges) {
      if (visible_edges.count({b, a})) continue;  // inside the visible region
      Face face;
      if (!make_face(p, a, b, i, face)) return false;
      faces.push_back(face);
    }
  }
  std::vector<glm::dvec3> out;
  std::set<std::pair<size_t, size_t>> edges;
  for (const Face& f : faces) {
    if (!f.alive) continue;
    out.insert(out.end(), {p[f.a], p[f.b], p[f.c]});
    edges.insert({{f.a, f.b}, {f.b, f.c}, {f.c, f.a}});
  }
  for (const auto& [a, b] : edges)  // closed and consistently wound: every edge has its reverse
    if (!edges.count({b, a})) return false;
  triangles.insert(triangles.end(), out.begin(), out.end());
  return true;
}

}  // namespace lintel::rooms
