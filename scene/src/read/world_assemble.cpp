// Cells, shell and instance meshes, volumes, instances and draw groups. A node's role follows its
// tag: a cell's own mesh is its shell, a volume node's mesh its volume, a portal node's mesh its
// polygon; every other mesh node below a cell is an instance of that cell.
#include "read/world_assemble.h"

#include "read/closed_mesh.h"
#include "read/mesh_read.h"

#include <tiny_gltf.h>

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <map>

namespace lintel::scene_read {

glm::mat4 to_float(const glm::dmat4& m) { return glm::mat4(m); }

glm::dvec3 transform_point(const glm::dmat4& m, const glm::vec3& p) {
  return glm::dvec3(m * glm::dvec4(glm::dvec3(p), 1.0));
}

namespace {

using Kind = NodeTag::Kind;

bool finite_as_float(const glm::dmat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!(std::fabs(m[c][r]) <= double(FLT_MAX))) return false;
  return true;
}

Status assemble_cells(AssemblyState& s, World& world) {
  s.cell_of_node.assign(s.nodes.size(), -1);
  for (size_t n = 0; n < s.nodes.size(); ++n) {
    const NodeRecord& node = s.nodes[n];
    if (!s.graph.in_scene[n] || node.tag.kind != Kind::Cell) continue;
    const auto [it, inserted] = s.cell_by_name.emplace(node.tag.cell_name, uint32_t(world.cells.size()));
    if (!inserted)
      return s.ctx.fail(node.element, "duplicate cell name '" + one_line(node.tag.cell_name, 64) + "' (also " +
                                          s.nodes[size_t(world.cells[it->second].node)].element + ")");
    const glm::dmat4& to_world = s.graph.world[n];
    // Columns' lengths bound the determinant; a much smaller one means a collapsed axis.
    const glm::dmat3 linear(to_world);
    const double det = glm::determinant(linear);
    const double scale = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
    // A mirrored cell would turn its shell, volume and portal sides inside out; its instances may
    // mirror (assemble_instances), the cell frame may not.
    if (det < 0.0)
      return s.ctx.fail(node.element,
                        "cell transform mirrors (negative scale or determinant): only instances may be mirrored; "
                        "mirror the cell's mesh instead");
    if (!(det > 1e-9 * scale)) return s.ctx.fail(node.element, "cell transform is degenerate (near-zero determinant)");
    const glm::dmat4 to_cell = glm::inverse(to_world);
    if (!finite_as_float(to_cell)) return s.ctx.fail(node.element, "cell transform cannot be inverted in float range");
    Cell cell;
    cell.name = node.tag.cell_name;
    cell.node = int(n);
    cell.cell_to_world = to_float(to_world);
    cell.world_to_cell = to_float(to_cell);
    s.cell_of_node[n] = int(world.cells.size());
    world.cells.push_back(std::move(cell));
  }
  return {};
}

// The nearest cell at or above node n (a cell node owns itself), as a cell index, or -1.
int owning_cell(const AssemblyState& s, size_t n) {
  if (s.cell_of_node[n] >= 0) return s.cell_of_node[n];
  const int ancestor = s.graph.cell_ancestor[n];
  return ancestor >= 0 ? s.cell_of_node[size_t(ancestor)] : -1;
}

// glTF mesh index -> its parts in World::meshes (read_drawn_meshes).
using MeshSlots = std::map<int, std::vector<uint32_t>>;

bool is_instance_node(const AssemblyState& s, size_t n) {
  return s.graph.in_scene[n] && s.nodes[n].mesh >= 0 && s.nodes[n].tag.kind == Kind::None;
}

// Reads every mesh that a shell or an instance draws, in glTF index order, into world.meshes;
// returns the glTF index -> world.meshes indices map (one per material the mesh uses:
// read_mesh_parts). Parts without triangles are left out (a mesh with none: the nodes using it
// are then warned about and skipped). Their base colour textures fill world.textures, in order of
// first use.
Status read_drawn_meshes(AssemblyState& s, World& world, MeshSlots& mesh_slot) {
  std::map<int, bool> used;  // ordered: World::meshes follows glTF mesh order
  for (size_t n = 0; n < s.nodes.size(); ++n) {
    if (!s.graph.in_scene[n] || s.nodes[n].mesh < 0) continue;
    const bool shell = s.nodes[n].tag.kind == Kind::Cell;
    const bool instance = is_instance_node(s, n) && owning_cell(s, n) >= 0;
    if (shell || instance) used[s.nodes[n].mesh] = true;
  }
  TextureTable textures(s.ctx, s.model, s.base_dir, world.textures);
  std::vector<Mesh> parts;
  for (const auto& [index, unused] : used) {
    if (Status st = read_mesh_parts(s.ctx, s.model, index, s.budget, textures, parts); !st) return st;
    std::vector<uint32_t> slots;
    for (Mesh& mesh : parts) {
      if (mesh.indices.empty()) continue;
      slots.push_back(uint32_t(world.meshes.size()));
      world.meshes.push_back(std::move(mesh));
    }
    if (slots.empty()) {
      s.ctx.warn(describe("mesh", size_t(index), s.model.meshes[size_t(index)].name),
                 "has no triangles; the nodes using it are skipped");
      continue;
    }
    mesh_slot[index] = std::move(slots);
  }
  return {};
}

Status assemble_volumes(AssemblyState& s, World& world) {
  std::vector<int> volume_node(world.cells.size(), -1);
  for (size_t n = 0; n < s.nodes.size(); ++n) {
    const NodeRecord& node = s.nodes[n];
    if (!s.graph.in_scene[n] || node.tag.kind != Kind::Volume) continue;
    if (node.mesh < 0) return s.ctx.fail(node.element, "volume node has no mesh");
    const int cell_index = owning_cell(s, n);
    if (cell_index < 0) return s.ctx.fail(node.element, "volume node is not below a cell");
    if (volume_node[size_t(cell_index)] >= 0)
      return s.ctx.fail(node.element, "cell '" + world.cells[size_t(cell_index)].name + "' already has a volume (" +
                                          s.nodes[size_t(volume_node[size_t(cell_index)])].element + ")");
    volume_node[size_t(cell_index)] = int(n);
    Mesh mesh;
    if (Status st = read_mesh(s.ctx, s.model, node.mesh, s.budget, nullptr, mesh); !st) return st;
    if (mesh.indices.empty()) return s.ctx.fail(node.element, "volume mesh has no triangles");
    Cell& cell = world.cells[size_t(cell_index)];
    const glm::dmat4 node_to_cell = glm::inverse(s.graph.world[size_t(cell.node)]) * s.graph.world[n];
    // A mirrored volume node: each triangle's last two corners swapped keeps its faces outward.
    const bool mirrored = glm::determinant(glm::dmat3(node_to_cell)) < 0.0;
    cell.volume_triangles_cell.reserve(mesh.indices.size());
    for (size_t k = 0; k < mesh.indices.size(); ++k) {
      const size_t corner = k % 3;
      const uint32_t i = mirrored && corner != 0 ? mesh.indices[k - corner + 3 - corner] : mesh.indices[k];
      const glm::vec3 p(transform_point(node_to_cell, mesh.positions[i]));
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        return s.ctx.fail(node.element, "volume vertex is not finite in cell space");
      cell.volume_triangles_cell.push_back(p);
      cell.volume_box_cell.extend(p);
    }
    if (const size_t open = count_open_edges(cell.volume_triangles_cell); open > 0)
      return s.ctx.fail(node.element, "volume mesh is not closed (" + std::to_string(open) + " open edges)");
  }
  return {};
}

// An instance of `mesh` placed by node n's world matrix in cell `cell_index`.
void add_instance(AssemblyState& s, World& world, size_t n, int cell_index, uint32_t mesh) {
  Instance instance;
  instance.name = s.nodes[n].name;
  instance.node = int(n);
  instance.cell = uint32_t(cell_index);
  instance.mesh = mesh;
  instance.mesh_to_world = to_float(s.graph.world[n]);
  // A mirroring transform keeps its mesh: as glTF 2.0 says, its front faces are then clockwise,
  // the rule every reader applies (the renderer's kFaceMirrored, GI, path tracer, ray cast).
  world.instances.push_back(std::move(instance));  // bounds_world, Cell::instances: finalize_world()
}

// The shell is the first part of the cell node's mesh; its other parts (other materials) are
// instances of the cell placed by the cell node, so every reader draws them with their own looks.
Status assemble_shells(AssemblyState& s, World& world, const MeshSlots& mesh_slot) {
  for (size_t c = 0; c < world.cells.size(); ++c) {
    Cell& cell = world.cells[c];
    const NodeRecord& node = s.nodes[size_t(cell.node)];
    Aabb shell_bounds;
    if (node.mesh >= 0) {
      const auto slot = mesh_slot.find(node.mesh);
      if (slot != mesh_slot.end()) {
        cell.shell_mesh = int(slot->second.front());
        for (size_t k = 0; k < slot->second.size(); ++k) {
          if (k > 0) add_instance(s, world, size_t(cell.node), int(c), slot->second[k]);
          shell_bounds.extend(world.meshes[slot->second[k]].bounds_mesh);
        }
      }
    }
    if (!cell.volume_box_cell.empty()) continue;  // a volume node gave it
    if (cell.shell_mesh < 0)
      return s.ctx.fail(node.element, "cell '" + cell.name + "' has neither a shell mesh nor a volume node");
    // The shell is the cell node's own mesh, so mesh space is cell space.
    cell.volume_box_cell = shell_bounds;
  }
  return {};
}

void assemble_instances(AssemblyState& s, World& world, const MeshSlots& mesh_slot) {
  for (size_t n = 0; n < s.nodes.size(); ++n) {
    if (!is_instance_node(s, n)) continue;
    const NodeRecord& node = s.nodes[n];
    const int cell_index = owning_cell(s, n);
    if (cell_index < 0) {
      s.ctx.warn(node.element, "mesh node outside any cell (ignored)");
      continue;
    }
    const auto slot = mesh_slot.find(node.mesh);
    if (slot == mesh_slot.end()) continue;  // its mesh has no triangles: warned once per mesh
    // One instance per part: a mesh of several materials is drawn as several, one node's name.
    for (const uint32_t mesh : slot->second) add_instance(s, world, n, cell_index, mesh);
  }
  // One draw group per drawn mesh that has instances, in World::meshes (= glTF mesh, then
  // material) order; instances ascending.
  std::vector<uint8_t> drawn(world.meshes.size(), 0);
  for (const Instance& instance : world.instances) drawn[instance.mesh] = 1;
  std::vector<uint32_t> group_of_mesh(world.meshes.size(), 0);
  for (uint32_t m = 0; m < world.meshes.size(); ++m)
    if (drawn[m]) {
      group_of_mesh[m] = uint32_t(world.groups.size());
      world.groups.push_back(DrawGroup{m, {}});
    }
  for (Instance& instance : world.instances) instance.group = group_of_mesh[instance.mesh];  // lists: finalize_world()
}

}  // namespace

