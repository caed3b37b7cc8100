// Portal polygons and links of the rooms importer (see rooms_portal.h). The hull is Andrew's
// monotone chain in the portal's plane; the links follow the loader's orientation probes
// (docs/scene-format.md, "Orientation"), reaching a little further so that a portal set in a
// doorway of a thick wall still finds the rooms on both sides.
#include "rooms/rooms_portal.h"

#include "read/load_context.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace lintel::rooms {
namespace {

constexpr size_t kMaxCorners = 64;  // the scene format's limit

double cross2(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Counter-clockwise hull without collinear points; `eps` is an area below which a turn is straight.
std::vector<size_t> convex_hull_2d(const std::vector<glm::dvec2>& p, double eps) {
  std::vector<size_t> order(p.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return p[a].x < p[b].x || (p[a].x == p[b].x && p[a].y < p[b].y); });
  std::vector<size_t> hull(2 * order.size() + 1);
  size_t k = 0;
  for (size_t i : order) {
    while (k >= 2 && cross2(p[hull[k - 2]], p[hull[k - 1]], p[i]) <= eps) --k;
    hull[k++] = i;
  }
  for (size_t j = order.size() - 1, t = k + 1; j-- > 0;) {
    const size_t i = order[j];
    while (k >= t && cross2(p[hull[k - 2]], p[hull[k - 1]], p[i]) <= eps) --k;
    hull[k++] = i;
  }
  hull.resize(k > 0 ? k - 1 : 0);
  return hull;
}

std::string names_of(const std::vector<int>& rooms, const std::vector<std::string>& names) {
  std::string text;
  for (size_t i = 0; i < rooms.size() && i < 4; ++i)
    text += (i ? ", '" : "'") + scene_read::one_line(names[size_t(rooms[i])], 64) + "'";
  if (rooms.size() > 4) text += ", ...";
  return text;
}

}  // namespace

std::string hull_polygon(const std::vector<glm::dvec3>& points_world, const std::vector<uint32_t>& indices,
                         double rounding_m, HullPolygon& out) {
  out = {};
  out.rounding_m = rounding_m;
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const glm::dvec3& p : points_world) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  out.size = points_world.empty() ? 0.0 : glm::length(hi - lo);
  if (indices.size() < 3) return "has no triangles";
  // The face normal: triangle area vectors summed (right-hand rule). When they cancel (a
  // double-sided portal), the widest triangle gives the plane and the winding is unknown.
  glm::dvec3 area_sum(0.0), widest(0.0);
  double area_total = 0.0;
  for (size_t i = 0; i + 2 < indices.size(); i += 3) {
    const glm::dvec3 a = points_world[indices[i]], b = points_world[indices[i + 1]], c = points_world[indices[i + 2]];
    const glm::dvec3 v = 0.5 * glm::cross(b - a, c - a);
    area_sum += v;
    area_total += glm::length(v);
    if (glm::length(v) > glm::length(widest)) widest = v;
  }
  const double degenerate_area = std::max(1e-6 * out.size * out.size, rounding_m * out.size);
  if (glm::length(widest) <= degenerate_area)
    return "is degenerate (every triangle's area is under " + scene_read::number_text(degenerate_area) + " m^2)";
  out.winding_consistent = glm::length(area_sum) > 0.5 * area_total;
  out.normal = glm::normalize(out.winding_consistent ? area_sum : widest);
  glm::dvec3 mean(0.0);
  for (const glm::dvec3& p : points_world) mean += p;
  mean /= double(points_world.size());
  const double plane_tolerance = std::max(1e-3 * out.size, rounding_m);
  double worst = 0.0;
  for (const glm::dvec3& p : points_world) worst = std::max(worst, std::fabs(glm::dot(p - mean, out.normal)));
  if (worst > plane_tolerance)
    return "is not planar: a vertex is " + scene_read::number_text(worst) + " m from the plane (tolerance " +
           scene_read::number_text(plane_tolerance) + " m)";
  const glm::dvec3 u = glm::normalize(std::fabs(out.normal.x) < 0.9 ? glm::cross(out.normal, glm::dvec3(1, 0, 0))
                                                                    : glm::cross(out.normal, glm::dvec3(0, 1, 0)));
  const glm::dvec3 v = glm::cross(out.normal, u);  // (u, v, normal) right-handed: CCW in 2D is CCW about normal
  std::vector<glm::dvec2> flat;
  flat.reserve(points_world.size());
  for (const glm::dvec3& p : points_world) flat.emplace_back(glm::dot(p - mean, u), glm::dot(p - mean, v));
  const std::vector<size_t> hull =
      convex_hull_2d(flat, std::max(1e-9 * out.size * out.size, rounding_m * out.size * 1e-3));
  double area = 0.0;
  for (size_t i = 0; i < hull.size(); ++i) {
    const glm::dvec2 a = flat[hull[i]], b = flat[hull[(i + 1) % hull.size()]];
    area += 0.5 * (a.x * b.y - a.y * b.x);
  }
  if (hull.size() < 3 || area <= degenerate_area)
    return "is degenerate (its vertices' outline has area " + scene_read::number_text(area) + " m^2)";
  if (hull.size() > kMaxCorners)
    return "has more than 64 corners on its outline (" + std::to_string(hull.size()) + "; the format's limit)";
  for (size_t i : hull) out.corners_world.push_back(mean + u * flat[i].x + v * flat[i].y);
  for (const glm::dvec3& c : out.corners_world) out.centroid += c;
  out.centroid /= double(out.corners_world.size());
  return "";
}

