// `house`: 3 x 3 rooms authored the way a modeller exports closed rooms -- every room a closed,
// single-sided shell facing its own air, neighbouring rooms' walls back to back in ONE plane (only
// back-face culling decides which of the two the camera sees) -- tilted, every cell frame a
// random rotation and offset (compensated in the vertices), doors between all neighbours, a crate
// in some rooms and a point light in most. Rectangles are built in house space, taken to world
// space by the house's tilt and into each cell's space by the inverse of its frame. Its views are
// inspection cameras (through doors, along shared walls, into corners); the scene's timeline holds
// each of them for a second.
#include <lintel/scene_gen.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <random>
#include <string>

namespace lintel {
namespace {

constexpr int kRooms = 3;                       // per side
constexpr float kPitch = 4.0f, kHeight = 2.5f;  // room size (walls have no thickness)
constexpr float kDoorHalf = 0.5f, kDoorTop = 2.0f;

// House space -> world: a tilt about an oblique axis and a turn, so no wall is axis-aligned.
glm::mat4 house_to_world() {
  return glm::translate(glm::mat4(1.0f), glm::vec3(3.0f, 1.0f, -2.0f)) *
         glm::rotate(glm::mat4(1.0f), glm::radians(23.0f), glm::normalize(glm::vec3(1.0f, 0.3f, 0.6f))) *
         glm::rotate(glm::mat4(1.0f), glm::radians(31.0f), glm::vec3(0.0f, 1.0f, 0.0f));
}

struct Frame {
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
};

// Rectangle on plane `axis` = `at` (house space) over [a0, a1] x [b0, b1] of the other two axes (x,
// y, z order), front face (counter-clockwise) towards `facing` along `axis`; appended to `m` in
// the space `to_local` maps house space to.
void add_rect(MeshDesc& m, const glm::mat4& to_local, int axis, float at, float a0, float a1, float b0, float b1,
              float facing) {
  auto point = [&](float a, float b) {
    glm::vec3 p;
    p[axis] = at;
    p[axis == 0 ? 1 : 0] = a;
    p[axis == 2 ? 1 : 2] = b;
    return p;
  };
  glm::vec3 p[4] = {point(a0, b0), point(a1, b0), point(a1, b1), point(a0, b1)};
  glm::vec3 n(0.0f);
  n[axis] = facing;
  if (glm::dot(glm::cross(p[1] - p[0], p[2] - p[0]), n) < 0.0f) std::swap(p[1], p[3]);
  const glm::vec3 n_local = glm::normalize(glm::transpose(glm::inverse(glm::mat3(to_local))) * n);
  const uint32_t base = uint32_t(m.positions.size());
  for (const glm::vec3& q : p) {
    m.positions.push_back(glm::vec3(to_local * glm::vec4(q, 1.0f)));
    m.normals.push_back(n_local);
  }
  m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

// A wall on plane `axis` = `at` spanning [a0, a1] horizontally (the other horizontal axis), with a
// centred door when `door`.
void add_wall(MeshDesc& m, const glm::mat4& to_local, int axis, float at, float a0, float a1, bool door, float facing) {
  // Horizontal axis along the wall and y: add_rect orders the free axes x, y, z.
  auto rect = [&](float h0, float h1, float y0, float y1) {
    if (axis == 0)
      add_rect(m, to_local, 0, at, y0, y1, h0, h1, facing);  // (y, z)
    else
      add_rect(m, to_local, 2, at, h0, h1, y0, y1, facing);  // (x, y)
  };
  if (!door) {
    rect(a0, a1, 0.0f, kHeight);
    return;
  }
  const float mid = 0.5f * (a0 + a1);
  rect(a0, mid - kDoorHalf, 0.0f, kHeight);
  rect(mid + kDoorHalf, a1, 0.0f, kHeight);
  rect(mid - kDoorHalf, mid + kDoorHalf, kDoorTop, kHeight);
}

// A closed box [lo, hi] (house space), faces outward.
void add_box(MeshDesc& m, const glm::mat4& to_local, const glm::vec3& lo, const glm::vec3& hi) {
  for (int axis = 0; axis < 3; ++axis) {
    const int a = axis == 0 ? 1 : 0, b = axis == 2 ? 1 : 2;
    add_rect(m, to_local, axis, lo[axis], lo[a], hi[a], lo[b], hi[b], -1.0f);
    add_rect(m, to_local, axis, hi[axis], lo[a], hi[a], lo[b], hi[b], +1.0f);
  }
}

int add_mesh(SceneDesc& s, MeshDesc m) {
  s.meshes.push_back(std::move(m));
  return int(s.meshes.size() - 1);
}

int add_node(SceneDesc& s, NodeDesc n) {
  s.nodes.push_back(std::move(n));
  return int(s.nodes.size() - 1);
}

std::string room_name(int i, int j) { return "r" + std::to_string(i) + std::to_string(j); }

}  // namespace

SceneDesc generate_house(const HouseOptions& options, std::vector<View>* views) {
  SceneDesc out;
  SceneDesc& s = out;
  const glm::mat4 to_world = house_to_world();
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int i = 0; i < kRooms; ++i)
    for (int j = 0; j < kRooms; ++j) {
      const float x0 = kPitch * float(i), x1 = x0 + kPitch, z0 = kPitch * float(j), z1 = z0 + kPitch;
      Frame f;
      f.translation = glm::vec3(to_world * glm::vec4(x0 + 2.0f + u(rng), 1.0f + u(rng), z0 + 2.0f + u(rng), 1.0f));
      f.rotation = glm::angleAxis(glm::radians(180.0f * u(rng)), glm::normalize(glm::vec3(u(rng), 1.0f, u(rng))));
      const glm::mat4 cell_to_world = glm::translate(glm::mat4(1.0f), f.translation) * glm::mat4_cast(f.rotation);
      const glm::mat4 house_to_cell = glm::inverse(cell_to_world) * to_world;
      const float hue = float(i * kRooms + j) / float(kRooms * kRooms);
      const glm::vec4 color(0.25f + 0.6f * hue, 0.85f - 0.5f * hue, 0.3f + 0.5f * float((i + 2 * j) % 3) / 2.0f, 1.0f);

      MeshDesc shell;
      shell.name = room_name(i, j) + "_shell";
      shell.base_color = color;
      add_rect(shell, house_to_cell, 1, 0.0f, x0, x1, z0, z1, +1.0f);     // floor
      add_rect(shell, house_to_cell, 1, kHeight, x0, x1, z0, z1, -1.0f);  // ceiling
      add_wall(shell, house_to_cell, 0, x0, z0, z1, i > 0, +1.0f);
      add_wall(shell, house_to_cell, 0, x1, z0, z1, i + 1 < kRooms, -1.0f);
      add_wall(shell, house_to_cell, 2, z0, x0, x1, j > 0, +1.0f);
      add_wall(shell, house_to_cell, 2, z1, x0, x1, j + 1 < kRooms, -1.0f);
      NodeDesc cell;
      cell.name = room_name(i, j);
      cell.kind = NodeDesc::Kind::Cell;
      cell.cell_name = cell.name;
      cell.translation = f.translation;
      cell.rotation = f.rotation;
      cell.mesh = add_mesh(s, shell);
      const int cell_node = add_node(s, cell);

      MeshDesc volume;
      volume.name = cell.name + "_volume";
      volume.base_color = glm::vec4(1.0f, 1.0f, 1.0f, 0.0f);
      add_box(volume, house_to_cell, {x0, 0.0f, z0}, {x1, kHeight, z1});
      NodeDesc vnode;
      vnode.name = volume.name;
      vnode.kind = NodeDesc::Kind::Volume;
      vnode.parent = cell_node;
      vnode.mesh = add_mesh(s, volume);
      add_node(s, vnode);

      if ((i + j) % 2 == 0) {  // a crate against the room's -x wall
        MeshDesc crate;
        crate.name = cell.name + "_crate";
        crate.base_color = glm::vec4(0.9f - 0.6f * hue, 0.5f, 0.2f + 0.6f * hue, 1.0f);
        add_box(crate, house_to_cell, {x0 + 0.3f, 0.0f, z0 + 0.6f}, {x0 + 1.1f, 0.8f, z0 + 1.6f});
        NodeDesc n;
        n.name = crate.name;
        n.parent = cell_node;
        n.mesh = add_mesh(s, crate);
        add_node(s, n);
      }
      if ((i * kRooms + j) % 4 != 3) {  // a lamp in most rooms
        LightDesc lamp;
        lamp.name = cell.name + "_lamp";
        lamp.color = glm::vec3(1.0f, 0.92f, 0.8f);
        lamp.intensity = 8.0f;
        lamp.range = 9.0f;
        s.lights.push_back(lamp);
        NodeDesc n;
        n.name = lamp.name;
        n.parent = cell_node;
        n.translation = glm::vec3(house_to_cell * glm::vec4(x0 + 2.6f, 2.1f, z0 + 2.3f, 1.0f));
        n.light = int(s.lights.size() - 1);
        add_node(s, n);
      }
    }
  // Doors: the opening in each shared wall, a two-way portal in the wall's plane (world space).
  auto portal = [&](const std::string& from, const std::string& to, int axis, float at, float mid) {
    MeshDesc opening;
    opening.name = "door_" + from + "_" + to;
    if (axis == 0)
      add_rect(opening, to_world, 0, at, 0.0f, kDoorTop, mid - kDoorHalf, mid + kDoorHalf, +1.0f);
    else
      add_rect(opening, to_world, 2, at, mid - kDoorHalf, mid + kDoorHalf, 0.0f, kDoorTop, +1.0f);
    opening.base_color = glm::vec4(0.3f, 0.6f, 1.0f, 0.0f);
    NodeDesc n;
    n.name = opening.name;
    n.kind = NodeDesc::Kind::Portal;
    n.portal_from = from;
    n.portal_to = to;
    n.mesh = add_mesh(s, opening);
    add_node(s, n);
  };
  for (int i = 0; i < kRooms; ++i)
    for (int j = 0; j < kRooms; ++j) {
      if (i + 1 < kRooms)
        portal(room_name(i, j), room_name(i + 1, j), 0, kPitch * float(i + 1), kPitch * (float(j) + 0.5f));
      if (j + 1 < kRooms)
        portal(room_name(i, j), room_name(i, j + 1), 2, kPitch * float(j + 1), kPitch * (float(i) + 0.5f));
    }

