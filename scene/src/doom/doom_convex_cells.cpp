// Convex unions of a sector's exact pieces (doom_convex_cells.h). Convexity of a union of pieces
// that do not overlap is tested by area: the union is convex exactly when its convex hull has no
// more area than the pieces together.
#include "doom/doom_convex_cells.h"

#include "doom/polygon_triangulate.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <utility>

namespace lintel::doom {

std::vector<size_t> convex_piece_groups(const SectorPartition& part, double hull_excess,
                                        const std::vector<std::pair<size_t, size_t>>& must_join, size_t& group_count) {
  const size_t n = part.pieces.size();
  std::vector<size_t> parent(n);
  std::iota(parent.begin(), parent.end(), size_t(0));
  auto find = [&](size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::vector<double> area(n, 0.0);
  std::vector<std::vector<glm::dvec2>> corners(n);
  for (size_t i = 0; i < n; ++i) {
    const SectorPartition::Piece& piece = part.pieces[i];
    for (const auto& t : piece.triangles)
      area[i] += 0.5 * orient2(part.corners[t[0]], part.corners[t[1]], part.corners[t[2]]);
    for (uint32_t c : piece.polygon) corners[i].push_back(part.corners[c]);
  }
  // Adjacent pairs with the length of boundary they share, longest first (ties: lower ids first).
  std::map<std::pair<size_t, size_t>, double> shared;
  for (const SectorPartition::Diagonal& d : part.diagonals)
    shared[{std::min(d.left, d.right), std::max(d.left, d.right)}] +=
        glm::length(part.corners[d.b] - part.corners[d.a]);
  std::vector<std::pair<double, std::pair<size_t, size_t>>> pairs;
  for (const auto& [ij, length] : shared) pairs.push_back({length, ij});
  std::stable_sort(pairs.begin(), pairs.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  auto join = [&](size_t a, size_t b, std::vector<glm::dvec2> both) {
    if (a > b) std::swap(a, b);
    parent[b] = a;
    area[a] += area[b];
    corners[a] = std::move(both);
    corners[b].clear();
  };
  for (const auto& [p, q] : must_join) {
    const size_t a = find(p), b = find(q);
    if (a == b) continue;
    std::vector<glm::dvec2> both = corners[a];
    both.insert(both.end(), corners[b].begin(), corners[b].end());
    join(a, b, std::move(both));
  }
  for (bool merged = true; merged;) {
    merged = false;
    for (const auto& [length, ij] : pairs) {
      const size_t a = find(ij.first), b = find(ij.second);
      if (a == b) continue;
      std::vector<glm::dvec2> both = corners[a];
      both.insert(both.end(), corners[b].begin(), corners[b].end());
      if (convex_hull_area(both) > (area[a] + area[b]) * (1.0 + hull_excess)) continue;
      join(a, b, std::move(both));
      merged = true;
    }
  }
  std::vector<size_t> group(n), group_of_root(n, SIZE_MAX);
  group_count = 0;
  for (size_t i = 0; i < n; ++i) {
    const size_t root = find(i);
    if (group_of_root[root] == SIZE_MAX) group_of_root[root] = group_count++;
    group[i] = group_of_root[root];
  }
  return group;
}

std::vector<GroupBoundary> group_boundaries(const SectorPartition& part, const std::vector<size_t>& group_of_piece) {
  // Cuts per ordered pair of groups, the lower group on the left.
  std::map<std::pair<size_t, size_t>, std::vector<std::pair<uint32_t, uint32_t>>> cuts;
  for (const SectorPartition::Diagonal& d : part.diagonals) {
    const size_t gl = group_of_piece[d.left], gr = group_of_piece[d.right];
    if (gl == gr) continue;
    if (gl < gr)
      cuts[{gl, gr}].emplace_back(d.a, d.b);
    else
      cuts[{gr, gl}].emplace_back(d.b, d.a);
  }
  std::vector<GroupBoundary> out;
  const std::vector<glm::dvec2>& pts = part.corners;
  for (auto& [key, segments] : cuts) {
    // Join a -> b and b -> c when a, b, c are collinear (exact: integer corners).
    for (bool joined = true; joined;) {
      joined = false;
      for (size_t s = 0; s < segments.size() && !joined; ++s)
        for (size_t t = 0; t < segments.size() && !joined; ++t) {
          if (s == t || segments[s].second != segments[t].first) continue;
          const glm::dvec2 a = pts[segments[s].first], b = pts[segments[s].second], c = pts[segments[t].second];
          if (orient2(a, b, c) != 0.0 || glm::dot(b - a, c - b) <= 0.0) continue;
          segments[s].second = segments[t].second;
          segments.erase(segments.begin() + std::ptrdiff_t(t));
          joined = true;
        }
    }
    for (const auto& [a, b] : segments) out.push_back({key.first, key.second, pts[a], pts[b]});
  }
  return out;
}

}  // namespace lintel::doom
