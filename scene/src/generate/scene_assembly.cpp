// Scene assembly: node layout per cell (cell, volume, rigid frame, instances, lights, portals)
// and the change of space of all baked vertices.
#include "generate/scene_assembly.h"

#include "write/portable_math.h"
#include "generate/room_shell.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cassert>
#include <cmath>

namespace lintel::gen {
namespace {

glm::dmat4 local_matrix(const NodeDesc& node) {
  const glm::dquat q = glm::normalize(glm::dquat(node.rotation));
  return glm::translate(glm::dmat4(1.0), glm::dvec3(node.translation)) * glm::mat4_cast(q) *
         glm::scale(glm::dmat4(1.0), glm::dvec3(node.scale));
}

void set_trs(NodeDesc& node, const glm::dvec3& t, const glm::dquat& r, const glm::dvec3& s) {
  node.translation = glm::vec3(t);
  node.rotation = glm::quat(glm::normalize(r));
  node.scale = glm::vec3(s);
}

// Splits a similarity transform (rotation, positive per-axis scale along the rotated axes, translation).
void decompose(const glm::dmat4& m, glm::dvec3& t, glm::dquat& r, glm::dvec3& s) {
  t = glm::dvec3(m[3]);
  glm::dmat3 linear(m);
  for (int i = 0; i < 3; ++i) {
    s[i] = glm::length(linear[i]);
    linear[i] /= s[i];
  }
  assert(std::fabs(glm::dot(linear[0], linear[1])) < 1e-5 && std::fabs(glm::dot(linear[1], linear[2])) < 1e-5);
  assert(glm::determinant(linear) > 0.0);
  r = glm::quat_cast(linear);
}

struct Assembler {
  const BuildingPlan& plan;
  SceneDesc scene;
  glm::dmat4 to_world;  // building -> world
  std::vector<int> cell_node, rigid_node;

  int add_node(NodeDesc node) {
    assert(node.parent < int(scene.nodes.size()));
    scene.nodes.push_back(std::move(node));
    return int(scene.nodes.size()) - 1;
  }

  // Building-space points into the space of `node` (whose world transform is final).
  glm::dmat4 building_to_node(int node) const { return glm::inverse(node_world_matrix(scene, node)) * to_world; }

  int add_mesh(MeshDesc mesh) {
    scene.meshes.push_back(std::move(mesh));
    return int(scene.meshes.size()) - 1;
  }

  void add_cell(int r) {
    const RoomPlan& room = plan.rooms[size_t(r)];
    NodeDesc cell;
    cell.name = room.name;
    cell.kind = NodeDesc::Kind::Cell;
    cell.cell_name = room.name;
    set_trs(cell, room.frame.translation, room.frame.rotation, room.frame.scale);
    const int node = add_node(cell);
    cell_node[size_t(r)] = node;

    const glm::dmat4 b2c = building_to_node(node);
    const glm::dmat3 normal_to_cell = glm::transpose(glm::inverse(glm::dmat3(b2c)));
    const ShellMesh shell = build_room_shell(plan, r);
    MeshDesc mesh;
    mesh.name = room.name + "_shell";
    mesh.base_color = room.color;
    for (const glm::dvec3& p : shell.positions()) mesh.positions.emplace_back(b2c * glm::dvec4(p, 1.0));
    for (const glm::dvec3& n : shell.normals()) mesh.normals.emplace_back(glm::normalize(normal_to_cell * n));
    mesh.indices = shell.indices();
    scene.nodes[size_t(node)].mesh = add_mesh(std::move(mesh));

    if (room.volume) add_volume(r, node);

    // Furniture and lights need a rigid world transform; a non-uniform cell scale would shear
    // them, so they hang from a child node that undoes the scale.
    const glm::vec3 s = scene.nodes[size_t(node)].scale;
    rigid_node[size_t(r)] = node;
    if (s.x != s.y || s.y != s.z) {
      NodeDesc frame;
      frame.name = room.name + "_unscaled";
      frame.parent = node;
      frame.scale = glm::vec3(1.0f / s.x, 1.0f / s.y, 1.0f / s.z);
      rigid_node[size_t(r)] = add_node(frame);
    }
  }

  void add_volume(int r, int cell) {
    const RoomPlan& room = plan.rooms[size_t(r)];
    const VolumeMesh volume = build_room_volume(plan, r);
    glm::dvec3 centre(0.0);
    for (const glm::dvec3& p : volume.positions) centre += p;
    centre /= double(volume.positions.size());
    NodeDesc node;
    node.name = room.name + "_volume";
    node.parent = cell;
    node.kind = NodeDesc::Kind::Volume;
    node.translation = glm::vec3(building_to_node(cell) * glm::dvec4(centre, 1.0));
    const int index = add_node(node);
    const glm::dmat4 b2n = building_to_node(index);
    MeshDesc mesh;
    mesh.name = room.name + "_volume";
    mesh.base_color = {0.3f, 0.6f, 1.0f, 0.0f};  // transparent if a viewer draws it
    for (const glm::dvec3& p : volume.positions) mesh.positions.emplace_back(b2n * glm::dvec4(p, 1.0));
    mesh.indices = volume.indices;
    scene.nodes[size_t(index)].mesh = add_mesh(std::move(mesh));
  }

