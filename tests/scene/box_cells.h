// Shared by the scene tests that hand-build scenes: an axis-aligned box mesh, a box cell (shell
// and volume, identity frames) and an axis-aligned portal between two cells.
#pragma once

#include <lintel/scene_io.h>

#include <glm/glm.hpp>

#include <string>
#include <utility>

namespace lintel::test {

// The closed box [lo, hi], faces outward, no uvs.
inline MeshDesc box_mesh(const std::string& name, glm::vec3 lo, glm::vec3 hi) {
  MeshDesc mesh;
  mesh.name = name;
  for (int c = 0; c < 8; ++c)
    mesh.positions.emplace_back(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z);
  mesh.indices = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                  2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  return mesh;
}

// The box [lo, hi] with its faces turned inwards: a closed room's single-sided shell, seen from inside.
inline MeshDesc inward_box_mesh(const std::string& name, glm::vec3 lo, glm::vec3 hi) {
  MeshDesc mesh = box_mesh(name, lo, hi);
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
  return mesh;
}

// A node `name` holding the box [lo, hi] (box_mesh) inside the cell node `cell`: an instance.
inline void add_box_instance(SceneDesc& scene, int cell, const std::string& name, glm::vec3 lo, glm::vec3 hi) {
  NodeDesc node;
  node.name = name;
  node.parent = cell;
  node.mesh = int(scene.meshes.size());
  scene.meshes.push_back(box_mesh(name, lo, hi));
  scene.nodes.push_back(node);
}

// A cell node `name` with `shell` as its mesh and the box [lo, hi] as its volume; the cell's node index.
inline int add_box_cell(SceneDesc& scene, const std::string& name, glm::vec3 lo, glm::vec3 hi, MeshDesc shell) {
  NodeDesc cell;
  cell.name = cell.cell_name = name;
  cell.kind = NodeDesc::Kind::Cell;
  cell.mesh = int(scene.meshes.size());
  scene.meshes.push_back(std::move(shell));
  const int index = int(scene.nodes.size());
  scene.nodes.push_back(cell);
  NodeDesc volume;
  volume.name = name + "_volume";
  volume.parent = index;
  volume.kind = NodeDesc::Kind::Volume;
  volume.mesh = int(scene.meshes.size());
  scene.meshes.push_back(box_mesh(name + " volume", lo, hi));
  scene.nodes.push_back(volume);
  return index;
}

// A portal `from` -> `to` in the plane x = x0 over z in [z0, z1], y in [y0, y1].
inline void add_portal(SceneDesc& scene, const std::string& name, const std::string& from, const std::string& to,
                       float x0, float z0, float z1, float y0, float y1, bool open = true) {
  MeshDesc mesh;
  mesh.name = name;
  mesh.positions = {{x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}, {x0, y1, z0}};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  NodeDesc node;
  node.name = name;
  node.kind = NodeDesc::Kind::Portal;
  node.portal_from = from;
  node.portal_to = to;
  node.portal_open = open;
  node.mesh = int(scene.meshes.size());
  scene.meshes.push_back(mesh);
  scene.nodes.push_back(node);
}

// Three 1 x 3 x 2 m box cells in a row along +X, "s0", "s1", "s2", joined by open portals over
// their whole shared walls (open walls: optimize merges them unless their shells differ);
// style(k, shell) gives cell k's shell its looks.
template <class Style>
SceneDesc row_of_three_cells(Style style) {
  SceneDesc scene;
  for (int k = 0; k < 3; ++k) {
    const std::string name = "s" + std::to_string(k);
    const glm::vec3 lo(float(k), 0.0f, 0.0f), hi(float(k + 1), 3.0f, 2.0f);
    MeshDesc shell = box_mesh(name, lo, hi);
    style(k, shell);
    add_box_cell(scene, name, lo, hi, shell);
  }
  add_portal(scene, "p01", "s0", "s1", 1, 0, 2, 0.0f, 3);
  add_portal(scene, "p12", "s1", "s2", 2, 0, 2, 0.0f, 3);
  return scene;
}

}  // namespace lintel::test
