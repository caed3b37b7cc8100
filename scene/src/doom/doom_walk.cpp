// The "doorway" timeline of an imported map: from the player 1 start, greedily through the
// nearest open line into a sector not yet visited (else a line not yet crossed, else back), so that the
// walk crosses many portals. Inside a sector the route runs between its pieces' centroids
// (shortest path on their visibility graph), which gets round corners of non-convex sectors. Every straight stretch is checked against all lines: between two
// crossings the eye crosses no line at all, and through a crossing only that line, so the walk
// never passes through a wall even in non-convex sectors.
// Teleporter lines the player walks over (docs/levels.md, "Timeline `doorway`") are candidates
// like open lines: crossed from their front side they move the eye to the destination thing, a
// jump in the timeline (gen::walk_timeline's runs) that no frame samples between the two places.
#include "doom/doom_level.h"
#include "generate/walk_timeline.h"

#include <algorithm>
#include <cmath>

namespace lintel::doom {
namespace {

constexpr double kApproachUnits =
    12.0;  // waypoints this far (or 1/2, 1/4, 1/8 of it) before and after a line's midpoint
constexpr double kMinSpanUnits = 32.0;  // an opening the eye can pass
constexpr double kHeadroomUnits = 8.0;  // eye kept this far inside the opening's span
// Crossings in a row back into visited sectors chosen by distance (out of a dead end); past them
// the walk heads for the nearest sector that still leads somewhere new (route_towards_unvisited).
constexpr uint32_t kMaxCrossingsWithoutNewSector = 4;
constexpr double kEdgeStationUnits = 8.0;      // a route's extra station: this far inside a piece's edge
constexpr double kBoundaryClearUnits = 6.0;    // and at least this far from a cell boundary
constexpr uint16_t kTeleportDestination = 14;  // thing type
constexpr uint16_t kMultiplayerOnly = 0x10;    // thing flag: not spawned in a single-player game

// Teleporters a player triggers by walking over the line from its front side: Doom's 39 (W1) and
// 97 (WR), Boom's silent 207 (W1) and 208 (WR), which go to the same destination thing. 125 and
// 126 teleport monsters only: to the player they are plain lines.
bool player_teleport(uint16_t special) { return special == 39 || special == 97 || special == 207 || special == 208; }
bool once_only(uint16_t special) { return special == 39 || special == 207; }

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

// Lines with one sector on both sides (decoration) do not count: crossing them changes nothing.
bool crosses_any_line(const Map& m, const glm::dvec2& p, const glm::dvec2& q, size_t except) {
  for (size_t l = 0; l < m.linedefs.size(); ++l) {
    const Linedef& line = m.linedefs[l];
    if (l == except || (line.back != kNoSide && m.sidedefs[line.back].sector == m.sidedefs[line.front].sector))
      continue;
    if (segments_meet(p, q, m.vertices[line.v1], m.vertices[line.v2])) return true;
  }
  return false;
}

int sector_at(const Level& level, const glm::dvec2& p) {
  const Map& m = level.map;
  return m.seg_sector(m.segs[m.subsectors[subsector_at(m, p)].first_seg]);
}

// Shortest route from stations[0] to every station over straight stretches that cross no line
// (Dijkstra on the visibility graph of the stations). prev[i] = the station before i, or -1.
std::vector<int> routes_from_first(const Map& m, const std::vector<glm::dvec2>& stations, std::vector<double>& dist) {
  const size_t n = stations.size();
  dist.assign(n, INFINITY);
  std::vector<int> prev(n, -1);
  std::vector<uint8_t> done(n, 0);
  dist[0] = 0.0;
  for (size_t round = 0; round < n; ++round) {
    size_t u = n;
    for (size_t i = 0; i < n; ++i)
      if (!done[i] && std::isfinite(dist[i]) && (u == n || dist[i] < dist[u])) u = i;
    if (u == n) break;
    done[u] = 1;
    for (size_t v = 0; v < n; ++v) {
      if (done[v]) continue;
      const double d = dist[u] + glm::length(stations[v] - stations[u]);
      if (d >= dist[v] || crosses_any_line(m, stations[u], stations[v], m.linedefs.size())) continue;
      dist[v] = d;
      prev[v] = int(u);
    }
  }
  return prev;
}

// Two consecutive keys of a jump: the eye moves far faster than a walk between them.
bool is_jump(const TimelineKey& a, const TimelineKey& b) {
  return glm::length(glm::dvec3(b.eye_world - a.eye_world)) > 2.0 * gen::kWalkSpeed * (b.t - a.t) + 1e-3;
}

// Backing out of a dead end turns the view around between two keys; interpolated linearly, the
// target would pass through the eye (an undefined view). A key halfway, looking at right angles,
// splits every turn of more than 90 degrees into two of at most 90.
void split_sharp_turns(Timeline& timeline) {
  std::vector<TimelineKey> keys{timeline.keys.front()};
  for (size_t i = 1; i < timeline.keys.size(); ++i) {
    const TimelineKey& a = keys.back();
    const TimelineKey& b = timeline.keys[i];
    const glm::dvec3 d0 = glm::normalize(glm::dvec3(a.target_world - a.eye_world));
    const glm::dvec3 d1 = glm::normalize(glm::dvec3(b.target_world - b.eye_world));
    const double t_mid = std::round(0.5 * (a.t + b.t) * 1000.0) / 1000.0;
    // Never across a jump: its keys are 1 ms apart and no eye between them may exist.
    if (glm::dot(d0, d1) < 0.0 && t_mid > a.t && t_mid < b.t && !is_jump(a, b)) {
      // Horizontal, at right angles to d0's heading, towards d1's (never vertical: up is +Y).
      const glm::dvec3 h0 = glm::normalize(glm::dvec3(d0.x, 0.0, d0.z)), h1 = glm::dvec3(d1.x, 0.0, d1.z);
      glm::dvec3 side = h1 - glm::dot(h1, h0) * h0;
      if (glm::length(side) < 1e-3) side = glm::dvec3(-h0.z, 0.0, h0.x);
      const glm::dvec3 eye = 0.5 * (glm::dvec3(a.eye_world) + glm::dvec3(b.eye_world));
      const double look = glm::length(glm::dvec3(a.target_world - a.eye_world));
      keys.push_back({t_mid, glm::vec3(eye), glm::vec3(eye + look * glm::normalize(side))});
    }
    keys.push_back(b);
  }
  timeline.keys = std::move(keys);
}

// Doom's EV_Teleport: the first sector (by index) tagged like the line that holds a teleport
// destination (the BSP's sector under the thing), and in it the first such thing (in thing order).
// Things only multiplayer games spawn do not count. Tag 0 teleports nowhere here (vanilla would
// search the untagged sectors). nullptr: the line teleports nowhere (Doom then lets it be crossed).
const Thing* teleport_destination(const Level& level, const Linedef& line) {
  const Map& m = level.map;
  if (line.tag == 0) return nullptr;
  for (size_t s = 0; s < m.sectors.size(); ++s) {
    if (m.sectors[s].tag != line.tag) continue;
    for (const Thing& t : m.things)
      if (t.type == kTeleportDestination && !(t.flags & kMultiplayerOnly) && sector_at(level, t.position) == int(s))
        return &t;
  }
  return nullptr;
}

// A point where the walk may stand in `sector` near p: p itself, or when p lies on a line (a
// start or a teleport destination can; every stretch from it would touch that line) the nearest
// centroid of the sector's pieces.
glm::dvec2 off_lines(const Level& level, int sector, const glm::dvec2& p) {
  const Map& m = level.map;
  if (!crosses_any_line(m, p, p, m.linedefs.size())) return p;
  glm::dvec2 nearest = p;
  double best = INFINITY;
  for (size_t piece : level.pieces_of_sector[size_t(sector)]) {
    const glm::dvec2 c = polygon_centroid(level.pieces[piece].polygon);
    if (glm::length(c - p) < best) best = glm::length(c - p), nearest = c;
  }
  return nearest;
}

// Whether `p` keeps kBoundaryClearUnits from every boundary between two cells: the cuts between a
// split sector's cells and the lines with a different sector on each side.
bool clear_of_cell_boundaries(const Level& level, const glm::dvec2& p) {
  auto near = [&](const glm::dvec2& a, const glm::dvec2& b) {
    const glm::dvec2 u = b - a;
    const double len2 = glm::dot(u, u);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, u) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * u)) < kBoundaryClearUnits;
  };
  for (const auto& [a, b] : level.cuts)
    if (near(a, b)) return false;
  const Map& m = level.map;
  for (const Linedef& line : m.linedefs)
    if (line.back != kNoSide && m.sidedefs[line.back].sector != m.sidedefs[line.front].sector &&
        near(m.vertices[line.v1], m.vertices[line.v2]))
      return false;
  return true;
}

