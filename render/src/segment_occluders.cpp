// Median-split BVHs (up to 4 triangles a leaf) and a nearest-hit segment query: slab tests
// against the boxes, Moller-Trumbore against the triangles, nearer subtrees pruned by the best
// hit so far. The boundary planes' triangles have a BVH of their own, asked only when an end of
// the segment is not well inside all of those planes (segment_occluders.h).
#include "segment_occluders.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <numeric>

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

// Moller-Trumbore: the segment parameter of the crossing, or a negative value; u, v: the
// crossing's barycentric weights of b and c.
float hit_triangle(const glm::vec3& origin, const glm::vec3& dir, const SegmentOccluders::Triangle& t, float& u,
                   float& v) {
  const glm::vec3 e1 = t.b - t.a, e2 = t.c - t.a;
  const glm::vec3 p = glm::cross(dir, e2);
  const float det = glm::dot(e1, p);
  if (std::abs(det) < 1e-12f) return -1.0f;
  const float inv = 1.0f / det;
  const glm::vec3 s = origin - t.a;
  u = glm::dot(s, p) * inv;
  if (u < 0.0f || u > 1.0f) return -1.0f;
  const glm::vec3 q = glm::cross(s, e1);
  v = glm::dot(dir, q) * inv;
  if (v < 0.0f || u + v > 1.0f) return -1.0f;
  return glm::dot(e2, q) * inv;
}

// Candidate boundary planes: the planes of the largest triangles, this many at most (a room has
// a handful; a curved wall's many small planes are left to the interior BVH).
constexpr size_t kMaxCandidatePlanes = 64;

}  // namespace

bool SegmentOccluders::CutOut::covered(float u, float v) const {
  float alpha = (1.0f - u - v) * alpha_a + u * alpha_b + v * alpha_c;
  if (texture) {
    const glm::vec2 uv = (1.0f - u - v) * uv_a + u * uv_b + v * uv_c;
    alpha *= sample_texture_rgba(*texture, sampler, uv, 0.0f).a;
  }
  return alpha >= cutoff;
}

SegmentOccluders::SegmentOccluders(const std::vector<Triangle>& triangles, std::vector<CutOut> cut_outs)
    : cuts_(std::move(cut_outs)), interior_({}), boundary_({}) {
  if (triangles.empty()) return;
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const Triangle& t : triangles) {
    lo = glm::min(lo, glm::min(t.a, glm::min(t.b, t.c)));
    hi = glm::max(hi, glm::max(t.a, glm::max(t.b, t.c)));
  }
  // Far beyond float rounding of a plane's offset at these coordinates, far below a room's size.
  const float largest = std::max(glm::length(lo), glm::length(hi));
  margin_ = 1e-5f * glm::length(hi - lo) + 16.0f * FLT_EPSILON * largest;
  std::vector<int> plane_of;
  planes_ = find_boundary_planes(triangles, margin_, plane_of);
  std::vector<Triangle> interior, boundary;
  for (size_t i = 0; i < triangles.size(); ++i) (plane_of[i] >= 0 ? boundary : interior).push_back(triangles[i]);
  interior_ = Bvh(std::move(interior));
  boundary_ = Bvh(std::move(boundary));
}

