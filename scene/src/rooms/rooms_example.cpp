// generate_rooms_example: a small house authored as a Blender user would for Godot 3's rooms
// (docs/rooms.md): four rooms of different shapes (two boxes, an L with a '-bound' because its box
// would swallow the kitchen, a tall garden), three doors, a one-way window, furniture and lights.
// Plain glTF: no Lintel extras; `lintel import rooms` makes it a scene.
//
//   z=7 +--------------------+          Garden: x -5..0, z 0..7, 4 m tall, turned half a turn
//       |  Living (L-shape)  |          one-way window in the hall's west wall, into the garden
//   z=4 |        +--door-----+
//   z=3 +--door--+  Kitchen  |
//       |  Hall  door        |
//   z=0 +--------+-----------+
//      x=0      x=4         x=7
#include "generate/furniture_meshes.h"
#include "generate/shell_mesh.h"

#include <lintel/rooms_import.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace lintel {
namespace {

struct Opening {
  const char* name;       // node name, with its suffix
  glm::dvec2 a, b;        // ends on the floor plan (x, z), world
  double bottom, top;     // heights (m)
  glm::dvec3 toward;      // one-way: the direction it looks (from the room behind into the room in front)
  const char* cut_in[2];  // rooms whose walls get the hole (a one-way window is a wall seen from outside)
  const char* parent;     // room node the portal hangs below (Godot style), or nullptr for a root
};

struct RoomSpec {
  const char* name;
  std::vector<glm::dvec2> footprint;  // counter-clockwise in (x, z), world
  size_t fan_from;                    // floor/ceiling fan corner (the reflex corner of an L)
  double floor, ceiling;
  glm::dvec3 origin;  // node translation (world)
  double turn_rad;    // node rotation about +Y
  glm::vec4 color;
  bool bound;  // give it a '-bound' (closed prism of the footprint)
};

const Opening kOpenings[] = {
    {"HallKitchen-portal", {4, 1}, {4, 2}, 0.0, 2.1, {}, {"Hall", "Kitchen"}, "Hall"},
    {"HallLiving-portal", {1.5, 3}, {2.5, 3}, 0.0, 2.1, {}, {"Hall", "Living"}, nullptr},
    {"KitchenLiving-portal", {5, 4}, {6, 4}, 0.0, 2.1, {}, {"Kitchen", "Living"}, nullptr},
    {"HallWindow-portal-oneway", {0, 1}, {0, 2}, 1.0, 2.0, {-1, 0, 0}, {"Hall", nullptr}, "Hall"},
};

std::vector<RoomSpec> room_specs() {
  return {
      {"Hall", {{0, 0}, {4, 0}, {4, 3}, {0, 3}}, 0, 0.0, 2.7, {2, 0, 1.5}, 0.0, {0.86f, 0.84f, 0.78f, 1}, false},
      {"Kitchen", {{4, 0}, {7, 0}, {7, 4}, {4, 4}}, 0, 0.0, 2.7, {5.5, 0, 2}, 0.0, {0.80f, 0.88f, 0.84f, 1}, false},
      {"Living",
       {{0, 3}, {4, 3}, {4, 4}, {7, 4}, {7, 7}, {4, 7}, {0, 7}},
       2,
       0.0,
       2.7,
       {3, 0, 5},
       0.0,
       {0.92f, 0.86f, 0.74f, 1},
       true},
      {"Garden",
       {{-5, 0}, {0, 0}, {0, 7}, {-5, 7}},
       0,
       0.0,
       4.0,
       {-2.5, 0, 3.5},
       M_PI,
       {0.45f, 0.55f, 0.35f, 1},
       false},
  };
}

glm::dmat4 node_matrix(const RoomSpec& room) {
  return glm::translate(glm::dmat4(1.0), room.origin) *
         glm::rotate(glm::dmat4(1.0), room.turn_rad, glm::dvec3(0, 1, 0));
}

glm::dvec3 at(glm::dvec2 p, double y) { return {p.x, y, p.y}; }

double signed_area(const std::vector<glm::dvec2>& f) {
  double a = 0.0;
  for (size_t i = 0; i < f.size(); ++i) a += f[i].x * f[(i + 1) % f.size()].y - f[(i + 1) % f.size()].x * f[i].y;
  return 0.5 * a;
}

// Wall a->b from floor to ceiling with rectangular holes (u along the wall, heights), facing `normal`.
void add_wall(gen::ShellMesh& m, glm::dvec2 a, glm::dvec2 b, double y0, double y1, std::vector<glm::dvec4> holes,
              const glm::dvec3& normal) {
  const double length = glm::length(b - a);
  const glm::dvec2 dir = (b - a) / length;
  auto p = [&](double u, double y) { return at(a + dir * u, y); };
  std::sort(holes.begin(), holes.end(), [](const glm::dvec4& l, const glm::dvec4& r) { return l.x < r.x; });
  double u = 0.0;
  for (const glm::dvec4& h : holes) {  // (u0, u1, bottom, top)
    if (h.x > u) m.add_quad(p(u, y0), p(h.x, y0), p(h.x, y1), p(u, y1), normal);
    if (h.z > y0) m.add_quad(p(h.x, y0), p(h.y, y0), p(h.y, h.z), p(h.x, h.z), normal);
    if (h.w < y1) m.add_quad(p(h.x, h.w), p(h.y, h.w), p(h.y, y1), p(h.x, y1), normal);
    u = h.y;
  }
  if (u < length) m.add_quad(p(u, y0), p(length, y0), p(length, y1), p(u, y1), normal);
}

bool on_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 ab = b - a, ap = p - a;
  const double t = glm::dot(ap, ab) / glm::dot(ab, ab);
  return std::fabs(ab.x * ap.y - ab.y * ap.x) < 1e-9 && t >= -1e-9 && t <= 1 + 1e-9;
}

