// Portal crossings of a moving point (portal_crossing.h). The loop is ViewerTracker::update's,
// kept in one function here so that any number of moving objects share one adjacency; the
// tracker keeps its own copy (viewer_tracker.* belongs to the tracker's owners; see
// docs/visibility.md, "Moving instances").
#include <lintel/portal_crossing.h>

#include <lintel/cell_locate.h>
#include <lintel/doorway_rule.h>

#include <algorithm>
#include <limits>
#include <cassert>

namespace lintel {

void CrossingGraph::build(const World& world) {
  const size_t cells = world.cells.size();
  incident_begin.assign(cells + 1, 0);
  for (const Portal& p : world.portals) {
    if (p.linked()) continue;  // teleports and mirrors are walls for moving objects (docs/visibility.md)
    ++incident_begin[p.from + 1];
    if (p.to != p.from) ++incident_begin[p.to + 1];
  }
  for (size_t c = 0; c < cells; ++c) incident_begin[c + 1] += incident_begin[c];
  incident.assign(incident_begin.back(), 0);
  std::vector<uint32_t> next(incident_begin.begin(), incident_begin.end() - 1);
  for (uint32_t i = 0; i < world.portals.size(); ++i) {
    const Portal& p = world.portals[i];
    if (p.linked()) continue;
    incident[next[p.from]++] = i;
    if (p.to != p.from) incident[next[p.to]++] = i;
  }
  portal_plane.resize(world.portals.size());
  from.resize(world.portals.size());
  for (size_t i = 0; i < world.portals.size(); ++i) {
    portal_plane[i] = glm::dvec4(glm::dvec3(world.portals[i].normal_world), double(world.portals[i].plane_d_world));
    from[i] = world.portals[i].from;
  }
  band_m.resize(world.portals.size());
  max_band_m = 0.0;
  for (size_t i = 0; i < world.portals.size(); ++i) {
    band_m[i] = hysteresis_band_m(world.portals[i]);
    max_band_m = std::max(max_band_m, band_m[i]);
  }
  volumes_m3 = cell_volumes_m3(world);

  plane_begin.assign(1, 0);
  planes.clear();
  std::vector<glm::dvec3> tri;  // world-space triangles of one cell's volume
  for (const Cell& cell : world.cells) {
    tri.clear();
    const glm::dmat4 to_world(cell.cell_to_world);
    auto add = [&](const glm::dvec3& p_cell) { tri.push_back(glm::dvec3(to_world * glm::dvec4(p_cell, 1.0))); };
    if (!cell.volume_triangles_cell.empty()) {
      for (const glm::vec3& v : cell.volume_triangles_cell) add(glm::dvec3(v));
    } else if (!cell.volume_box_cell.empty()) {
      const Aabb& b = cell.volume_box_cell;
      glm::dvec3 c[8];
      for (int i = 0; i < 8; ++i)
        c[i] = {(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z};
      static constexpr int kQuads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
      for (const auto& q : kQuads)
        for (int k : {q[0], q[1], q[2], q[0], q[2], q[3]}) add(c[k]);
    }
    const size_t first = planes.size();
    glm::dvec3 centroid(0.0);
    double scale = 1.0;
    for (const glm::dvec3& v : tri) {
      centroid += v / double(tri.size());
      scale = std::max({scale, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    }
    bool convex = tri.size() >= 12;
    for (size_t i = 0; convex && i + 2 < tri.size(); i += 3) {
      const glm::dvec3 n = glm::cross(tri[i + 1] - tri[i], tri[i + 2] - tri[i]);
      const double length = glm::length(n);
      if (!(length > 1e-12 * scale * scale)) continue;  // degenerate: no plane
      glm::dvec4 plane(n / length, 0.0);
      plane.w = -glm::dot(glm::dvec3(plane), tri[i]);
      if (glm::dot(glm::dvec3(plane), centroid) + plane.w > 0.0) plane = -plane;  // outward
      for (const glm::dvec3& v : tri)
        if (glm::dot(glm::dvec3(plane), v) + plane.w > 1e-6 * scale) convex = false;
      planes.push_back(plane);
    }
    if (!convex) planes.resize(first);
    plane_begin.push_back(uint32_t(planes.size()));
  }
}

bool CrossingGraph::surely_inside(uint32_t cell, const glm::dvec3& p) const {
  const uint32_t begin = plane_begin[cell], end = plane_begin[cell + 1];
  if (begin == end) return false;
  for (uint32_t k = begin; k < end; ++k)
    if (glm::dot(glm::dvec3(planes[k]), p) + planes[k].w > 0.0) return false;
  return true;
}

double CrossingGraph::inside_clearance(uint32_t cell, const glm::dvec3& p) const {
  const uint32_t begin = plane_begin[cell], end = plane_begin[cell + 1];
  if (begin == end) return std::numeric_limits<double>::quiet_NaN();
  double clearance = std::numeric_limits<double>::infinity();
  for (uint32_t k = begin; k < end; ++k)
    clearance = std::min(clearance, -(glm::dot(glm::dvec3(planes[k]), p) + planes[k].w));
  return clearance;
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
      // portal_signed_distance, from the compact copy of the plane (the same operations).
      const glm::dvec3 n(graph.portal_plane[pi]);
      const double sign = graph.from[pi] == cell ? 1.0 : -1.0;
      const double s0 = sign * (glm::dot(n, p0) - graph.portal_plane[pi].w);
      const double s1 = sign * (glm::dot(n, p1) - graph.portal_plane[pi].w);
      const double band = graph.band_m[pi];
      if (!(s0 <= band && s1 > band)) continue;
      const double t = (band - s0) / (s1 - s0);
      if (t < t_done || t >= best_t) continue;
      if (!projects_inside_portal(world.portals[pi], p0 + (p1 - p0) * t, 1e-6)) continue;
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
