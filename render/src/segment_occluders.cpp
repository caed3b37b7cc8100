// Median-split BVH (up to 4 triangles a leaf) and a nearest-hit segment query: slab tests
// against the boxes, Moller-Trumbore against the triangles, nearer subtrees pruned by the best
// hit so far.
#include "segment_occluders.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lintel::render {
namespace {

constexpr uint32_t kLeafSize = 4;
// The segment's ends are excluded: a probe or surfel lying on a surface does not hide itself.
constexpr float kEndMargin = 1e-4f;

glm::vec3 centroid(const SegmentOccluders::Triangle& t) { return (t.a + t.b + t.c) * (1.0f / 3.0f); }

// Where along origin + t dir the segment enters the box, if it does before `t_max`.
bool hits_box(const glm::vec3& origin, const glm::vec3& inv_dir, const glm::vec3& lo, const glm::vec3& hi,
              float t_max) {
  float t0 = 0.0f, t1 = t_max;
  for (int a = 0; a < 3; ++a) {
    float n = (lo[a] - origin[a]) * inv_dir[a], f = (hi[a] - origin[a]) * inv_dir[a];
    if (n > f) std::swap(n, f);
    // NaN (0 * inf, the segment in the slab's plane) counts as inside: never a false miss.
    if (n > t0) t0 = n;
    if (f < t1) t1 = f;
    if (t0 > t1) return false;
  }
  return true;
}

// Moller-Trumbore: the segment parameter of the crossing, or a negative value.
float hit_triangle(const glm::vec3& origin, const glm::vec3& dir, const SegmentOccluders::Triangle& t) {
  const glm::vec3 e1 = t.b - t.a, e2 = t.c - t.a;
  const glm::vec3 p = glm::cross(dir, e2);
  const float det = glm::dot(e1, p);
  if (std::abs(det) < 1e-12f) return -1.0f;
  const float inv = 1.0f / det;
  const glm::vec3 s = origin - t.a;
  const float u = glm::dot(s, p) * inv;
  if (u < 0.0f || u > 1.0f) return -1.0f;
  const glm::vec3 q = glm::cross(s, e1);
  const float v = glm::dot(dir, q) * inv;
  if (v < 0.0f || u + v > 1.0f) return -1.0f;
  return glm::dot(e2, q) * inv;
}

}  // namespace

SegmentOccluders::SegmentOccluders(std::vector<Triangle> triangles) : triangles_(std::move(triangles)) {
  if (triangles_.empty()) return;
  nodes_.reserve(2 * triangles_.size() / kLeafSize + 2);
  nodes_.push_back({});
  build(0, 0, uint32_t(triangles_.size()));
}

void SegmentOccluders::build(uint32_t node, uint32_t begin, uint32_t end) {
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  glm::vec3 clo = lo, chi = hi;
  for (uint32_t i = begin; i < end; ++i) {
    const Triangle& t = triangles_[i];
    lo = glm::min(lo, glm::min(t.a, glm::min(t.b, t.c)));
    hi = glm::max(hi, glm::max(t.a, glm::max(t.b, t.c)));
    clo = glm::min(clo, centroid(t));
    chi = glm::max(chi, centroid(t));
  }
  nodes_[node].min = lo;
  nodes_[node].max = hi;
  if (end - begin <= kLeafSize) {
    nodes_[node].first = begin;
    nodes_[node].count = end - begin;
    return;
  }
  const glm::vec3 extent = chi - clo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  const uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(triangles_.begin() + begin, triangles_.begin() + mid, triangles_.begin() + end,
                   [axis](const Triangle& x, const Triangle& y) { return centroid(x)[axis] < centroid(y)[axis]; });
  const uint32_t left = uint32_t(nodes_.size());
  nodes_.push_back({});
  nodes_.push_back({});
  nodes_[node].first = left;
  nodes_[node].count = 0;
  build(left, begin, mid);
  build(left + 1, mid, end);
}

const SegmentOccluders::Triangle* SegmentOccluders::cross(const glm::vec3& from, const glm::vec3& to, bool any) const {
  if (nodes_.empty()) return nullptr;
  const glm::vec3 dir = to - from;
  const glm::vec3 inv_dir = 1.0f / dir;  // +-inf on an axis the segment does not move along
  float best = 1.0f - kEndMargin;
  const Triangle* nearest = nullptr;
  // Median splits make the tree at most log2(triangles) deep, so 64 entries always suffice.
  uint32_t stack[64];
  uint32_t top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    if (!hits_box(from, inv_dir, n.min, n.max, best)) continue;
    if (n.count == 0) {
      stack[top++] = n.first;
      stack[top++] = n.first + 1;
      continue;
    }
    for (uint32_t i = n.first; i < n.first + n.count; ++i) {
      const float t = hit_triangle(from, dir, triangles_[i]);
      if (t > kEndMargin && t < best) {
        best = t;
        nearest = &triangles_[i];
        if (any) return nearest;
      }
    }
  }
  return nearest;
}

SegmentOccluders::Hit SegmentOccluders::first_hit(const glm::vec3& from, const glm::vec3& to) const {
  const Triangle* t = cross(from, to, false);
  if (!t) return Hit::None;
  return glm::dot(t->normal, to - from) < 0.0f ? Hit::Front : Hit::Back;
}

bool SegmentOccluders::blocked(const glm::vec3& from, const glm::vec3& to) const {
  return cross(from, to, true) != nullptr;
}

}  // namespace lintel::render