// A prism over the footprint: facing inwards with the room's holes (`inward`, the shell), or
// closed and facing outwards (the bound).
gen::ShellMesh prism(const RoomSpec& room, bool inward) {
  gen::ShellMesh m;
  const std::vector<glm::dvec2>& f = room.footprint;
  const double side = (signed_area(f) > 0.0) == inward ? 1.0 : -1.0;
  for (size_t i = 0; i < f.size(); ++i) {
    const glm::dvec2 a = f[i], b = f[(i + 1) % f.size()];
    const glm::dvec2 e = glm::normalize(b - a);
    std::vector<glm::dvec4> holes;
    for (const Opening& o : kOpenings) {
      const bool cut = (o.cut_in[0] && room.name == std::string(o.cut_in[0])) ||
                       (o.cut_in[1] && room.name == std::string(o.cut_in[1]));
      if (!inward || !cut || !on_segment(o.a, a, b) || !on_segment(o.b, a, b)) continue;
      const double u0 = glm::dot(o.a - a, e), u1 = glm::dot(o.b - a, e);
      holes.emplace_back(std::min(u0, u1), std::max(u0, u1), o.bottom, o.top);
    }
    add_wall(m, a, b, room.floor, room.ceiling, holes, side * glm::dvec3(-e.y, 0.0, e.x));
  }
  const glm::dvec3 up(0, inward ? 1 : -1, 0);
  const size_t c = room.fan_from;
  for (size_t k = 1; k + 1 < f.size(); ++k) {
    const glm::dvec2 p1 = f[(c + k) % f.size()], p2 = f[(c + k + 1) % f.size()];
    m.add_triangle(at(f[c], room.floor), at(p1, room.floor), at(p2, room.floor), up);
    m.add_triangle(at(f[c], room.ceiling), at(p1, room.ceiling), at(p2, room.ceiling), -up);
  }
  return m;
}

MeshDesc to_local_mesh(const std::string& name, const gen::ShellMesh& m, const glm::dmat4& world_to_node,
                       glm::vec4 color) {
  MeshDesc out;
  out.name = name;
  out.base_color = color;
  for (const glm::dvec3& p : m.positions()) out.positions.emplace_back(glm::dvec3(world_to_node * glm::dvec4(p, 1.0)));
  for (const glm::dvec3& n : m.normals()) out.normals.emplace_back(glm::normalize(glm::dmat3(world_to_node) * n));
  out.indices = m.indices();
  return out;
}

int add_node(SceneDesc& s, const std::string& name, int parent, glm::vec3 translation, int mesh = -1,
             float turn = 0.0f) {
  NodeDesc n;
  n.name = name;
  n.parent = parent;
  n.translation = translation;
  n.rotation = glm::angleAxis(turn, glm::vec3(0, 1, 0));
  n.mesh = mesh;
  s.nodes.push_back(n);
  return int(s.nodes.size()) - 1;
}