std::vector<SegmentOccluders::Plane> SegmentOccluders::find_boundary_planes(const std::vector<Triangle>& triangles,
                                                                            float margin, std::vector<int>& plane_of) {
  plane_of.assign(triangles.size(), -1);
  std::vector<float> area(triangles.size());
  std::vector<glm::vec3> normal(triangles.size());
  for (size_t i = 0; i < triangles.size(); ++i) {
    const Triangle& t = triangles[i];
    const glm::vec3 c = glm::cross(t.b - t.a, t.c - t.a);
    area[i] = glm::length(c);
    normal[i] = area[i] > 0.0f ? c / area[i] : glm::vec3(0.0f);
  }
  std::vector<uint32_t> order(triangles.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](uint32_t x, uint32_t y) { return area[x] > area[y]; });
  // Each triangle's candidate: the first one whose plane holds all three of its vertices.
  struct Candidate {
    glm::vec3 n;
    float d;
    bool front = true, back = true;  // no vertex beyond the margin behind it / in front of it
  };
  std::vector<Candidate> candidates;
  std::vector<int> candidate_of(triangles.size(), -1);
  for (uint32_t i : order) {
    if (!(area[i] > 0.0f)) continue;
    const Triangle& t = triangles[i];
    auto holds = [&](const Candidate& c) {
      return std::abs(glm::dot(c.n, t.a) - c.d) <= margin && std::abs(glm::dot(c.n, t.b) - c.d) <= margin &&
             std::abs(glm::dot(c.n, t.c) - c.d) <= margin;
    };
    for (size_t k = 0; k < candidates.size() && candidate_of[i] < 0; ++k)
      if (std::abs(glm::dot(candidates[k].n, normal[i])) > 1.0f - 1e-5f && holds(candidates[k]))
        candidate_of[i] = int(k);
    if (candidate_of[i] < 0 && candidates.size() < kMaxCandidatePlanes &&
        holds({normal[i], glm::dot(normal[i], t.a)})) {
      candidate_of[i] = int(candidates.size());
      candidates.push_back({normal[i], glm::dot(normal[i], t.a)});
    }
  }
  // A boundary plane has every vertex of the cell on one side (or on it).
  for (const Triangle& t : triangles)
    for (const glm::vec3& v : {t.a, t.b, t.c})
      for (Candidate& c : candidates) {
        const float s = glm::dot(c.n, v) - c.d;
        c.front = c.front && s >= -margin;
        c.back = c.back && s <= margin;
      }
  std::vector<Plane> planes;
  std::vector<int> plane_index(candidates.size(), -1);
  for (size_t k = 0; k < candidates.size(); ++k) {
    const Candidate& c = candidates[k];
    if (c.front == c.back) continue;  // geometry on both sides, or all of it flat in the plane
    plane_index[k] = int(planes.size());
    planes.push_back(c.front ? Plane{c.n, c.d} : Plane{-c.n, -c.d});
  }
  for (size_t i = 0; i < triangles.size(); ++i)
    if (candidate_of[i] >= 0) plane_of[i] = plane_index[size_t(candidate_of[i])];
  return planes;
}

bool SegmentOccluders::inside_boundary(const glm::vec3& p) const {
  for (const Plane& plane : planes_)
    if (!(glm::dot(plane.n, p) - plane.d > margin_)) return false;
  return true;
}

const SegmentOccluders::Triangle* SegmentOccluders::cross(const glm::vec3& from, const glm::vec3& to, bool any,
                                                          bool ends_inside) const {
  float best = 1.0f - kEndMargin;
  const Triangle* hit = interior_.cross(from, to, any, best, cuts_);
  if (hit && any) return hit;
  // Both ends well inside every boundary plane: the segment crosses none of them.
  if (planes_.empty() || ends_inside) return hit;
  const Triangle* on_boundary = boundary_.cross(from, to, any, best, cuts_);
  return on_boundary ? on_boundary : hit;
}

SegmentOccluders::Bvh::Bvh(std::vector<Triangle> triangles) : triangles_(std::move(triangles)) {
  if (triangles_.empty()) return;
  nodes_.reserve(2 * triangles_.size() / kLeafSize + 2);
  nodes_.push_back({});
  build(0, 0, uint32_t(triangles_.size()));
}

void SegmentOccluders::Bvh::build(uint32_t node, uint32_t begin, uint32_t end) {
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

const SegmentOccluders::Triangle* SegmentOccluders::Bvh::cross(const glm::vec3& from, const glm::vec3& to, bool any,
                                                               float& best, const std::vector<CutOut>& cuts) const {
  if (nodes_.empty()) return nullptr;
  const glm::vec3 dir = to - from;
  const glm::vec3 inv_dir = 1.0f / dir;  // +-inf on an axis the segment does not move along
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
      float u = 0.0f, v = 0.0f;
      const float t = hit_triangle(from, dir, triangles_[i], u, v);
      if (t > kEndMargin && t < best && (triangles_[i].cut < 0 || cuts[size_t(triangles_[i].cut)].covered(u, v))) {
        best = t;
        nearest = &triangles_[i];
        if (any) return nearest;
      }
    }
  }
  return nearest;
}

SegmentOccluders::Hit SegmentOccluders::first_hit(const glm::vec3& from, const glm::vec3& to,
                                                  bool ends_inside_boundary) const {
  const Triangle* t = cross(from, to, false, ends_inside_boundary);
  if (!t) return Hit::None;
  return glm::dot(t->normal, to - from) < 0.0f ? Hit::Front : Hit::Back;
}

bool SegmentOccluders::blocked(const glm::vec3& from, const glm::vec3& to, bool ends_inside_boundary) const {
  return cross(from, to, true, ends_inside_boundary) != nullptr;
}

SegmentOccluders::Hit SegmentOccluders::first_hit(const glm::vec3& from, const glm::vec3& to) const {
  return first_hit(from, to, inside_boundary(from) && inside_boundary(to));
}

bool SegmentOccluders::blocked(const glm::vec3& from, const glm::vec3& to) const {
  return blocked(from, to, inside_boundary(from) && inside_boundary(to));
}

}  // namespace lintel::render
