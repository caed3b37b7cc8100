// Convex unions of a sector's floor pieces (doom_convex_cells.h). Convexity of a union of pieces
// that do not overlap is tested by area: the union is convex exactly when its convex hull has no
// more area than the pieces together.
#include "doom/doom_convex_cells.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

namespace lintel::doom {
namespace {

constexpr double kOnLine = 0.5;         // map units: an edge's ends this close to another's line share it (see below)
constexpr double kHullRounding = 0.5;   // map units^2 of hull excess always allowed (rounding of corners)
constexpr double kMinSharedRun = 1e-3;  // map units: shorter shared stretches are corners, not boundaries

double cross2(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

// The stretches where an edge of piece p and an edge of piece q lie on one line facing each
// other, as segments along p's edges (p to their left). Appends to `out`.
void shared_edges(const std::vector<glm::dvec2>& p, const std::vector<glm::dvec2>& q,
                  std::vector<std::pair<glm::dvec2, glm::dvec2>>& out) {
  for (size_t i = 0; i < p.size(); ++i) {
    const glm::dvec2 a = p[i], b = p[(i + 1) % p.size()];
    const double length = glm::length(b - a);
    if (!(length > kMinSharedRun)) continue;
    const glm::dvec2 u = (b - a) / length;
    for (size_t j = 0; j < q.size(); ++j) {
      const glm::dvec2 c = q[j], d = q[(j + 1) % q.size()];
      if (glm::dot(d - c, u) >= 0.0) continue;  // same direction: not facing
      if (std::fabs(cross2(u, c - a)) > kOnLine || std::fabs(cross2(u, d - a)) > kOnLine) continue;
      const double tc = glm::dot(c - a, u), td = glm::dot(d - a, u);
      const double lo = std::max(0.0, std::min(tc, td)), hi = std::min(length, std::max(tc, td));
      if (hi - lo > kMinSharedRun) out.emplace_back(a + lo * u, a + hi * u);
    }
  }
}

double shared_length(const std::vector<glm::dvec2>& p, const std::vector<glm::dvec2>& q) {
  std::vector<std::pair<glm::dvec2, glm::dvec2>> runs;
  shared_edges(p, q, runs);
  double sum = 0.0;
  for (const auto& [a, b] : runs) sum += glm::length(b - a);
  return sum;
}

double hull_area(std::vector<glm::dvec2> points) {
  std::sort(points.begin(), points.end(),
            [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (points.size() < 3) return 0.0;
  // Andrew's monotone chain.
  std::vector<glm::dvec2> hull(2 * points.size());
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross2(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross2(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return polygon_area(hull);
}

}  // namespace

double convex_hull_area(const std::vector<FloorPiece>& pieces, const std::vector<size_t>& piece_ids) {
  std::vector<glm::dvec2> points;
  for (size_t p : piece_ids) points.insert(points.end(), pieces[p].polygon.begin(), pieces[p].polygon.end());
  return hull_area(std::move(points));
}

std::vector<std::vector<size_t>> convex_piece_groups(const std::vector<FloorPiece>& pieces,
                                                     const std::vector<size_t>& piece_ids, double hull_excess) {
  const size_t n = piece_ids.size();
  std::vector<size_t> parent(n);
  std::iota(parent.begin(), parent.end(), size_t(0));
  auto find = [&](size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::vector<double> area(n);
  std::vector<std::vector<glm::dvec2>> corners(n);
  for (size_t i = 0; i < n; ++i) {
    area[i] = polygon_area(pieces[piece_ids[i]].polygon);
    corners[i] = pieces[piece_ids[i]].polygon;
  }
  // Adjacent pairs, the longest shared boundary first (ties: lower ids first, deterministic).
  std::vector<std::pair<double, std::pair<size_t, size_t>>> pairs;
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j) {
      const double shared = shared_length(pieces[piece_ids[i]].polygon, pieces[piece_ids[j]].polygon);
      if (shared > kMinSharedRun) pairs.push_back({shared, {i, j}});
    }
  std::stable_sort(pairs.begin(), pairs.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  for (bool merged = true; merged;) {
    merged = false;
    for (const auto& [shared, ij] : pairs) {
      size_t a = find(ij.first), b = find(ij.second);
      if (a == b) continue;
      std::vector<glm::dvec2> both = corners[a];
      both.insert(both.end(), corners[b].begin(), corners[b].end());
      const double sum = area[a] + area[b];
      if (hull_area(both) > sum * (1.0 + hull_excess) + kHullRounding) continue;
      if (a > b) std::swap(a, b);
      parent[b] = a;
      area[a] = sum;
      corners[a] = std::move(both);
      corners[b].clear();
      merged = true;
    }
  }
  std::vector<std::vector<size_t>> groups;
  std::vector<int> group_of_root(n, -1);
  for (size_t i = 0; i < n; ++i) {
    const size_t root = find(i);
    if (group_of_root[root] < 0) {
      group_of_root[root] = int(groups.size());
      groups.emplace_back();
    }
    groups[size_t(group_of_root[root])].push_back(piece_ids[i]);
  }
  for (std::vector<size_t>& g : groups) std::sort(g.begin(), g.end());
  std::sort(groups.begin(), groups.end(), [](const auto& x, const auto& y) { return x.front() < y.front(); });
  return groups;
}

std::vector<GroupBoundary> group_boundaries(const std::vector<FloorPiece>& pieces,
                                            const std::vector<std::vector<size_t>>& groups) {
  std::vector<std::pair<size_t, size_t>> members;  // (piece, group)
  for (size_t g = 0; g < groups.size(); ++g)
    for (size_t p : groups[g]) members.emplace_back(p, g);
  // Shared stretches per ordered pair of groups (lower group to the left).
  std::map<std::pair<size_t, size_t>, std::vector<std::pair<glm::dvec2, glm::dvec2>>> runs;
  for (size_t i = 0; i < members.size(); ++i)
    for (size_t j = i + 1; j < members.size(); ++j) {
      const auto [p, gp] = members[i];
      const auto [q, gq] = members[j];
      if (gp == gq) continue;
      std::vector<std::pair<glm::dvec2, glm::dvec2>> found;
      shared_edges(pieces[p].polygon, pieces[q].polygon, found);
      for (auto [a, b] : found) {
        if (gp < gq)
          runs[{gp, gq}].emplace_back(a, b);
        else
          runs[{gq, gp}].emplace_back(b, a);
      }
    }
  std::vector<GroupBoundary> out;
  for (auto& [key, segments] : runs) {
    // Join stretches on one line that overlap or touch into maximal runs.
    for (bool joined = true; joined;) {
      joined = false;
      for (size_t s = 0; s < segments.size() && !joined; ++s)
        for (size_t t = s + 1; t < segments.size() && !joined; ++t) {
          const auto [a, b] = segments[s];
          const auto [c, d] = segments[t];
          const double length = glm::length(b - a);
          const glm::dvec2 u = (b - a) / length;
          if (glm::dot(d - c, u) <= 0.0) continue;
          if (std::fabs(cross2(u, c - a)) > kOnLine || std::fabs(cross2(u, d - a)) > kOnLine) continue;
          const double tc = glm::dot(c - a, u), td = glm::dot(d - a, u);
          if (tc > length + kOnLine || td < -kOnLine) continue;  // apart
          const double lo = std::min(0.0, tc), hi = std::max(length, td);
          segments[s] = {a + lo * u, a + hi * u};
          segments.erase(segments.begin() + std::ptrdiff_t(t));
          joined = true;
        }
    }
    for (const auto& [a, b] : segments) out.push_back({key.first, key.second, a, b});
  }
  return out;
}

}  // namespace lintel::doom