int add_mesh(SceneDesc& s, MeshDesc mesh) {
  s.meshes.push_back(std::move(mesh));
  return int(s.meshes.size()) - 1;
}

}  // namespace

SceneDesc generate_rooms_example() {
  SceneDesc s;
  const std::vector<RoomSpec> rooms = room_specs();
  std::vector<int> room_node;
  for (const RoomSpec& room : rooms) {
    const glm::dmat4 world_to_node = glm::inverse(node_matrix(room));
    const int shell =
        add_mesh(s, to_local_mesh(std::string(room.name) + " walls", prism(room, true), world_to_node, room.color));
    room_node.push_back(
        add_node(s, std::string(room.name) + kRoomSuffix, -1, glm::vec3(room.origin), shell, float(room.turn_rad)));
    if (room.bound) {
      const int bound =
          add_mesh(s, to_local_mesh(std::string(room.name) + " bound", prism(room, false), world_to_node, room.color));
      add_node(s, std::string(room.name) + kBoundSuffix, room_node.back(), glm::vec3(0), bound);
    }
  }
  for (const Opening& o : kOpenings) {
    int parent = -1;
    glm::dmat4 world_to_node(1.0);
    for (size_t r = 0; r < rooms.size(); ++r)
      if (o.parent && rooms[r].name == std::string(o.parent)) {
        parent = room_node[r];
        world_to_node = glm::inverse(node_matrix(rooms[r]));
      }
    std::vector<glm::dvec3> quad = {at(o.a, o.bottom), at(o.b, o.bottom), at(o.b, o.top), at(o.a, o.top)};
    if (glm::dot(glm::cross(quad[1] - quad[0], quad[2] - quad[0]), o.toward) < 0.0)
      std::reverse(quad.begin(), quad.end());
    MeshDesc mesh;
    mesh.name = o.name;
    for (const glm::dvec3& p : quad) mesh.positions.emplace_back(glm::dvec3(world_to_node * glm::dvec4(p, 1.0)));
    mesh.indices = {0, 1, 2, 0, 2, 3};
    add_node(s, o.name, parent, glm::vec3(0), add_mesh(s, std::move(mesh)));
  }
  // Furniture below the rooms, in their frames (Garden is turned half a turn: its +X is west).
  const int table = add_mesh(s, gen::make_table({0.55f, 0.38f, 0.22f, 1}));
  const int chair = add_mesh(s, gen::make_chair({0.45f, 0.30f, 0.18f, 1}));
  const int sofa = add_mesh(s, gen::make_sofa({0.30f, 0.35f, 0.55f, 1}));
  const int shelf = add_mesh(s, gen::make_shelf({0.50f, 0.40f, 0.30f, 1}));
  const int tree = add_mesh(s, gen::make_tree({0.25f, 0.50f, 0.20f, 1}));
  add_node(s, "Shelf", room_node[0], {-1.2f, 0.0f, -1.3f}, shelf);
  add_node(s, "KitchenTable", room_node[1], {0.0f, 0.0f, 0.3f}, table);
  add_node(s, "KitchenChair", room_node[1], {0.0f, 0.0f, 1.0f}, chair, float(M_PI));
  add_node(s, "KitchenChair.001", room_node[1], {0.0f, 0.0f, -0.4f}, chair);
  add_node(s, "Sofa", room_node[2], {-1.5f, 0.0f, 1.4f}, sofa, float(M_PI));
  add_node(s, "Tree", room_node[3], {0.0f, 0.0f, 0.0f}, tree);
  // Lights: a lamp in the hall and the kitchen (KHR_lights_punctual point lights).
  for (int r : {0, 1}) {
    s.lights.push_back(
        {rooms[size_t(r)].name + std::string(" lamp"), Light::Type::Point, {1.0f, 0.93f, 0.8f}, 8.0f, 0.0f});
    const int lamp =
        add_node(s, rooms[size_t(r)].name + std::string(" lamp"), room_node[size_t(r)], {0.0f, 2.4f, 0.0f});
    s.nodes[size_t(lamp)].light = int(s.lights.size()) - 1;
  }
  return s;
}

}  // namespace lintel
