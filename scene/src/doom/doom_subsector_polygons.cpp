// Subsector polygons by half-plane clipping (Sutherland-Hodgman against one line at a time) down
// the BSP. Doom's side test: a point is on the right (front, child 0) of a line through o along d
// when cross(d, p - o) < 0.
#include "doom/doom_subsector_polygons.h"

#include <algorithm>
#include <cmath>

namespace lintel::doom {
namespace {

constexpr double kMinPieceArea = 1e-3;  // map units^2: slivers from nearly parallel partitions
constexpr double kBoxMargin = 64.0;     // map units around the vertices' bounding box

double side_of(const glm::dvec2& o, const glm::dvec2& d, const glm::dvec2& p) {
  return d.x * (p.y - o.y) - d.y * (p.x - o.x);  // < 0: right (front)
}

// Keeps the part of `poly` on the right of the line (keep_right) or on its left.
std::vector<glm::dvec2> clip(const std::vector<glm::dvec2>& poly, const glm::dvec2& o, const glm::dvec2& d,
                             bool keep_right) {
  std::vector<glm::dvec2> out;
  const size_t n = poly.size();
  const double scale = glm::length(d);
  for (size_t i = 0; i < n; ++i) {
    const glm::dvec2& a = poly[i];
    const glm::dvec2& b = poly[(i + 1) % n];
    double sa = side_of(o, d, a) / scale, sb = side_of(o, d, b) / scale;
    if (!keep_right) sa = -sa, sb = -sb;
    if (sa <= 0.0) out.push_back(a);
    if ((sa < 0.0 && sb > 0.0) || (sa > 0.0 && sb < 0.0)) out.push_back(a + (b - a) * (sa / (sa - sb)));
  }
  return out;
}

void descend(const Map& map, uint16_t child, std::vector<glm::dvec2> poly, std::vector<FloorPiece>& out) {
  if (poly.size() < 3) return;
  if (child & kSubsectorBit) {
    const Subsector& sub = map.subsectors[child & ~kSubsectorBit];
    for (uint32_t s = 0; s < sub.seg_count && poly.size() >= 3; ++s) {
      const Seg& seg = map.segs[sub.first_seg + s];
      const glm::dvec2 a = map.vertices[seg.v1], b = map.vertices[seg.v2];
      if (a != b) poly = clip(poly, a, b - a, true);
    }
    if (poly.size() >= 3 && polygon_area(poly) > kMinPieceArea)
      out.push_back({std::move(poly), map.seg_sector(map.segs[sub.first_seg])});
    return;
  }
  const Node& node = map.nodes[child];
  descend(map, node.child[0], clip(poly, node.origin, node.direction, true), out);
  descend(map, node.child[1], clip(poly, node.origin, node.direction, false), out);
}

}  // namespace

double polygon_area(const std::vector<glm::dvec2>& polygon) {
  double twice = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec2& a = polygon[i];
    const glm::dvec2& b = polygon[(i + 1) % polygon.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * twice;
}

glm::dvec2 polygon_centroid(const std::vector<glm::dvec2>& polygon) {
  glm::dvec2 sum(0.0);
  double area = 0.0;
  for (size_t i = 1; i + 1 < polygon.size(); ++i) {
    const double a = 0.5 * ((polygon[i].x - polygon[0].x) * (polygon[i + 1].y - polygon[0].y) -
                            (polygon[i + 1].x - polygon[0].x) * (polygon[i].y - polygon[0].y));
    sum += a * (polygon[0] + polygon[i] + polygon[i + 1]) / 3.0;
    area += a;
  }
  return area != 0.0 ? sum / area : polygon[0];
}

std::vector<FloorPiece> subsector_polygons(const Map& map) {
  glm::dvec2 lo(INFINITY), hi(-INFINITY);
  for (const glm::dvec2& v : map.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
  lo -= kBoxMargin;
  hi += kBoxMargin;
  // Counter-clockwise in (x, y): clipping keeps the winding.
  const std::vector<glm::dvec2> box = {{lo.x, lo.y}, {hi.x, lo.y}, {hi.x, hi.y}, {lo.x, hi.y}};
  std::vector<FloorPiece> out;
  if (map.nodes.empty()) {
    descend(map, kSubsectorBit, box, out);
  } else {
    descend(map, uint16_t(map.nodes.size() - 1), box, out);
  }
  return out;
}

uint16_t subsector_at(const Map& map, const glm::dvec2& p) {
  if (map.nodes.empty()) return 0;
  uint16_t child = uint16_t(map.nodes.size() - 1);
  while (!(child & kSubsectorBit)) {
    const Node& node = map.nodes[child];
    child = node.child[side_of(node.origin, node.direction, p) < 0.0 ? 0 : 1];
  }
  return uint16_t(child & ~kSubsectorBit);
}

}  // namespace lintel::doom
