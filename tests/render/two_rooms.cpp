// The leak test's scene: quads in world space, moved into each cell's space by the inverse of
// its frame; every quad has its own four vertices and a normal facing the room's air.
#include "two_rooms.h"

#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace lintel::render::test {
namespace {

constexpr float kDoorZ0 = 1.5f, kDoorZ1 = 2.5f, kDoorTop = 2.0f;
constexpr float kPortalX = 0.5f * (kRoomAMaxX + kRoomBMinX);

struct Frame {
  glm::vec3 translation;
  glm::quat rotation;
  glm::mat4 world_to_local() const {
    return glm::inverse(glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation));
  }
};

// Appends quad p0 p1 p2 p3 (a planar rectangle, corners in order), front face towards `normal`
// (world), transformed into the frame's local space.
void add_quad(MeshDesc& m, const Frame& f, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3, glm::vec3 normal) {
  if (glm::dot(glm::cross(p1 - p0, p2 - p0), normal) < 0.0f) std::swap(p1, p3);
  const glm::mat4 to_local = f.world_to_local();
  const glm::vec3 n_local = glm::normalize(glm::mat3(to_local) * normal);
  const uint32_t base = uint32_t(m.positions.size());
  for (const glm::vec3& p : {p0, p1, p2, p3}) {
    m.positions.push_back(glm::vec3(to_local * glm::vec4(p, 1.0f)));
    m.normals.push_back(n_local);
  }
  m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

// Axis-aligned rectangle on the plane `axis` = `at`, spanning [a0, a1] x [b0, b1] along the other
// two axes (in x, y, z order, skipping `axis`).
void add_rect(MeshDesc& m, const Frame& f, int axis, float at, float a0, float a1, float b0, float b1, float facing) {
  auto point = [&](float a, float b) {
    glm::vec3 p;
    p[axis] = at;
    p[axis == 0 ? 1 : 0] = a;
    p[axis == 2 ? 1 : 2] = b;
    return p;
  };
  glm::vec3 n(0.0f);
  n[axis] = facing;
  add_quad(m, f, point(a0, b0), point(a1, b0), point(a1, b1), point(a0, b1), n);
}

// The shell of the room whose air is x in [x0, x1]. With `door`, the wall at `door_x` (x0 or x1)
// has the door, whose reveal reaches `reveal_x` (the portal plane).
MeshDesc room_shell(const std::string& name, const Frame& f, float x0, float x1, bool door, float door_x,
                    float reveal_x, const glm::vec4& color) {
  MeshDesc m;
  m.name = name + "_shell";
  m.base_color = color;
  const float h = kRoomHeight, d = kRoomDepth;
  add_rect(m, f, 1, 0.0f, x0, x1, 0.0f, d, +1.0f);  // floor (x, z)
  add_rect(m, f, 1, h, x0, x1, 0.0f, d, -1.0f);     // ceiling
  add_rect(m, f, 2, 0.0f, x0, x1, 0.0f, h, +1.0f);  // walls z = 0 and z = d (x, y)
  add_rect(m, f, 2, d, x0, x1, 0.0f, h, -1.0f);
  for (float wall_x : {x0, x1}) {
    const float facing = wall_x == x0 ? +1.0f : -1.0f;
    if (!door || wall_x != door_x) {
      add_rect(m, f, 0, wall_x, 0.0f, h, 0.0f, d, facing);  // (y, z)
      continue;
    }
    add_rect(m, f, 0, wall_x, 0.0f, h, 0.0f, kDoorZ0, facing);
    add_rect(m, f, 0, wall_x, 0.0f, h, kDoorZ1, d, facing);
    add_rect(m, f, 0, wall_x, kDoorTop, h, kDoorZ0, kDoorZ1, facing);
    // Reveals: jambs, head and sill from the wall face to the portal plane, facing the opening.
    const float r0 = std::min(wall_x, reveal_x), r1 = std::max(wall_x, reveal_x);
    add_rect(m, f, 2, kDoorZ0, r0, r1, 0.0f, kDoorTop, +1.0f);
    add_rect(m, f, 2, kDoorZ1, r0, r1, 0.0f, kDoorTop, -1.0f);
    add_rect(m, f, 1, kDoorTop, r0, r1, kDoorZ0, kDoorZ1, -1.0f);
    add_rect(m, f, 1, 0.0f, r0, r1, kDoorZ0, kDoorZ1, +1.0f);
  }
  return m;
}

// A closed box [lo, hi] in world space, faces outward (volumes and crates).
MeshDesc box(const std::string& name, const Frame& f, const glm::vec3& lo, const glm::vec3& hi,
             const glm::vec4& color) {
  MeshDesc m;
  m.name = name;
  m.base_color = color;
  for (int axis = 0; axis < 3; ++axis) {
    const int a = axis == 0 ? 1 : 0, b = axis == 2 ? 1 : 2;
    add_rect(m, f, axis, lo[axis], lo[a], hi[a], lo[b], hi[b], -1.0f);
    add_rect(m, f, axis, hi[axis], lo[a], hi[a], lo[b], hi[b], +1.0f);
  }
  return m;
}

int add_mesh(SceneDesc& s, MeshDesc m) {
  s.meshes.push_back(std::move(m));
  return int(s.meshes.size() - 1);
}

int add_node(SceneDesc& s, NodeDesc n) {
  s.nodes.push_back(std::move(n));
  return int(s.nodes.size() - 1);
}

}  // namespace