// Stations just inside the edges of `sector`'s pieces (a route between two pieces passes through
// the edge they share), those clear of every cell boundary (a turn next to a cut or a portal line
// would cross it and back within a few frames: a flap).
void add_edge_stations(const Level& level, int sector, std::vector<glm::dvec2>& stations) {
  for (size_t piece : level.pieces_of_sector[size_t(sector)]) {
    const std::vector<glm::dvec2>& poly = level.pieces[piece].polygon;
    const glm::dvec2 centre = polygon_centroid(poly);
    for (size_t i = 0; i < poly.size(); ++i) {
      const glm::dvec2 mid = 0.5 * (poly[i] + poly[(i + 1) % poly.size()]);
      const glm::dvec2 inward = centre - mid;
      const double length = glm::length(inward);
      if (!(length > 2.0)) continue;
      const glm::dvec2 station = mid + inward * (std::min(kEdgeStationUnits, 0.5 * length) / length);
      if (clear_of_cell_boundaries(level, station)) stations.push_back(station);
    }
  }
}

// The height both sectors leave open over a line between them (map units; negative: none).
double open_span(const Level& level, int f, int k) {
  return double(std::min(level.ceiling[size_t(f)], level.ceiling[size_t(k)])) -
         double(std::max(level.floor[size_t(f)], level.floor[size_t(k)]));
}