  // A child of `parent` whose world transform is to_world * building_transform (rigid).
  int add_rigid_child(std::string name, int parent, const glm::dvec3& position, const glm::dquat& rotation) {
    const glm::dmat4 world = to_world * glm::translate(glm::dmat4(1.0), position) * glm::mat4_cast(rotation);
    glm::dvec3 t, s;
    glm::dquat q;
    decompose(glm::inverse(node_world_matrix(scene, parent)) * world, t, q, s);
    NodeDesc node;
    node.name = std::move(name);
    node.parent = parent;
    set_trs(node, t, q, s);
    return add_node(node);
  }

  void add_portal(size_t index) {
    const OpeningPlan& o = plan.openings[index];
    const int from = cell_node[size_t(o.from)];
    const glm::dmat4 b2c = building_to_node(from);
    // The portal node sits at the opening's centre, its +Z along the opening's normal in cell space.
    const glm::dvec3 normal_cell = glm::normalize(glm::transpose(glm::inverse(glm::dmat3(b2c))) * o.normal);
    NodeDesc node;
    node.name = o.name;
    node.parent = from;
    node.kind = NodeDesc::Kind::Portal;
    node.portal_from = plan.rooms[size_t(o.from)].name;
    node.portal_to = plan.rooms[size_t(o.to)].name;
    node.two_way = o.two_way;
    node.portal_mirror = o.mirror;
    node.portal_link = o.link;
    set_trs(node, glm::dvec3(b2c * glm::dvec4(o.center(), 1.0)), rotation_between({0, 0, 1}, normal_cell),
            glm::dvec3(1.0));
    const int n = add_node(node);
    const glm::dmat4 b2n = building_to_node(n);

    // Corners counter-clockwise about the from->to normal (the loader orients by volumes anyway).
    std::vector<glm::dvec3> corners{o.point(o.u0, o.v0), o.point(o.u1, o.v0), o.point(o.u1, o.v1), o.point(o.u0, o.v1)};
    if (glm::dot(glm::cross(corners[1] - corners[0], corners[2] - corners[0]), o.normal) < 0.0)
      std::swap(corners[1], corners[3]);
    MeshDesc mesh;
    mesh.name = o.name;
    mesh.base_color = {1.0f, 0.8f, 0.2f, 0.0f};
    for (const glm::dvec3& p : corners) mesh.positions.emplace_back(b2n * glm::dvec4(p, 1.0));
    mesh.indices = {0, 1, 2, 0, 2, 3};
    scene.nodes[size_t(n)].mesh = add_mesh(std::move(mesh));
  }
};

}  // namespace

glm::dmat4 node_world_matrix(const SceneDesc& scene, int index) {
  glm::dmat4 m(1.0);
  for (int i = index; i >= 0; i = scene.nodes[size_t(i)].parent) m = local_matrix(scene.nodes[size_t(i)]) * m;
  return m;
}

SceneDesc assemble_scene(const BuildingPlan& plan) {
  Assembler a{plan,
              {},
              building_to_world(plan),
              std::vector<int>(plan.rooms.size(), -1),
              std::vector<int>(plan.rooms.size(), -1)};
  a.scene.meshes = plan.meshes;
  for (size_t r = 0; r < plan.rooms.size(); ++r) a.add_cell(int(r));
  for (const InstancePlan& inst : plan.instances) {
    const int node = a.add_rigid_child(inst.name, a.rigid_node[size_t(inst.room)], inst.position, inst.rotation);
    a.scene.nodes[size_t(node)].mesh = inst.mesh;
  }
  for (const LightPlan& light : plan.lights) {
    const int node =
        a.add_rigid_child(light.light.name, a.rigid_node[size_t(light.room)], light.position, light.rotation);
    a.scene.lights.push_back(light.light);
    a.scene.nodes[size_t(node)].light = int(a.scene.lights.size()) - 1;
  }
  for (size_t i = 0; i < plan.openings.size(); ++i) a.add_portal(i);

  for (Timeline timeline : plan.timelines) {
    for (TimelineKey& key : timeline.keys) {
      key.eye_world = glm::vec3(a.to_world * glm::dvec4(glm::dvec3(key.eye_world), 1.0));
      key.target_world = glm::vec3(a.to_world * glm::dvec4(glm::dvec3(key.target_world), 1.0));
    }
    for (TimelineInstanceKey& key : timeline.instance_keys) {  // carried objects: building -> world
      if (key.has_translation)
        key.translation_world = glm::vec3(a.to_world * glm::dvec4(glm::dvec3(key.translation_world), 1.0));
      if (key.has_rotation) {  // a turn of the instance as placed: the same turn seen in world axes
        const glm::vec4& r = key.rotation_xyzw;
        const glm::dquat b = plan.building_rotation;
        const glm::dquat q = b * glm::dquat(r.w, r.x, r.y, r.z) * glm::inverse(b);
        key.rotation_xyzw = glm::vec4(float(q.x), float(q.y), float(q.z), float(q.w));
      }
    }
    a.scene.timelines.push_back(std::move(timeline));
  }
  return std::move(a.scene);
}

}  // namespace lintel::gen
