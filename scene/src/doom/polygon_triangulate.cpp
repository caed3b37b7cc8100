// Ear clipping with hole bridges (polygon_triangulate.h). Holes are bridged in order of their
// rightmost corner, rightmost first, each to the nearest vertex of the polygon built so far that
// it sees (checked against every edge, not found by a ray: slower, but exact); a bridge adds two
// copies of both of its ends. Ears are cut with an exact containment test that ignores copies of
// the ear's own corners.
#include "doom/polygon_triangulate.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <utility>

namespace lintel::doom {
namespace {

// p strictly inside the (interior) angle at v between edges prev -> v -> next, the interior on
// the left: a convex corner's wedge is open; a reflex corner's is everything outside the
// exterior's closed wedge.
bool inside_angle(const glm::dvec2& prev, const glm::dvec2& v, const glm::dvec2& next, const glm::dvec2& p) {
  const double in = orient2(prev, v, p), out = orient2(v, next, p);
  if (orient2(prev, v, next) > 0.0) return in > 0.0 && out > 0.0;
  return in > 0.0 || out > 0.0;
}

// Segment m-v meets edge a-b anywhere but at m or v themselves (an edge ending at m or v may only
// touch there).
bool blocks(const glm::dvec2& m, const glm::dvec2& v, const glm::dvec2& a, const glm::dvec2& b) {
  for (const glm::dvec2& end : {m, v}) {
    if (a != end && b != end) continue;
    const glm::dvec2 other = a == end ? b : a, far = end == m ? v : m;
    // Shares an end: blocks only when it runs along the segment.
    return orient2(end, far, other) == 0.0 && glm::dot(other - end, far - end) > 0.0;
  }
  return closed_segments_meet(m, v, a, b);
}

bool point_in_closed_triangle(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, const glm::dvec2& p) {
  return orient2(a, b, p) >= 0.0 && orient2(b, c, p) >= 0.0 && orient2(c, a, p) >= 0.0;
}

// Joins `hole` into `ring` by a bridge from the hole's rightmost corner to the nearest ring vertex
// it sees. `pending` are the holes not joined yet (their edges may block a bridge).
bool bridge_hole(const std::vector<glm::dvec2>& pts, std::vector<uint32_t>& ring, const std::vector<uint32_t>& hole,
                 const std::vector<const std::vector<uint32_t>*>& pending) {
  size_t mi = 0;
  for (size_t i = 1; i < hole.size(); ++i) {
    const glm::dvec2 &p = pts[hole[i]], &q = pts[hole[mi]];
    if (p.x > q.x || (p.x == q.x && p.y > q.y)) mi = i;
  }
  const glm::dvec2 m = pts[hole[mi]];
  const glm::dvec2 m_prev = pts[hole[(mi + hole.size() - 1) % hole.size()]], m_next = pts[hole[(mi + 1) % hole.size()]];
  size_t best = ring.size();
  double best_d2 = 0.0;
  for (size_t k = 0; k < ring.size(); ++k) {
    const glm::dvec2 v = pts[ring[k]];
    const double d2 = glm::dot(v - m, v - m);
    if (best < ring.size() && d2 >= best_d2) continue;
    const glm::dvec2 v_prev = pts[ring[(k + ring.size() - 1) % ring.size()]], v_next = pts[ring[(k + 1) % ring.size()]];
    if (!inside_angle(v_prev, v, v_next, m) || !inside_angle(m_prev, m, m_next, v)) continue;
    bool clear = true;
    for (size_t e = 0; e < ring.size() && clear; ++e)
      clear = !blocks(m, v, pts[ring[e]], pts[ring[(e + 1) % ring.size()]]);
    for (const std::vector<uint32_t>* h : pending)
      for (size_t e = 0; e < h->size() && clear; ++e)
        clear = !blocks(m, v, pts[(*h)[e]], pts[(*h)[(e + 1) % h->size()]]);
    if (clear) best = k, best_d2 = d2;
  }
  if (best == ring.size()) return false;
  // ring[..best], m, the hole around from m back to m, ring[best] again, ring[best+1..]
  std::vector<uint32_t> joined(ring.begin(), ring.begin() + std::ptrdiff_t(best) + 1);
  for (size_t i = 0; i <= hole.size(); ++i) joined.push_back(hole[(mi + i) % hole.size()]);
  joined.push_back(ring[best]);
  joined.insert(joined.end(), ring.begin() + std::ptrdiff_t(best) + 1, ring.end());
  ring = std::move(joined);
  return true;
}

}  // namespace

double orient2(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool closed_segments_meet(const glm::dvec2& p, const glm::dvec2& q, const glm::dvec2& a, const glm::dvec2& b) {
  const double d1 = orient2(a, b, p), d2 = orient2(a, b, q), d3 = orient2(p, q, a), d4 = orient2(p, q, b);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  auto on = [](const glm::dvec2& s0, const glm::dvec2& s1, const glm::dvec2& r, double d) {
    return d == 0.0 && std::min(s0.x, s1.x) <= r.x && r.x <= std::max(s0.x, s1.x) && std::min(s0.y, s1.y) <= r.y &&
           r.y <= std::max(s0.y, s1.y);
  };
  return on(a, b, p, d1) || on(a, b, q, d2) || on(p, q, a, d3) || on(p, q, b, d4);
}

bool triangulate_polygon(const std::vector<glm::dvec2>& pts, const std::vector<uint32_t>& outer,
                         const std::vector<std::vector<uint32_t>>& holes,
                         std::vector<std::array<uint32_t, 3>>& triangles) {
  triangles.clear();
  std::vector<uint32_t> ring = outer;
  std::vector<size_t> order(holes.size());
  std::iota(order.begin(), order.end(), size_t(0));
  auto rightmost = [&](size_t h) {
    glm::dvec2 best = pts[holes[h][0]];
    for (uint32_t i : holes[h])
      if (pts[i].x > best.x || (pts[i].x == best.x && pts[i].y > best.y)) best = pts[i];
    return best;
  };
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    const glm::dvec2 pa = rightmost(a), pb = rightmost(b);
    return pa.x > pb.x || (pa.x == pb.x && (pa.y > pb.y || (pa.y == pb.y && a < b)));
  });
  for (size_t k = 0; k < order.size(); ++k) {
    std::vector<const std::vector<uint32_t>*> pending;
    for (size_t j = k + 1; j < order.size(); ++j) pending.push_back(&holes[order[j]]);
    if (!bridge_hole(pts, ring, holes[order[k]], pending)) return false;
  }

