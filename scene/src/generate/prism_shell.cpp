// Shells of rooms with a convex polygonal footprint (the ring's wedges): each wall is a panel in
// its own (a along the wall, y) coordinates; all walls share one height split list and the floor
// and ceiling are fans through the walls' bottom and top vertices, so the shell stays watertight.
#include "generate/room_shell.h"

#include <cassert>
#include <cmath>

namespace lintel::gen {
namespace {

glm::dvec2 left_normal(const glm::dvec2& d) { return {-d.y, d.x}; }  // inward for counter-clockwise

struct Wall {
  glm::dvec2 start, dir, inward;  // mid-plane line: start + a * dir
  double a_begin = 0, a_end = 0;  // where the face (offset inwards) meets its neighbours
  glm::dvec2 corner_begin, corner_end;
  std::vector<PanelHole> holes;
  std::vector<double> a_splits;
};

// Corner of the face lines of walls p and q (q follows p): both offset inwards by half a wall.
glm::dvec2 face_corner(const Wall& p, const Wall& q, double half) {
  const glm::dvec2 base = q.start + q.inward * half;
  const double s = (half - glm::dot(base - p.start, p.inward)) / glm::dot(q.dir, p.inward);
  return base + q.dir * s;
}

}  // namespace

ShellMesh build_prism_shell(const BuildingPlan& plan, int room) {
  const RoomPlan& r = plan.rooms[size_t(room)];
  const size_t n = r.footprint.size();
  assert(n >= 3);
  const double hw = 0.5 * kWallThickness;
  const double y_floor = r.floor_mid + 0.5 * kSlabThickness, y_ceiling = r.ceiling_mid - 0.5 * kSlabThickness;

  std::vector<Wall> walls(n);
  for (size_t k = 0; k < n; ++k) {
    walls[k].start = r.footprint[k];
    walls[k].dir = glm::normalize(r.footprint[(k + 1) % n] - r.footprint[k]);
    walls[k].inward = left_normal(walls[k].dir);
  }
  for (size_t k = 0; k < n; ++k) {
    Wall& w = walls[k];
    // The same call for a wall's begin and its predecessor's end: bit-identical shared corners.
    w.corner_begin = face_corner(walls[(k + n - 1) % n], w, hw);
    w.corner_end = face_corner(w, walls[(k + 1) % n], hw);
    w.a_begin = glm::dot(w.corner_begin - w.start, w.dir);
    w.a_end = glm::dot(w.corner_end - w.start, w.dir);
  }

  std::vector<double> heights{y_floor, y_ceiling};
  for (const OpeningPlan& o : plan.openings) {
    if ((o.from != room && o.to != room) || o.linked()) continue;  // linked portals cut no hole
    assert(!o.in_slab && o.v_axis == glm::dvec3(0, 1, 0));         // no floor holes in polygonal rooms
    const glm::dvec3 p0 = o.point(o.u0, 0.0), p1 = o.point(o.u1, 0.0);
    bool placed = false;
    for (Wall& w : walls) {
      const glm::dvec2 q0(p0.x, p0.z), q1(p1.x, p1.z);
      if (std::fabs(glm::dot(q0 - w.start, w.inward)) > 1e-7 || std::fabs(glm::dot(q1 - w.start, w.inward)) > 1e-7)
        continue;
      double a0 = glm::dot(q0 - w.start, w.dir), a1 = glm::dot(q1 - w.start, w.dir);
      if (a0 > a1) std::swap(a0, a1);
      if (a0 <= w.a_begin || a1 >= w.a_end) continue;
      double b0 = o.v0, b1 = o.v1;
      if (std::fabs(b0 - y_floor) < 1e-9) b0 = y_floor;  // door sills snap to the floor
      w.holes.push_back({a0, a1, b0, b1, hole_kind(o, room)});
      heights.insert(heights.end(), {b0, b1});
      placed = true;
      break;
    }
    assert(placed && "opening is not on any wall of the room");
    (void)placed;
  }
  const std::vector<double> b_splits = splits_within(heights, y_floor, y_ceiling);

  ShellMesh out;
  for (Wall& w : walls) {
    std::vector<double> along{w.a_begin, w.a_end};
    for (const PanelHole& h : w.holes) along.insert(along.end(), {h.a0, h.a1});
    w.a_splits = splits_within(along, w.a_begin, w.a_end);
    WallPanel panel;
    panel.a_splits = w.a_splits;
    panel.b_splits = b_splits;
    panel.holes = w.holes;
    panel.normal = {w.inward.x, 0, w.inward.y};
    panel.axis_a = {w.dir.x, 0, w.dir.y};
    panel.axis_b = {0, 1, 0};
    const Wall wall = w;
    panel.point = [wall, hw](double a, double b, bool mid) {
      if (!mid && a == wall.a_begin) return glm::dvec3(wall.corner_begin.x, b, wall.corner_begin.y);
      if (!mid && a == wall.a_end) return glm::dvec3(wall.corner_end.x, b, wall.corner_end.y);
      const glm::dvec2 p = wall.start + wall.dir * a + (mid ? 0.0 : hw) * wall.inward;
      return glm::dvec3(p.x, b, p.y);
    };
    emit_panel(panel, out);

    // Floor and ceiling fans use this wall's bottom and top vertices, exactly as the panel made them.
    glm::dvec2 centre(0.0);
    for (const Wall& c : walls) centre += c.corner_begin;
    centre /= double(n);
    for (size_t i = 0; i + 1 < w.a_splits.size(); ++i)
      for (int level = 0; level < 2; ++level) {
        const double y = level == 0 ? y_floor : y_ceiling;
        out.add_triangle(glm::dvec3(centre.x, y, centre.y), panel.point(w.a_splits[i], y, false),
                         panel.point(w.a_splits[i + 1], y, false), {0, level == 0 ? 1 : -1, 0});
      }
  }
  return out;
}

}  // namespace lintel::gen
