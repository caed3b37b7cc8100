// Exact convex pieces of a sector (doom_sector_partition.h): outline loops from the sector's line
// sides, the checks that make them a polygon with holes, ear clipping per outer loop, the
// certificate, then the Hertel-Mehlhorn merge of the triangles.
#include "doom/doom_sector_partition.h"

#include "doom/polygon_triangulate.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

namespace lintel::doom {
namespace {

constexpr double kMaxExactCoordinate = 1048576.0;  // 2^20: products and area sums stay exact in double

struct OutlineEdge {
  uint32_t pos_from = 0, pos_to = 0;  // positions; the sector lies to the left of from -> to
  uint32_t from = 0, to = 0;          // corners (a position where two loops touch has a corner per loop)
  uint32_t side = 0;                  // 2 * linedef + (0 front, 1 back)
};

// Winding number of a closed loop around p (p on no edge of it).
int winding(const std::vector<glm::dvec2>& pts, const std::vector<uint32_t>& loop, const glm::dvec2& p) {
  int w = 0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const glm::dvec2 a = pts[loop[i]], b = pts[loop[(i + 1) % loop.size()]];
    if (a.y <= p.y) {
      if (b.y > p.y && orient2(a, b, p) > 0.0) ++w;
    } else if (b.y <= p.y && orient2(a, b, p) < 0.0) {
      --w;
    }
  }
  return w;
}

double twice_area(const std::vector<glm::dvec2>& pts, const std::vector<uint32_t>& loop) {
  double sum = 0.0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const glm::dvec2 a = pts[loop[i]], b = pts[loop[(i + 1) % loop.size()]];
    sum += a.x * b.y - b.x * a.y;
  }
  return sum;
}

// The outline's directed edges between distinct positions. Empty string or the reason.
std::string outline_edges(const Map& map, uint16_t sector, const std::vector<uint32_t>& lines,
                          std::vector<glm::dvec2>& positions, std::vector<OutlineEdge>& edges) {
  std::map<std::pair<double, double>, uint32_t> position_of;
  auto position = [&](const glm::dvec2& p) {
    const auto [it, added] = position_of.try_emplace({p.x, p.y}, uint32_t(positions.size()));
    if (added) positions.push_back(p);
    return it->second;
  };
  for (const uint32_t l : lines) {
    const Linedef& line = map.linedefs[l];
    const glm::dvec2 a = map.vertices[line.v1], b = map.vertices[line.v2];
    if (a == b) continue;
    const int front = map.sidedefs[line.front].sector;
    const int back = line.back == kNoSide ? -1 : map.sidedefs[line.back].sector;
    if (front == back || (front != sector && back != sector)) continue;
    for (const glm::dvec2& p : {a, b})
      if (p != glm::floor(p) || std::fabs(p.x) >= kMaxExactCoordinate || std::fabs(p.y) >= kMaxExactCoordinate)
        return "a line end is not an integer point";
    // The front side lies to the right of v1 -> v2.
    if (front == sector) edges.push_back({position(b), position(a), 0, 0, uint32_t(2 * l)});
    if (back == sector) edges.push_back({position(a), position(b), 0, 0, uint32_t(2 * l + 1)});
  }
  if (edges.size() < 3) return "fewer than 3 lines";
  return {};
}