SceneDesc two_rooms(bool door) {
  SceneDesc s;
  const Frame identity{glm::vec3(0.0f), glm::quat(1.0f, 0.0f, 0.0f, 0.0f)};
  const Frame frame_a{{2.0f, 0.0f, 2.0f}, glm::quat(1.0f, 0.0f, 0.0f, 0.0f)};
  const Frame frame_b{{6.2f, 0.0f, 2.0f}, glm::angleAxis(glm::radians(90.0f), glm::vec3(0.0f, 1.0f, 0.0f))};
  struct Room {
    const char* name;
    Frame frame;
    float x0, x1, door_x, volume_x0, volume_x1;
    glm::vec4 color;
    glm::vec3 crate_world;
  } rooms[2] = {
      {"A",
       frame_a,
       kRoomAMinX,
       kRoomAMaxX,
       kRoomAMaxX,
       kRoomAMinX,
       kPortalX,
       {0.8f, 0.8f, 0.75f, 1.0f},
       {1.0f, 0.0f, 1.0f}},
      {"B",
       frame_b,
       kRoomBMinX,
       kRoomBMaxX,
       kRoomBMinX,
       kPortalX,
       kRoomBMaxX,
       {0.75f, 0.8f, 0.8f, 1.0f},
       {7.0f, 0.0f, 3.0f}},
  };
  int cell_a_node = -1;
  for (const Room& r : rooms) {
    NodeDesc cell;
    cell.name = std::string("room_") + r.name;
    cell.kind = NodeDesc::Kind::Cell;
    cell.cell_name = r.name;
    cell.translation = r.frame.translation;
    cell.rotation = r.frame.rotation;
    cell.mesh = add_mesh(s, room_shell(cell.name, r.frame, r.x0, r.x1, door, r.door_x, kPortalX, r.color));
    const int cell_node = add_node(s, cell);
    if (cell_a_node < 0) cell_a_node = cell_node;

    NodeDesc volume;
    volume.name = cell.name + "_volume";
    volume.kind = NodeDesc::Kind::Volume;
    volume.parent = cell_node;
    volume.mesh = add_mesh(s, box(volume.name, r.frame, {r.volume_x0, 0.0f, 0.0f},
                                  {r.volume_x1, kRoomHeight, kRoomDepth}, glm::vec4(1.0f)));
    add_node(s, volume);

    // The crate's mesh is in its node's space; the node sits at the crate's spot in the cell.
    NodeDesc crate;
    crate.name = cell.name + "_crate";
    crate.parent = cell_node;
    crate.translation = glm::vec3(r.frame.world_to_local() * glm::vec4(r.crate_world, 1.0f));
    crate.mesh =
        add_mesh(s, box(crate.name, identity, {-0.4f, 0.0f, -0.4f}, {0.4f, 0.8f, 0.4f}, {0.7f, 0.5f, 0.3f, 1.0f}));
    add_node(s, crate);
  }

  LightDesc lamp;
  lamp.name = "lamp_A";
  lamp.type = Light::Type::Point;
  lamp.color = {1.0f, 0.9f, 0.8f};
  lamp.intensity = 12.0f;
  lamp.range = 0.0f;  // unlimited: nothing but the walls and the cell graph keeps it out of B
  s.lights.push_back(lamp);
  NodeDesc light;
  light.name = "lamp_A";
  light.parent = cell_a_node;
  light.translation = glm::vec3(frame_a.world_to_local() * glm::vec4(kLightA, 1.0f));
  light.light = 0;
  add_node(s, light);

  if (door) {
    MeshDesc opening;
    opening.name = "door_AB";
    add_rect(opening, identity, 0, kPortalX, 0.0f, kDoorTop, kDoorZ0, kDoorZ1, +1.0f);
    NodeDesc portal;
    portal.name = "door_AB";
    portal.kind = NodeDesc::Kind::Portal;
    portal.portal_from = "A";
    portal.portal_to = "B";
    portal.mesh = add_mesh(s, opening);
    add_node(s, portal);
  }
  return s;
}

View towards_crate_a(float aspect) {
  View v;
  v.eye_world = {3.5f, 1.6f, 3.5f};
  v.target_world = {1.0f, 0.4f, 1.0f};  // room A's crate
  v.aspect = aspect;
  return v;
}

MeshDesc& crate_a(SceneDesc& desc) {
  auto is_crate = [](const MeshDesc& m) { return m.name == "room_A_crate"; };
  const auto count = std::count_if(desc.meshes.begin(), desc.meshes.end(), is_crate);
  // Thrown, not asserted: tests build in Release, and gtest fails the test on an exception.
  if (count != 1)
    throw std::logic_error("two_rooms: " + std::to_string(count) + " meshes named room_A_crate, expected 1");
  return *std::find_if(desc.meshes.begin(), desc.meshes.end(), is_crate);
}

World built_world(const SceneDesc& desc) {
  World world;
  const Status s = build_world(desc, "two rooms", world);
  EXPECT_TRUE(s.ok()) << s.message();
  return world;
}

}  // namespace lintel::render::test
