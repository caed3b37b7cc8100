// The "doorway" timeline of an imported map: from the player 1 start, greedily through the
// nearest open line into a sector not yet visited (else any line not yet crossed), so that the
// walk crosses many portals. Every straight stretch is checked against all lines: between two
// crossings the eye crosses no line at all, and through a crossing only that line, so the walk
// never passes through a wall even in non-convex sectors.
#include "doom_level.h"
#include "walk_timeline.h"

#include <algorithm>
#include <cmath>

namespace lintel::doom {
namespace {

constexpr double kApproachUnits = 12.0;  // waypoints this far before and after a line's midpoint
constexpr double kMinSpanUnits = 32.0;   // an opening the eye can pass
constexpr double kHeadroomUnits = 8.0;   // eye kept this far inside the opening's span

double orient(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Closed segments p-q and a-b share a point (touching counts).
bool segments_meet(const glm::dvec2& p, const glm::dvec2& q, const glm::dvec2& a, const glm::dvec2& b) {
  const double d1 = orient(a, b, p), d2 = orient(a, b, q), d3 = orient(p, q, a), d4 = orient(p, q, b);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  auto on = [](const glm::dvec2& s0, const glm::dvec2& s1, const glm::dvec2& r, double d) {
    return d == 0.0 && std::min(s0.x, s1.x) <= r.x && r.x <= std::max(s0.x, s1.x) && std::min(s0.y, s1.y) <= r.y &&
           r.y <= std::max(s0.y, s1.y);
  };
  return on(a, b, p, d1) || on(a, b, q, d2) || on(p, q, a, d3) || on(p, q, b, d4);
}

bool crosses_any_line(const Map& m, const glm::dvec2& p, const glm::dvec2& q, size_t except) {
  for (size_t l = 0; l < m.linedefs.size(); ++l)
    if (l != except && segments_meet(p, q, m.vertices[m.linedefs[l].v1], m.vertices[m.linedefs[l].v2])) return true;
  return false;
}

int sector_at(const Level& level, const glm::dvec2& p) {
  const Map& m = level.map;
  return m.seg_sector(m.segs[m.subsectors[subsector_at(m, p)].first_seg]);
}

}  // namespace

void add_doorway_walk(const Level& level, uint32_t crossings, SceneDesc& scene, DoomImportStats& stats) {
  const Map& m = level.map;
  glm::dvec2 p(0.0);
  bool found = false;
  for (const Thing& t : m.things)
    if (t.type == 1 && level.cell_node[size_t(sector_at(level, t.position))] >= 0) {
      p = t.position;
      found = true;
      break;
    }
  if (!found) {  // no usable start: the centroid of the first cell's first piece
    for (size_t s = 0; s < m.sectors.size() && !found; ++s)
      if (level.cell_node[s] >= 0) p = polygon_centroid(level.pieces[level.pieces_of_sector[s][0]].polygon), found = true;
  }
  int sector = sector_at(level, p);
  auto eye_height = [&](int s) { return level.floor[size_t(s)] + std::min(kEyeUnits, 0.5 * (level.ceiling[size_t(s)] - level.floor[size_t(s)])); };
  std::vector<glm::dvec3> waypoints{glm::dvec3(to_world(p, eye_height(sector)))};
  std::vector<uint8_t> visited(m.sectors.size(), 0), used(m.linedefs.size(), 0);
  visited[size_t(sector)] = 1;
  for (uint32_t step = 0; step < crossings; ++step) {
    double best_score = INFINITY;
    size_t best_line = 0;
    int best_target = -1;
    glm::dvec2 best_in(0.0), best_out(0.0);
    for (size_t l = 0; l < m.linedefs.size(); ++l) {
      const Linedef& line = m.linedefs[l];
      const int f = side_cell_sector(level, line.front), k = side_cell_sector(level, line.back);
      if (used[l] || f < 0 || k < 0 || f == k || (f != sector && k != sector)) continue;
      const int target = f == sector ? k : f;
      const double lo = std::max(level.floor[size_t(f)], level.floor[size_t(k)]);
      const double hi = std::min(level.ceiling[size_t(f)], level.ceiling[size_t(k)]);
      if (hi - lo < kMinSpanUnits) continue;
      const glm::dvec2 a = m.vertices[line.v1], b = m.vertices[line.v2];
      const glm::dvec2 mid = 0.5 * (a + b);
      glm::dvec2 into_target = glm::normalize(glm::dvec2(b.y - a.y, a.x - b.x));  // into the front
      if (target == k) into_target = -into_target;
      const glm::dvec2 in = mid - kApproachUnits * into_target, out = mid + kApproachUnits * into_target;
      const double score = glm::length(in - p) + (visited[size_t(target)] ? 1e6 : 0.0);
      if (score >= best_score) continue;
      if (sector_at(level, in) != sector || sector_at(level, out) != target) continue;
      if (crosses_any_line(m, p, in, m.linedefs.size()) || crosses_any_line(m, in, out, l)) continue;
      best_score = score, best_line = l, best_target = target, best_in = in, best_out = out;
    }
    if (best_target < 0) break;
    const Linedef& line = m.linedefs[best_line];
    const int f = side_cell_sector(level, line.front), k = side_cell_sector(level, line.back);
    const double lo = std::max(level.floor[size_t(f)], level.floor[size_t(k)]) + kHeadroomUnits;
    const double hi = std::min(level.ceiling[size_t(f)], level.ceiling[size_t(k)]) - kHeadroomUnits;
    waypoints.emplace_back(to_world(best_in, std::clamp(eye_height(sector), lo, hi)));
    waypoints.emplace_back(to_world(best_out, std::clamp(eye_height(best_target), lo, hi)));
    used[best_line] = 1;
    visited[size_t(best_target)] = 1;
    sector = best_target;
    p = best_out;
    ++stats.walk_crossings;
  }
  if (waypoints.size() == 1) waypoints.push_back(waypoints[0] + glm::dvec3(0.01, 0.0, 0.0));
  scene.timelines.push_back(gen::walk_timeline("doorway", 60.0, waypoints));
}

}  // namespace lintel::doom