// Where 2k lines of the sector meet at one position, they must alternate in, out around it (the
// sector and the outside take turns); each edge arriving is then followed by the next edge
// clockwise, which leaves, and that pair gets a corner of its own. So loops that touch at a
// position (two rooms meeting at a corner, a pillar touching a wall) become loops that share a
// position but no corner. Fills the corners and every edge's from/to.
std::string join_at_corners(const std::vector<glm::dvec2>& positions, std::vector<OutlineEdge>& edges,
                            std::vector<glm::dvec2>& corners) {
  std::vector<std::vector<uint32_t>> at(positions.size());  // edges touching each position
  for (uint32_t e = 0; e < edges.size(); ++e) at[edges[e].pos_from].push_back(e), at[edges[e].pos_to].push_back(e);
  for (uint32_t v = 0; v < positions.size(); ++v) {
    std::vector<uint32_t>& incident = at[v];
    if (incident.size() < 2 || incident.size() % 2) return "a corner ends an odd number of its lines";
    // Direction from v along each edge; sorted clockwise starting from the first one's, exactly.
    auto dir = [&](uint32_t e) {
      const uint32_t other = edges[e].pos_from == v ? edges[e].pos_to : edges[e].pos_from;
      return positions[other] - positions[v];
    };
    const glm::dvec2 r = dir(incident[0]);
    auto cross = [](const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; };
    auto half = [&](const glm::dvec2& w) {  // 0: along r, 1: clockwise within a half turn, 2: opposite, 3: the rest
      const double c = cross(r, w);
      if (c == 0.0) return glm::dot(r, w) > 0.0 ? 0 : 2;
      return c < 0.0 ? 1 : 3;
    };
    std::sort(incident.begin(), incident.end(), [&](uint32_t x, uint32_t y) {
      const glm::dvec2 a = dir(x), b = dir(y);
      const int ha = half(a), hb = half(b);
      if (ha != hb) return ha < hb;
      return cross(a, b) < 0.0;  // b clockwise of a
    });
    const size_t n = incident.size();
    for (size_t i = 0; i < n; ++i) {
      const glm::dvec2 a = dir(incident[i]), b = dir(incident[(i + 1) % n]);
      if (cross(a, b) == 0.0 && glm::dot(a, b) > 0.0) return "two of its lines overlap";
      const bool arrives = edges[incident[i]].pos_to == v, next_leaves = edges[incident[(i + 1) % n]].pos_from == v;
      if (arrives != next_leaves) return "its lines at a corner do not alternate in and out";
    }
    for (size_t i = 0; i < n; ++i) {
      if (edges[incident[i]].pos_to != v) continue;
      const auto corner = uint32_t(corners.size());
      corners.push_back(positions[v]);
      edges[incident[i]].to = corner;
      edges[incident[(i + 1) % n]].from = corner;
    }
  }
  return {};
}

// No two edges meet except consecutive ones at their shared corner (those must not fold back
// onto each other) and edges at a position where loops touch, which may share only that point.
std::string check_simple(const std::vector<glm::dvec2>& positions, const std::vector<OutlineEdge>& edges) {
  std::vector<uint32_t> by_x(edges.size());
  std::iota(by_x.begin(), by_x.end(), 0u);
  auto lo_x = [&](uint32_t e) { return std::min(positions[edges[e].pos_from].x, positions[edges[e].pos_to].x); };
  auto hi_x = [&](uint32_t e) { return std::max(positions[edges[e].pos_from].x, positions[edges[e].pos_to].x); };
  std::sort(by_x.begin(), by_x.end(), [&](uint32_t x, uint32_t y) { return lo_x(x) < lo_x(y); });
  for (size_t i = 0; i < by_x.size(); ++i) {
    const OutlineEdge& e = edges[by_x[i]];
    const glm::dvec2 p = positions[e.pos_from], q = positions[e.pos_to];
    for (size_t j = i + 1; j < by_x.size() && lo_x(by_x[j]) <= hi_x(by_x[i]); ++j) {
      const OutlineEdge& f = edges[by_x[j]];
      const glm::dvec2 a = positions[f.pos_from], b = positions[f.pos_to];
      const bool share_p = p == a || p == b, share_q = q == a || q == b;
      if (share_p && share_q) return "two of its lines overlap";
      if (share_p || share_q) {
        // One shared end: they must not run along each other from it.
        const glm::dvec2 s = share_p ? p : q, u = share_p ? q : p, w = s == a ? b : a;
        if (orient2(s, u, w) == 0.0 && glm::dot(u - s, w - s) > 0.0) return "two of its lines overlap";
        continue;
      }
      if (closed_segments_meet(p, q, a, b)) return "two of its lines cross or touch";
    }
  }
  return {};
}

