// Portal crossings of a moving point (portal_crossing.h). The loop is ViewerTracker::update's,
// kept in one function here so that any number of moving objects share one adjacency; the
// tracker keeps its own copy (viewer_tracker.* belongs to the tracker's owners; see
// docs/visibility.md, "Moving instances").
#include <lintel/portal_crossing.h>

#include <lintel/cell_locate.h>
#include <lintel/doorway_rule.h>

#include <algorithm>
#include <cassert>

namespace lintel {

void CrossingGraph::build(const World& world) {
  const size_t cells = world.cells.size();
  incident_begin.assign(cells + 1, 0);
  for (const Portal& p : world.portals) {
    ++incident_begin[p.from + 1];
    if (p.to != p.from) ++incident_begin[p.to + 1];
  }
  for (size_t c = 0; c < cells; ++c) incident_begin[c + 1] += incident_begin[c];
  incident.assign(incident_begin.back(), 0);
  std::vector<uint32_t> next(incident_begin.begin(), incident_begin.end() - 1);
  for (uint32_t i = 0; i < world.portals.size(); ++i) {
    const Portal& p = world.portals[i];
    incident[next[p.from]++] = i;
    if (p.to != p.from) incident[next[p.to]++] = i;
  }
  band_m.resize(world.portals.size());
  max_band_m = 0.0;
  for (size_t i = 0; i < world.portals.size(); ++i) {
    band_m[i] = hysteresis_band_m(world.portals[i]);
    max_band_m = std::max(max_band_m, band_m[i]);
  }
  volumes_m3 = cell_volumes_m3(world);
}

uint32_t follow_portal_crossings(const World& world, const CrossingGraph& graph, uint32_t cell, const glm::dvec3& p0,
                                 const glm::dvec3& p1, uint32_t max_crossings, std::vector<uint32_t>* crossed) {
  assert(cell + 1 < graph.incident_begin.size());
  double t_done = 0.0;
  uint32_t last_portal = kNoCell;
  for (uint32_t step = 0; step < max_crossings; ++step) {
    uint32_t best_portal = kNoCell;
    double best_t = 2.0;
    for (uint32_t k = graph.incident_begin[cell]; k < graph.incident_begin[cell + 1]; ++k) {
      const uint32_t pi = graph.incident[k];
      if (pi == last_portal) continue;
      const Portal& portal = world.portals[pi];
      const double band = graph.band_m[pi];
      const double s0 = portal_signed_distance(portal, cell, p0);
      const double s1 = portal_signed_distance(portal, cell, p1);
      if (!(s0 <= band && s1 > band)) continue;
      const double t = (band - s0) / (s1 - s0);
      if (t < t_done || t >= best_t) continue;
      if (!projects_inside_portal(portal, p0 + (p1 - p0) * t, 1e-6)) continue;
      best_t = t;
      best_portal = pi;
    }
    if (best_portal == kNoCell) break;
    const Portal& p = world.portals[best_portal];
    cell = cell == p.from ? p.to : p.from;
    if (crossed) crossed->push_back(best_portal);
    t_done = best_t;
    last_portal = best_portal;
  }
  return cell;
}

}  // namespace lintel