Status assemble_world(AssemblyState& s, World& world) {
  if (Status st = assemble_cells(s, world); !st) return st;
  MeshSlots mesh_slot;
  if (Status st = read_drawn_meshes(s, world, mesh_slot); !st) return st;
  if (Status st = assemble_volumes(s, world); !st) return st;
  if (Status st = assemble_shells(s, world, mesh_slot); !st) return st;
  assemble_instances(s, world, mesh_slot);
  if (Status st = assemble_portals(s, world); !st) return st;
  if (Status st = assemble_lights(s, world); !st) return st;
  std::vector<uint8_t> has_portal(world.cells.size(), 0);
  for (const Portal& portal : world.portals) has_portal[portal.from] = has_portal[portal.to] = 1;
  for (size_t c = 0; c < world.cells.size(); ++c) {
    const Cell& cell = world.cells[c];
    const std::string& element = s.nodes[size_t(cell.node)].element;
    if (!has_portal[c]) s.ctx.warn(element, "cell '" + cell.name + "' has no portals");
    // A see-through shell (a fenced yard, a grated wall) shows what lies beyond it, but the
    // visibility flood crosses into other cells through portals only: say so once per cell.
    const Mesh::AlphaMode shell_alpha =
        cell.shell_mesh >= 0 ? world.meshes[size_t(cell.shell_mesh)].alpha_mode : Mesh::AlphaMode::Opaque;
    if (shell_alpha == Mesh::AlphaMode::Mask)
      s.ctx.warn(element, "cell '" + cell.name +
                              "' has a cut-out shell (alphaMode MASK): other cells seen through it are drawn only "
                              "where a portal leads to them");
    if (shell_alpha == Mesh::AlphaMode::Blend)
      s.ctx.warn(element, "cell '" + cell.name +
                              "' has a see-through shell (alphaMode BLEND): other cells seen through it are drawn "
                              "only where a portal leads to them");
  }
  return {};
}

}  // namespace lintel::scene_read