// Merges convex pieces across diagonals while they stay convex, longest diagonal first. Fills
// out.pieces and out.diagonals from the triangles.
void merge_convex(const std::vector<std::array<uint32_t, 3>>& triangles, SectorPartition& out) {
  const std::vector<glm::dvec2>& pts = out.corners;
  std::map<std::pair<uint32_t, uint32_t>, size_t> triangle_of;  // directed edge -> its triangle
  for (size_t t = 0; t < triangles.size(); ++t)
    for (size_t k = 0; k < 3; ++k) triangle_of[{triangles[t][k], triangles[t][(k + 1) % 3]}] = t;
  struct Inner {
    double length = 0.0;
    uint32_t a = 0, b = 0;
    size_t left = 0, right = 0;  // triangles
  };
  std::vector<Inner> inner;
  for (const auto& [edge, t] : triangle_of) {
    if (edge.first > edge.second) continue;
    const auto it = triangle_of.find({edge.second, edge.first});
    if (it == triangle_of.end()) continue;
    inner.push_back({glm::length(pts[edge.second] - pts[edge.first]), edge.first, edge.second, t, it->second});
  }
  std::stable_sort(inner.begin(), inner.end(), [](const Inner& x, const Inner& y) { return x.length > y.length; });

  std::vector<size_t> parent(triangles.size());
  std::iota(parent.begin(), parent.end(), size_t(0));
  auto find = [&](size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::vector<std::vector<uint32_t>> polygon(triangles.size());
  for (size_t t = 0; t < triangles.size(); ++t) polygon[t] = {triangles[t][0], triangles[t][1], triangles[t][2]};
  std::vector<uint8_t> kept(inner.size(), 1);
  for (size_t d = 0; d < inner.size(); ++d) {
    const size_t p = find(inner[d].left), q = find(inner[d].right);
    if (p == q) continue;
    // p has a -> b, q has b -> a. Merged: p from b round to a, then q's corners strictly between a and b.
    const std::vector<uint32_t>&pp = polygon[p], &qq = polygon[q];
    const size_t ib = size_t(std::find(pp.begin(), pp.end(), inner[d].b) - pp.begin());
    const size_t ia = size_t(std::find(qq.begin(), qq.end(), inner[d].a) - qq.begin());
    std::vector<uint32_t> merged;
    for (size_t k = 0; k < pp.size(); ++k) merged.push_back(pp[(ib + k) % pp.size()]);  // b ... a
    for (size_t k = 1; k + 1 < qq.size(); ++k) merged.push_back(qq[(ia + k) % qq.size()]);
    const size_t n = merged.size(), at_a = pp.size() - 1;
    auto turn = [&](size_t i) {
      return orient2(pts[merged[(i + n - 1) % n]], pts[merged[i]], pts[merged[(i + 1) % n]]);
    };
    if (turn(0) < 0.0 || turn(at_a) < 0.0) continue;
    parent[q] = p;
    polygon[p] = std::move(merged);
    polygon[q].clear();
    kept[d] = 0;
  }
  std::vector<size_t> piece_of_root(triangles.size(), SIZE_MAX);
  for (size_t t = 0; t < triangles.size(); ++t) {
    const size_t r = find(t);
    if (piece_of_root[r] == SIZE_MAX) {
      piece_of_root[r] = out.pieces.size();
      out.pieces.push_back({polygon[r], {}});
    }
    out.pieces[piece_of_root[r]].triangles.push_back(triangles[t]);
  }
  for (size_t d = 0; d < inner.size(); ++d)
    if (kept[d])
      out.diagonals.push_back(
          {inner[d].a, inner[d].b, piece_of_root[find(inner[d].left)], piece_of_root[find(inner[d].right)]});
  // Sides: the piece of the triangle on each outline edge's left.
  for (auto& [side, piece] : out.side_piece) piece = piece_of_root[find(piece)];
}

}  // namespace