  // Ear clipping over a circular list of ring positions.
  const size_t n = ring.size();
  if (n < 3) return false;
  std::vector<size_t> prev(n), next(n);
  for (size_t i = 0; i < n; ++i) prev[i] = (i + n - 1) % n, next[i] = (i + 1) % n;
  size_t left = n, at = 0, since_cut = 0;
  while (left > 3) {
    if (since_cut > left) {  // a whole round without an ear
      triangles.clear();
      return false;
    }
    const glm::dvec2 p = pts[ring[prev[at]]], v = pts[ring[at]], q = pts[ring[next[at]]];
    bool ear = orient2(p, v, q) > 0.0;
    for (size_t j = next[next[at]]; ear && j != prev[at]; j = next[j]) {
      const glm::dvec2 r = pts[ring[j]];
      if (r == p || r == v || r == q) continue;  // a copy of a corner (a bridge's end)
      ear = !point_in_closed_triangle(p, v, q, r);
    }
    if (!ear) {
      at = next[at];
      ++since_cut;
      continue;
    }
    triangles.push_back({ring[prev[at]], ring[at], ring[next[at]]});
    next[prev[at]] = next[at];
    prev[next[at]] = prev[at];
    at = prev[at];
    --left;
    since_cut = 0;
  }
  const glm::dvec2 p = pts[ring[prev[at]]], v = pts[ring[at]], q = pts[ring[next[at]]];
  if (!(orient2(p, v, q) > 0.0)) {
    triangles.clear();
    return false;
  }
  triangles.push_back({ring[prev[at]], ring[at], ring[next[at]]});
  return true;
}

bool triangulation_covers_outline(const std::vector<glm::dvec2>& pts, const std::vector<std::vector<uint32_t>>& loops,
                                  const std::vector<std::array<uint32_t, 3>>& triangles) {
  std::map<std::pair<uint32_t, uint32_t>, int> used;  // directed edge -> times used by a triangle
  for (const auto& t : triangles) {
    if (!(orient2(pts[t[0]], pts[t[1]], pts[t[2]]) > 0.0)) return false;
    for (int k = 0; k < 3; ++k)
      if (++used[{t[size_t(k)], t[size_t(k + 1) % 3]}] > 1) return false;
  }
  size_t outline_edges = 0;
  for (const std::vector<uint32_t>& loop : loops)
    for (size_t i = 0; i < loop.size(); ++i) {
      const uint32_t a = loop[i], b = loop[(i + 1) % loop.size()];
      const auto it = used.find({a, b});
      if (it == used.end() || used.count({b, a})) return false;
      ++outline_edges;
    }
  size_t unpaired = 0;
  for (const auto& [edge, count] : used) unpaired += !used.count({edge.second, edge.first});
  return unpaired == outline_edges;
}

}  // namespace lintel::doom