  // Views from inside rooms: through doors, along shared walls at grazing angles, into corners.
  const struct {
    glm::vec3 eye, target;
  } cameras[] = {
      {{0.6f, 1.6f, 0.6f}, {11.0f, 1.0f, 2.0f}},   // along the x row, through two doors
      {{0.6f, 1.6f, 0.6f}, {2.0f, 1.0f, 11.0f}},   // along the z column
      {{2.0f, 1.2f, 2.0f}, {3.99f, 1.0f, 3.99f}},  // into the corner where four rooms meet
      {{6.0f, 1.7f, 6.0f}, {4.5f, 1.2f, 0.2f}},    // the middle room, a wall with a door at a slant
      {{7.5f, 1.5f, 1.0f}, {0.5f, 0.5f, 11.0f}},   // diagonally across the house
      {{10.5f, 2.2f, 10.5f}, {4.2f, 0.3f, 4.4f}},  // from a far corner, looking down towards the centre
  };
  Timeline inspect;
  inspect.name = "inspect";
  inspect.fps = 30.0;
  inspect.fov_y_deg = 70.0;
  inspect.aspect = 16.0 / 9.0;
  double t = 0.0;
  for (const auto& c : cameras) {
    View v;
    v.eye_world = glm::vec3(to_world * glm::vec4(c.eye, 1.0f));
    v.target_world = glm::vec3(to_world * glm::vec4(c.target, 1.0f));
    v.up_world = glm::normalize(glm::mat3(to_world) * glm::vec3(0.0f, 1.0f, 0.0f));
    v.fov_y_deg = 70.0f;
    if (views) views->push_back(v);
    // Held for a second, then a cut to the next camera (the timeline's up is world +Y).
    inspect.keys.push_back({t, v.eye_world, v.target_world});
    inspect.keys.push_back({t + 0.99, v.eye_world, v.target_world});
    t += 1.0;
  }
  s.timelines.push_back(std::move(inspect));
  return out;
}

}  // namespace lintel