double convex_hull_area(std::vector<glm::dvec2> points) {
  std::sort(points.begin(), points.end(),
            [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return 0.0;
  std::vector<glm::dvec2> hull(2 * points.size());
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && orient2(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && orient2(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  double twice = 0.0;
  for (size_t i = 0; i + 1 < k; ++i) twice += hull[i].x * hull[i + 1].y - hull[i + 1].x * hull[i].y;
  return 0.5 * twice;
}

std::string partition_sector(const Map& map, uint16_t sector, SectorPartition& out) {
  std::vector<uint32_t> lines(map.linedefs.size());
  std::iota(lines.begin(), lines.end(), 0u);
  return partition_sector(map, sector, lines, out);
}

std::string partition_sector(const Map& map, uint16_t sector, const std::vector<uint32_t>& lines,
                             SectorPartition& out) {
  out = {};
  std::vector<glm::dvec2> positions;
  std::vector<OutlineEdge> edges;
  if (std::string why = outline_edges(map, sector, lines, positions, edges); !why.empty()) return why;
  if (std::string why = check_simple(positions, edges); !why.empty()) return why;
  if (std::string why = join_at_corners(positions, edges, out.corners); !why.empty()) return why;
  const std::vector<glm::dvec2>& pts = out.corners;
  std::vector<uint32_t> edge_from(pts.size(), 0);
  for (uint32_t e = 0; e < edges.size(); ++e) edge_from[edges[e].from] = e;

  // Loops (each corner is on exactly one), their areas and nesting.
  std::vector<std::vector<uint32_t>> loops;
  std::vector<uint8_t> seen(pts.size(), 0);
  for (uint32_t c = 0; c < pts.size(); ++c) {
    if (seen[c]) continue;
    loops.emplace_back();
    for (uint32_t at = c; !seen[at]; at = edges[edge_from[at]].to) {
      seen[at] = 1;
      loops.back().push_back(at);
    }
  }
  std::vector<double> area2(loops.size());
  for (size_t i = 0; i < loops.size(); ++i) {
    area2[i] = twice_area(pts, loops[i]);
    if (area2[i] == 0.0) return "a loop of its lines has no area";
  }
  // The loop directly around each loop: the smallest that contains the middle of its first edge
  // (loops meet at most at corners, so that point decides; half-integers keep the test exact).
  std::vector<int> around(loops.size(), -1);
  for (size_t i = 0; i < loops.size(); ++i)
    for (size_t j = 0; j < loops.size(); ++j) {
      const glm::dvec2 probe = 0.5 * (pts[loops[i][0]] + pts[loops[i][1]]);
      if (i == j || winding(pts, loops[j], probe) == 0) continue;
      if (around[i] < 0 || std::fabs(area2[j]) < std::fabs(area2[size_t(around[i])])) around[i] = int(j);
    }
  for (size_t i = 0; i < loops.size(); ++i) {
    const bool hole = area2[i] < 0.0;
    if (hole && (around[i] < 0 || area2[size_t(around[i])] < 0.0)) return "a hole of its outline is not inside it";
    if (!hole && around[i] >= 0 && area2[size_t(around[i])] > 0.0) return "an outer loop lies inside another";
  }

  std::vector<std::array<uint32_t, 3>> triangles;
  double total2 = 0.0;
  for (size_t i = 0; i < loops.size(); ++i) {
    if (area2[i] < 0.0) continue;
    std::vector<std::vector<uint32_t>> holes, all = {loops[i]};
    for (size_t j = 0; j < loops.size(); ++j)
      if (around[j] == int(i) && area2[j] < 0.0) holes.push_back(loops[j]), all.push_back(loops[j]);
    std::vector<std::array<uint32_t, 3>> these;
    if (!triangulate_polygon(pts, loops[i], holes, these)) return "its outline could not be triangulated";
    if (!triangulation_covers_outline(pts, all, these)) return "its triangulation failed the exact check";
    triangles.insert(triangles.end(), these.begin(), these.end());
  }
  for (double a : area2) total2 += a;
  out.area = 0.5 * total2;

  // Each outline edge is an edge of exactly one triangle (the certificate): that triangle's piece.
  std::map<std::pair<uint32_t, uint32_t>, size_t> triangle_of;
  for (size_t t = 0; t < triangles.size(); ++t)
    for (size_t k = 0; k < 3; ++k) triangle_of[{triangles[t][k], triangles[t][(k + 1) % 3]}] = t;
  for (const OutlineEdge& e : edges) out.side_piece.emplace_back(e.side, triangle_of.at({e.from, e.to}));
  std::sort(out.side_piece.begin(), out.side_piece.end());
  merge_convex(triangles, out);
  // The merge keeps pieces convex by construction; checked again, exactly, because the cells rely on it.
  for (const SectorPartition::Piece& piece : out.pieces) {
    const size_t n = piece.polygon.size();
    double tiles2 = 0.0;
    for (const auto& t : piece.triangles) tiles2 += orient2(pts[t[0]], pts[t[1]], pts[t[2]]);
    if (tiles2 != twice_area(pts, piece.polygon)) return "a merged piece lost its area";
    for (size_t i = 0; i < n; ++i)
      if (orient2(pts[piece.polygon[(i + n - 1) % n]], pts[piece.polygon[i]], pts[piece.polygon[(i + 1) % n]]) < 0.0)
        return "a merged piece is not convex";
  }
  return {};
}

}  // namespace lintel::doom
