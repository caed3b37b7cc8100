// Picks the shell builder for a room and builds the closed volumes (mid-plane prisms, and for the
// exterior a big box with the house cut out from below).
#include "generate/room_shell.h"

#include <cassert>

namespace lintel::gen {
namespace {

void add_face(VolumeMesh& m, std::initializer_list<uint32_t> ring, const glm::dvec3& outward) {
  const std::vector<uint32_t> v(ring);
  for (size_t i = 1; i + 1 < v.size(); ++i) {
    const glm::dvec3 &a = m.positions[v[0]], &b = m.positions[v[i]], &c = m.positions[v[i + 1]];
    if (glm::dot(glm::cross(b - a, c - a), outward) >= 0.0)
      m.indices.insert(m.indices.end(), {v[0], v[i], v[i + 1]});
    else
      m.indices.insert(m.indices.end(), {v[0], v[i + 1], v[i]});
  }
}

VolumeMesh prism_volume(const RoomPlan& room) {
  VolumeMesh m;
  const auto n = uint32_t(room.footprint.size());
  for (const glm::dvec2& p : room.footprint) m.positions.emplace_back(p.x, room.floor_mid, p.y);
  for (const glm::dvec2& p : room.footprint) m.positions.emplace_back(p.x, room.ceiling_mid, p.y);
  for (uint32_t i = 1; i + 1 < n; ++i) {
    add_face(m, {0, i, i + 1}, {0, -1, 0});
    add_face(m, {n, n + i, n + i + 1}, {0, 1, 0});
  }
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t j = (i + 1) % n;
    const glm::dvec2 e = room.footprint[j] - room.footprint[i];
    add_face(m, {i, j, n + j, n + i}, {e.y, 0, -e.x});  // right of a counter-clockwise edge: outside
  }
  return m;
}

// Air around the house: a box from the ground up to sky_height above the roof, minus the house's
// mid-plane box (from the ground to the roof slab's mid-plane), which the rooms' volumes fill.
VolumeMesh exterior_volume(const RoomPlan& room) {
  assert(is_axis_aligned_box(room));
  const double x0 = room.footprint[0].x, z0 = room.footprint[0].y, x1 = room.footprint[2].x, z1 = room.footprint[2].y;
  const double m = room.ground_margin + 0.5 * kWallThickness;
  const double g = room.floor_mid, top = room.ceiling_mid + room.sky_height, dent = room.ceiling_mid;
  VolumeMesh v;
  const double ox[4] = {x0 - m, x1 + m, x1 + m, x0 - m}, oz[4] = {z0 - m, z0 - m, z1 + m, z1 + m};
  const double ix[4] = {x0, x1, x1, x0}, iz[4] = {z0, z0, z1, z1};
  for (int i = 0; i < 4; ++i) v.positions.emplace_back(ox[i], g, oz[i]);     // 0..3 outer bottom
  for (int i = 0; i < 4; ++i) v.positions.emplace_back(ox[i], top, oz[i]);   // 4..7 outer top
  for (int i = 0; i < 4; ++i) v.positions.emplace_back(ix[i], g, iz[i]);     // 8..11 dent bottom
  for (int i = 0; i < 4; ++i) v.positions.emplace_back(ix[i], dent, iz[i]);  // 12..15 dent top
  add_face(v, {4, 5, 6, 7}, {0, 1, 0});
  add_face(v, {12, 13, 14, 15}, {0, -1, 0});  // the dent's ceiling faces down, into the house
  for (uint32_t i = 0; i < 4; ++i) {
    const uint32_t j = (i + 1) % 4;
    const glm::dvec3 out =
        glm::dvec3(ox[i] + ox[j], 0, oz[i] + oz[j]) * 0.5 - glm::dvec3(0.5 * (x0 + x1), 0, 0.5 * (z0 + z1));
    add_face(v, {i, j, 4 + j, 4 + i}, out);             // outer side
    add_face(v, {i, j, 8 + j, 8 + i}, {0, -1, 0});      // ground ring between outer box and dent
    add_face(v, {8 + i, 8 + j, 12 + j, 12 + i}, -out);  // dent wall, facing into the house
  }
  return v;
}

}  // namespace

PanelHole::Kind hole_kind(const OpeningPlan& o, int room) {
  return (o.two_way || o.from == room) ? PanelHole::Kind::Open : PanelHole::Kind::Plugged;
}

bool is_axis_aligned_box(const RoomPlan& room) {
  const auto& f = room.footprint;
  return f.size() == 4 && f[0].y == f[1].y && f[1].x == f[2].x && f[2].y == f[3].y && f[3].x == f[0].x &&
         f[0].x < f[1].x && f[1].y < f[2].y;
}

ShellMesh build_room_shell(const BuildingPlan& plan, int room) {
  const RoomPlan& r = plan.rooms[size_t(room)];
  if (r.exterior) return build_exterior_shell(plan, room);
  if (is_axis_aligned_box(r)) return build_box_shell(plan, room);
  return build_prism_shell(plan, room);
}

VolumeMesh build_room_volume(const BuildingPlan& plan, int room) {
  const RoomPlan& r = plan.rooms[size_t(room)];
  return r.exterior ? exterior_volume(r) : prism_volume(r);
}

}  // namespace lintel::gen