namespace {

// Per room, hits in front minus hits behind (`sides`: -1 behind, +1 in front, or both), and the
// rooms touched (ascending), of the probes link_portal and link_mirror share.
void probe_sides(const HullPolygon& polygon, const std::vector<RoomVolume>& rooms, std::initializer_list<int> sides,
                 std::vector<int>& score, std::vector<int>& touched_out) {
  std::vector<glm::dvec3> samples{polygon.centroid};
  for (const glm::dvec3& c : polygon.corners_world) samples.push_back(polygon.centroid + 0.8 * (c - polygon.centroid));
  const double grow = std::max(1e-5 * polygon.size, polygon.rounding_m);
  // Only rooms whose bounds come within the farthest probe can be touched (keeps a level with
  // thousands of rooms linear in practice).
  const double reach = std::max(kProbeSteps[3] * polygon.size, 2.0 * polygon.rounding_m) + grow;
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const glm::dvec3& c : polygon.corners_world) {
    lo = glm::min(lo, c - reach);
    hi = glm::max(hi, c + reach);
  }
  std::vector<size_t> near;
  for (size_t r = 0; r < rooms.size(); ++r)
    if (glm::all(glm::lessThanEqual(rooms[r].bounds_min, hi)) && glm::all(glm::lessThanEqual(lo, rooms[r].bounds_max)))
      near.push_back(r);
  score.assign(rooms.size(), 0);
  std::set<int> touched;
  for (int side : sides) {
    for (double step : kProbeSteps) {
      const double d = std::max(step * polygon.size, 2.0 * polygon.rounding_m);
      bool any = false;
      for (size_t r : near)
        for (const glm::dvec3& s : samples)
          if (volume_contains(rooms[r], s + double(side) * d * polygon.normal, grow)) {
            score[r] += side;
            touched.insert(int(r));
            any = true;
          }
      if (any) break;
    }
  }
  touched_out.assign(touched.begin(), touched.end());
}

}  // namespace

std::string link_portal(const HullPolygon& polygon, const std::vector<RoomVolume>& rooms,
                        const std::vector<std::string>& room_names, PortalLinkResult& out) {
  out = {};
  std::vector<int> score;
  probe_sides(polygon, rooms, {-1, 1}, score, out.touched);
  if (out.touched.empty())
    return "portal touches no room: no room's volume lies within " +
           scene_read::number_text(kProbeSteps[3] * polygon.size) + " m (0.15 x its size) on either side";
  if (out.touched.size() == 1)
    return "portal touches only one room (" + names_of(out.touched, room_names) + "); it must join two rooms";
  if (out.touched.size() > 2)
    return "portal touches " + std::to_string(out.touched.size()) + " rooms (" + names_of(out.touched, room_names) +
           "); it must join exactly two";
  const int a = out.touched[0], b = out.touched[1];
  if (score[size_t(a)] == score[size_t(b)])
    return "portal cannot tell which of rooms " + names_of(out.touched, room_names) +
           " lies behind it and which in front (do their volumes overlap at the portal?)";
  out.to = score[size_t(a)] > score[size_t(b)] ? a : b;
  out.from = out.to == a ? b : a;
  return "";
}

std::string link_mirror(const HullPolygon& polygon, const std::vector<RoomVolume>& rooms,
                        const std::vector<std::string>& room_names, PortalLinkResult& out) {
  out = {};
  std::vector<int> score;
  probe_sides(polygon, rooms, {1}, score, out.touched);
  if (out.touched.empty())
    return "mirror faces no room: no room's volume lies within " +
           scene_read::number_text(kProbeSteps[3] * polygon.size) +
           " m (0.15 x its size) in front of its face (its face must look into the room it reflects)";
  if (out.touched.size() > 1)
    return "mirror faces " + std::to_string(out.touched.size()) + " rooms (" + names_of(out.touched, room_names) +
           "); it must face exactly one";
  out.from = out.to = out.touched[0];
  return "";
}

}  // namespace lintel::rooms
