// export_rooms: a Lintel World written back in the rooms convention (see rooms_import.h), so that
// a scene can be edited in a tool that knows only node names. Cells become root '-room' nodes with
// their frames; a cell frame with a non-uniform scale gets a child that undoes the scale, and the
// instances and lights hang from it with rigid transforms (TRS cannot hold a sheared child).
#include "write/mesh_desc_of.h"
#include "rooms/rooms_assemble.h"
#include "rooms/rooms_trs.h"

#include <lintel/rooms_import.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace lintel {
namespace {

glm::dquat rotation_from_minus_z(const glm::dvec3& direction) {
  const glm::dvec3 from(0.0, 0.0, -1.0);
  const glm::dvec3 to = glm::normalize(direction);
  const double w = 1.0 + glm::dot(from, to);
  if (w < 1e-12) return glm::dquat(0.0, 1.0, 0.0, 0.0);  // opposite: half a turn about X
  const glm::dvec3 axis = glm::cross(from, to);
  return glm::normalize(glm::dquat(w, axis.x, axis.y, axis.z));
}

Status plain_name(const std::string& name, const std::string& what) {
  if (rooms::role_of_name(name).role == rooms::Role::Plain) return {};
  return Status::unsupported(
      "export rooms: " + what + " '" + name +
      "' ends in a rooms suffix (-room, -portal, -mirror, -bound); importing it back would change its role");
}

Status add_child(SceneDesc& scene, int parent, const std::string& name, const glm::dmat4& local, NodeDesc node) {
  node.name = name;
  node.parent = parent;
  if (!rooms::set_trs_from_matrix(local, node))
    return Status::unsupported("export rooms: node '" + name + "': its transform relative to its room is sheared");
  scene.nodes.push_back(std::move(node));
  return {};
}

MeshDesc bound_mesh(const Cell& cell) {
  MeshDesc mesh;
  mesh.name = cell.name + " bound";
  if (!cell.volume_triangles_cell.empty()) {
    mesh.positions = cell.volume_triangles_cell;
    for (uint32_t i = 0; i < mesh.positions.size(); ++i) mesh.indices.push_back(i);
    return mesh;
  }
  const Aabb& b = cell.volume_box_cell;
  for (int c = 0; c < 8; ++c)
    mesh.positions.emplace_back((c & 1) ? b.max.x : b.min.x, (c & 2) ? b.max.y : b.min.y, (c & 4) ? b.max.z : b.min.z);
  mesh.indices = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                  2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  return mesh;
}

Status export_cell(const World& world, const Cell& cell, SceneDesc& scene) {
  const glm::dmat4 cell_to_world(cell.cell_to_world);
  NodeDesc room;
  room.name = cell.name + kRoomSuffix;
  room.mesh = cell.shell_mesh;
  if (!rooms::set_trs_from_matrix(cell_to_world, room))
    return Status::unsupported("export rooms: cell '" + cell.name + "': its frame is sheared");
  const int room_index = int(scene.nodes.size());
  scene.nodes.push_back(room);

  NodeDesc bound;
  bound.mesh = int(scene.meshes.size());
  scene.meshes.push_back(bound_mesh(cell));
  if (Status s = add_child(scene, room_index, cell.name + kBoundSuffix, glm::dmat4(1.0), bound); !s) return s;

  // Instances and lights hang from a rigid frame: the room's rotation and translation only.
  int frame_index = room_index;
  glm::dmat4 frame_to_world = cell_to_world;
  if (glm::any(glm::notEqual(room.scale, glm::vec3(1.0f)))) {
    const glm::dvec3 unscale = 1.0 / glm::dvec3(room.scale);
    glm::dmat4 local(1.0);
    local[0][0] = unscale.x;
    local[1][1] = unscale.y;
    local[2][2] = unscale.z;
    frame_index = int(scene.nodes.size());
    if (Status s = add_child(scene, room_index, cell.name + " frame", local, NodeDesc{}); !s) return s;
    frame_to_world = cell_to_world * local;
  }
  const glm::dmat4 world_to_frame = glm::inverse(frame_to_world);
  for (uint32_t i : cell.instances) {
    const Instance& instance = world.instances[i];
    if (Status s = plain_name(instance.name, "instance"); !s) return s;
    NodeDesc node;
    node.mesh = int(instance.mesh);
    if (Status s =
            add_child(scene, frame_index, instance.name, world_to_frame * glm::dmat4(instance.mesh_to_world), node);
        !s)
      return s;
  }
  for (uint32_t i : cell.lights) {
    const Light& light = world.lights[i];
    if (Status s = plain_name(light.name, "light"); !s) return s;
    NodeDesc node;
    node.light = int(scene.lights.size());
    scene.lights.push_back({light.name, light.type, light.color, light.intensity, light.range, light.inner_cone_rad,
                            light.outer_cone_rad});
    const glm::dmat4 light_to_world = glm::translate(glm::dmat4(1.0), glm::dvec3(light.position_world)) *
                                      glm::mat4_cast(rotation_from_minus_z(glm::dvec3(light.direction_world)));
    if (Status s = add_child(scene, frame_index, light.name, world_to_frame * light_to_world, node); !s) return s;
  }
  return {};
}

}  // namespace

Status export_rooms(const World& world, SceneDesc& out) {
  out = {};
  SceneDesc scene;
  for (const Mesh& mesh : world.meshes) scene.meshes.push_back(mesh_desc_of(mesh));
  scene.textures = world.textures;
  for (const Cell& cell : world.cells)
    if (Status s = export_cell(world, cell, scene); !s) return s;
  for (const Portal& portal : world.portals) {
    if (portal.link == PortalLinkKind::Teleport)
      return Status::unsupported("export rooms: portal '" + portal.name +
                                 "' is a teleport; the rooms convention has no teleports (docs/rooms.md)");
    // The polygon winds from `from` into `to`: what the importer reads as "behind" and "in front".
    // A mirror's normal points out of its room, into the wall: turned over, its face looks into
    // the room it reflects, as the convention has it.
    const bool mirror = portal.link == PortalLinkKind::Mirror;
    NodeDesc node;
    node.name = portal.name + (mirror ? kMirrorSuffix : portal.two_way ? kPortalSuffix : kOneWayPortalSuffix);
    node.mesh = int(scene.meshes.size());
    MeshDesc polygon;
    polygon.name = portal.name;
    polygon.positions = portal.polygon_world;
    if (mirror) std::reverse(polygon.positions.begin(), polygon.positions.end());
    for (uint32_t i = 1; i + 1 < polygon.positions.size(); ++i)
      polygon.indices.insert(polygon.indices.end(), {0, i, i + 1});
    scene.meshes.push_back(std::move(polygon));
    scene.nodes.push_back(std::move(node));
  }
  out = std::move(scene);
  return {};
}

}  // namespace lintel