// The sectors the walk can cross into from each sector: through a line with cells on both sides
// and an opening the eye passes (teleporters aside), either way.
std::vector<std::vector<int>> walkable_neighbours(const Level& level) {
  const Map& m = level.map;
  std::vector<std::vector<int>> out(m.sectors.size());
  for (const Linedef& line : m.linedefs) {
    const int f = side_cell_sector(level, line.front), k = side_cell_sector(level, line.back);
    if (f < 0 || k < 0 || f == k || open_span(level, f, k) < kMinSpanUnits) continue;
    out[size_t(f)].push_back(k);
    out[size_t(k)].push_back(f);
  }
  return out;
}

// The first sector on a route of fewest crossings from `from` to the nearest other sector that
// borders an unvisited one; -1 when no unvisited sector can be reached. Backing out of a dead end
// by distance alone stops after a few crossings in a long corridor of visited sectors; this
// finds the way out whatever its length (the walk's crossing budget still bounds it).
int route_towards_unvisited(const std::vector<std::vector<int>>& neighbours, int from,
                            const std::vector<uint8_t>& visited) {
  std::vector<int> parent(neighbours.size(), -2);
  std::vector<int> queue{from};
  parent[size_t(from)] = -1;
  for (size_t head = 0; head < queue.size(); ++head) {
    const int s = queue[head];
    const bool leads_on = std::any_of(neighbours[size_t(s)].begin(), neighbours[size_t(s)].end(),
                                      [&](int n) { return !visited[size_t(n)]; });
    if (s != from && leads_on) {
      int hop = s;
      while (parent[size_t(hop)] != from) hop = parent[size_t(hop)];
      return hop;
    }
    for (int n : neighbours[size_t(s)])
      if (parent[size_t(n)] == -2 && visited[size_t(n)]) parent[size_t(n)] = s, queue.push_back(n);
  }
  return -1;
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
      if (level.cell_node[s] >= 0)
        p = polygon_centroid(level.pieces[level.pieces_of_sector[s][0]].polygon), found = true;
  }
  int sector = sector_at(level, p);
  p = off_lines(level, sector, p);  // Freedoom's E1M5 starts on a line
  auto eye_height = [&](int s) {
    return level.floor[size_t(s)] + std::min(kEyeUnits, 0.5 * (level.ceiling[size_t(s)] - level.floor[size_t(s)]));
  };
  // Runs of waypoints; a teleport starts the next run (a jump).
  std::vector<std::vector<glm::dvec3>> runs{{glm::dvec3(to_world(p, eye_height(sector)))}};
  std::vector<uint8_t> visited(m.sectors.size(), 0), used(m.linedefs.size(), 0);
  visited[size_t(sector)] = 1;
  // Each line's teleport destination (nullptr: none, or not a player teleporter).
  std::vector<const Thing*> destination(m.linedefs.size(), nullptr);
  for (size_t l = 0; l < m.linedefs.size(); ++l)
    if (player_teleport(m.linedefs[l].special)) destination[l] = teleport_destination(level, m.linedefs[l]);
  // Crossing line l from its front teleports (a W1 teleporter is spent once crossed either way,
  // as vanilla Doom clears its special).
  auto teleports = [&](size_t l) {
    return destination[l] != nullptr && !(once_only(m.linedefs[l].special) && used[l]);
  };
  struct Candidate {
    size_t line;
    int target;  // the sector the eye ends in (a teleport's: the destination's)
    glm::dvec2 in, out;
    int through = -1;  // a teleport: the sector behind the line, where `out` lies
    glm::dvec2 landing{0.0};
  };
  uint32_t since_new_sector = 0;
  const std::vector<std::vector<int>> neighbours = walkable_neighbours(level);
  for (uint32_t step = 0; step < crossings; ++step) {
    // Stations of this sector: the eye, its pieces' centroids (to get round corners) and the
    // approach point of every line that leads on.
    std::vector<glm::dvec2> stations{p};
    for (size_t piece : level.pieces_of_sector[size_t(sector)])
      stations.push_back(polygon_centroid(level.pieces[piece].polygon));
    const size_t first_candidate = stations.size();
    std::vector<Candidate> candidates;
    for (size_t l = 0; l < m.linedefs.size(); ++l) {
      const Linedef& line = m.linedefs[l];
      const int f = side_cell_sector(level, line.front), k = side_cell_sector(level, line.back);
      const bool teleport = teleports(l) && f == sector;  // walked over from the front
      if (f < 0 || k < 0 || (f == k && !teleport) || (f != sector && k != sector)) continue;
      int target = f == sector ? k : f;
      glm::dvec2 landing(0.0);
      if (teleport) {  // to the destination, which must stand in a cell
        landing = destination[l]->position;
        target = sector_at(level, landing);
        if (level.cell_node[size_t(target)] < 0) continue;
        landing = off_lines(level, target, landing);
      }
      if (open_span(level, f, k) < kMinSpanUnits) continue;
      const glm::dvec2 a = m.vertices[line.v1], b = m.vertices[line.v2];
      const glm::dvec2 mid = 0.5 * (a + b);
      glm::dvec2 into_target = glm::normalize(glm::dvec2(b.y - a.y, a.x - b.x));  // into the front
      if (teleport || target == k) into_target = -into_target;
      const int beyond = teleport ? k : target;  // the sector just past the line
      // Thin sectors (a door is often 8 units deep): the first offset that lands on both sides.
      for (double offset : {kApproachUnits, 0.5 * kApproachUnits, 0.25 * kApproachUnits, 0.125 * kApproachUnits}) {
        const glm::dvec2 in = mid - offset * into_target, out = mid + offset * into_target;
        if (sector_at(level, in) != sector || sector_at(level, out) != beyond) continue;
        if (crosses_any_line(m, in, out, l)) continue;
        candidates.push_back({l, target, in, out, teleport ? k : -1, landing});
        stations.push_back(in);
        break;
      }
    }
    if (candidates.empty()) break;
    std::vector<double> dist;
    std::vector<int> prev = routes_from_first(m, stations, dist);
    // Piece centroids alone may not connect the eye to an exit round a corner of an odd-shaped
    // sector (freedoom2 MAP17's walk stopped after 7 crossings so): when no way into a new sector
    // is reachable, or later no way towards one, the edge stations join in (add_edge_stations).
    auto reaches_new = [&] {
      for (size_t c = 0; c < candidates.size(); ++c)
        if (!visited[size_t(candidates[c].target)] && std::isfinite(dist[first_candidate + c])) return true;
      return false;
    };
    const bool some_new = std::any_of(candidates.begin(), candidates.end(),
                                      [&](const Candidate& c) { return !visited[size_t(c.target)]; });
    bool edge_stations = false;
    auto with_edge_stations = [&] {
      if (edge_stations) return;
      edge_stations = true;
      add_edge_stations(level, sector, stations);
      prev = routes_from_first(m, stations, dist);
    };
    if (some_new && !reaches_new()) with_edge_stations();
    size_t best = candidates.size();
    double best_score = INFINITY;
    for (size_t c = 0; c < candidates.size(); ++c) {
      const double d = dist[first_candidate + c];
      // New sectors first, then lines not yet crossed, then back the way we came (dead ends).
      const double score =
          d + (visited[size_t(candidates[c].target)] ? 1e6 : 0.0) + (used[candidates[c].line] ? 2e6 : 0.0);
      if (std::isfinite(d) && score < best_score) best_score = score, best = c;
    }
    if (best == candidates.size()) break;
    since_new_sector = visited[size_t(candidates[best].target)] ? since_new_sector + 1 : 0;
    if (since_new_sector > kMaxCrossingsWithoutNewSector) {
      // Out of the dead end by the shortest way to a sector that leads somewhere new.
      const int hop = route_towards_unvisited(neighbours, sector, visited);
      auto best_towards_hop = [&] {
        size_t pick = candidates.size();
        for (size_t c = 0; c < candidates.size(); ++c)
          if (candidates[c].target == hop && candidates[c].through < 0 && std::isfinite(dist[first_candidate + c]) &&
              (pick == candidates.size() || dist[first_candidate + c] < dist[first_candidate + pick]))
            pick = c;
        return pick;
      };
      best = best_towards_hop();
      if (best == candidates.size() && hop >= 0) {  // the way there may lie round a corner too
        with_edge_stations();
        best = best_towards_hop();
      }
      if (best == candidates.size()) break;
    }
    const Candidate& chosen = candidates[best];
    std::vector<size_t> route;  // stations after the eye, up to the approach point
    for (int i = int(first_candidate + best); i > 0; i = prev[size_t(i)]) route.push_back(size_t(i));
    const Linedef& line = m.linedefs[chosen.line];
    const int f = side_cell_sector(level, line.front), k = side_cell_sector(level, line.back);
    const double lo = std::max(level.floor[size_t(f)], level.floor[size_t(k)]) + kHeadroomUnits;
    const double hi = std::min(level.ceiling[size_t(f)], level.ceiling[size_t(k)]) - kHeadroomUnits;
    const bool teleport = chosen.through >= 0;
    std::vector<glm::dvec3>& run = runs.back();
    for (size_t i = route.size(); i-- > 1;) run.emplace_back(to_world(stations[route[i]], eye_height(sector)));
    run.emplace_back(to_world(chosen.in, std::clamp(eye_height(sector), lo, hi)));
    run.emplace_back(to_world(chosen.out, std::clamp(eye_height(teleport ? chosen.through : chosen.target), lo, hi)));
    used[chosen.line] = 1;
    visited[size_t(chosen.target)] = 1;
    sector = chosen.target;
    if (teleport) {  // over the line, then at once at the destination: a new run
      p = chosen.landing;
      runs.push_back({glm::dvec3(to_world(p, eye_height(sector)))});
      ++stats.walk_teleports;
    } else {
      p = chosen.out;
      ++stats.walk_crossings;
    }
  }
  if (runs.size() == 1 && runs[0].size() == 1) runs[0].push_back(runs[0][0] + glm::dvec3(0.01, 0.0, 0.0));
  Timeline walk = gen::walk_timeline("doorway", 60.0, runs);
  split_sharp_turns(walk);
  scene.timelines.push_back(std::move(walk));
}

}  // namespace lintel::doom
