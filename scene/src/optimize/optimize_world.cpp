// optimize_world / optimize_scene (lintel/optimize.h): a World written back as a SceneDesc with
// the merge plan's cells. Every cell node is a root node with its first part's frame; what hangs
// below it (volume, instances, lights, portals out of it) is placed by world matrices, so any
// source hierarchy flattens to cell -> child.
#define GLM_ENABLE_EXPERIMENTAL  // glm::rotation (gtx/quaternion), the light's turn from -Z
#include <lintel/cell_locate.h>
#include <lintel/optimize.h>
#include <lintel/scene_io.h>

#include "write/mesh_desc_of.h"
#include "optimize/cell_merge_plan.h"
#include "rooms/rooms_trs.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/quaternion.hpp>

#include <map>

namespace lintel {
namespace {

// Appends `mesh` taken by `to_cell` (mesh space -> merged cell space) to `out`; with `tint`, its
// vertex colours (white where it has none) times `tint`.
void append_mesh(const Mesh& mesh, const glm::dmat4& to_cell, const glm::vec4* tint, MeshDesc& out) {
  const uint32_t base = uint32_t(out.positions.size());
  const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(to_cell)));
  for (const glm::vec3& p : mesh.positions) out.positions.push_back(glm::vec3(to_cell * glm::dvec4(p, 1.0)));
  for (const glm::vec3& nrm : mesh.normals)
    out.normals.push_back(glm::vec3(glm::normalize(normal_matrix * glm::dvec3(nrm))));
  out.uvs.insert(out.uvs.end(), mesh.uvs.begin(), mesh.uvs.end());
  if (tint)
    for (size_t v = 0; v < mesh.positions.size(); ++v)
      out.colors.push_back(*tint * (v < mesh.colors.size() ? mesh.colors[v] : glm::vec4(1.0f)));
  for (uint32_t i : mesh.indices) out.indices.push_back(base + i);
}

// The cell's closed volume in its own space, 3 points per triangle (its box when it has none).
std::vector<glm::vec3> volume_triangles_cell(const Cell& cell) {
  if (!cell.volume_triangles_cell.empty()) return cell.volume_triangles_cell;
  std::vector<glm::vec3> out;
  const Aabb& b = cell.volume_box_cell;
  glm::vec3 c[8];
  for (int i = 0; i < 8; ++i)
    c[i] = {(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z};
  static constexpr int kQuads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : kQuads)
    for (int k : {q[0], q[1], q[2], q[0], q[2], q[3]}) out.push_back(c[k]);
  return out;
}

class SceneWriter {
 public:
  SceneWriter(const World& world, const optimize::CellMergePlan& plan) : world_(world), plan_(plan) {}

  Status write(SceneDesc& out) {
    scene_.textures = world_.textures;
    scene_.timelines = world_.timelines;
    scene_.environment = environment_desc_of(world_);  // every light is kept (write_cell)
    cell_node_.assign(plan_.groups.size(), -1);
    world_to_cell_.resize(plan_.groups.size());
    for (uint32_t g = 0; g < plan_.groups.size(); ++g)
      if (Status s = write_cell(g); !s) return s;
    for (uint32_t p = 0; p < world_.portals.size(); ++p) write_portal(p);
    out = std::move(scene_);
    return {};
  }

 private:
  int kept_mesh(uint32_t mesh) {
    auto [it, added] = mesh_index_.try_emplace(mesh, int(scene_.meshes.size()));
    if (added) scene_.meshes.push_back(mesh_desc_of(world_.meshes[mesh]));
    return it->second;
  }

  Status add_child(int parent, const std::string& name, const glm::dmat4& local, NodeDesc node) {
    node.name = name;
    node.parent = parent;
    if (!rooms::set_trs_from_matrix(local, node))
      return Status::unsupported("optimize: node '" + name + "': its transform relative to its merged cell is sheared");
    scene_.nodes.push_back(std::move(node));
    return {};
  }

  Status write_cell(uint32_t g) {
    const std::vector<uint32_t>& parts = plan_.groups[g];
    const Cell& first = world_.cells[parts[0]];
    NodeDesc node;
    node.name = first.name;
    node.kind = NodeDesc::Kind::Cell;
    node.cell_name = first.name;
    if (!rooms::set_trs_from_matrix(glm::dmat4(first.cell_to_world), node))
      return Status::unsupported("optimize: cell '" + first.name + "': its frame is sheared");
    // The frame as the loader will rebuild it from TRS, so that parts land where they were.
    const glm::dmat4 cell_to_world = glm::translate(glm::dmat4(1.0), glm::dvec3(node.translation)) *
                                     glm::mat4_cast(glm::dquat(node.rotation)) *
                                     glm::scale(glm::dmat4(1.0), glm::dvec3(node.scale));
    const glm::dmat4 world_to_cell = glm::inverse(cell_to_world);
    world_to_cell_[g] = world_to_cell;
    if (parts.size() == 1) {
      if (first.shell_mesh >= 0) node.mesh = kept_mesh(uint32_t(first.shell_mesh));
    } else {
      MeshDesc shell;
      // Parts of different colours (Doom sectors tinted by light level) or with vertex colours:
      // each part's base colour goes into its vertices' colours and the shell's is white, so that
      // every part keeps its own looks (the merged mesh has one material).
      bool tinted = false;
      const Mesh* seen = nullptr;
      for (uint32_t c : parts) {
        if (world_.cells[c].shell_mesh < 0) continue;
        const Mesh& mesh = world_.meshes[size_t(world_.cells[c].shell_mesh)];
        tinted = tinted || !mesh.colors.empty() || (seen && seen->base_color != mesh.base_color);
        seen = &mesh;
      }
      for (uint32_t c : parts) {
        const Cell& cell = world_.cells[c];
        if (cell.shell_mesh < 0) continue;
        const Mesh& mesh = world_.meshes[size_t(cell.shell_mesh)];
        if (shell.positions.empty()) {
          shell.name = first.name + " merged shell";
          shell.texture = mesh.base_color_texture;
          shell.sampler = mesh.base_color_sampler;
        }
        shell.double_sided = mesh.double_sided;
        shell.alpha_mode = mesh.alpha_mode;  // the same for every part (cell_merge_plan.cpp)
        shell.alpha_cutoff = mesh.alpha_cutoff;
        shell.emissive = mesh.emissive;  // also the same for every part
        shell.emissive_texture = mesh.emissive_texture;
        shell.emissive_sampler = mesh.emissive_sampler;
        // Tints go into the vertex colours; a cut-out keeps its base alpha (the same for every
        // part), which its coverage uses.
        const bool cut_out = mesh.alpha_mode == Mesh::AlphaMode::Mask;
        shell.base_color = tinted ? glm::vec4(glm::vec3(1.0f), cut_out ? mesh.base_color.a : 1.0f) : mesh.base_color;
        // Normals and uvs only when every part has them (the file wants one per position or none).
        append_mesh(mesh, world_to_cell * glm::dmat4(cell.cell_to_world), tinted ? &mesh.base_color : nullptr, shell);
      }
      if (shell.normals.size() != shell.positions.size()) shell.normals.clear();
      if (shell.uvs.size() != shell.positions.size())
        shell.uvs.clear(), shell.texture = -1, shell.emissive_texture = -1;
      if (!shell.positions.empty()) {
        node.mesh = int(scene_.meshes.size());
        scene_.meshes.push_back(std::move(shell));
      }
    }
    const int index = int(scene_.nodes.size());
    cell_node_[g] = index;
    scene_.nodes.push_back(node);

    // The volume: a single part's own, else every part's closed volume (a union of closed pieces).
    if (parts.size() > 1 || !first.volume_triangles_cell.empty()) {
      MeshDesc volume;
      volume.name = first.name + " volume";
      volume.base_color = {0.3f, 0.6f, 1.0f, 0.0f};
      for (uint32_t c : parts) {
        const Cell& cell = world_.cells[c];
        const glm::dmat4 to_cell = world_to_cell * glm::dmat4(cell.cell_to_world);
        for (const glm::vec3& p : volume_triangles_cell(cell)) {
          volume.indices.push_back(uint32_t(volume.positions.size()));
          volume.positions.push_back(parts.size() == 1 ? p : glm::vec3(to_cell * glm::dvec4(p, 1.0)));
        }
      }
      NodeDesc vol;
      vol.kind = NodeDesc::Kind::Volume;
      vol.mesh = int(scene_.meshes.size());
      scene_.meshes.push_back(std::move(volume));
      if (Status s = add_child(index, first.name + "_volume", glm::dmat4(1.0), vol); !s) return s;
    }
    // Instances and lights hang from a rigid frame: a non-uniformly scaled cell frame gets a child
    // that undoes the scale (TRS cannot hold the shear a rotated child would need below it).
    int frame = index;
    glm::dmat4 world_to_frame = world_to_cell;
    if (node.scale.x != node.scale.y || node.scale.y != node.scale.z) {
      NodeDesc unscale;
      unscale.scale = 1.0f / node.scale;
      frame = int(scene_.nodes.size());
      if (Status s =
              add_child(index, first.name + " frame", glm::scale(glm::dmat4(1.0), glm::dvec3(unscale.scale)), unscale);
          !s)
        return s;
      world_to_frame = glm::scale(glm::dmat4(1.0), glm::dvec3(node.scale)) * world_to_cell;
    }
    for (uint32_t c : parts) {
      for (uint32_t i : world_.cells[c].instances) {
        const Instance& instance = world_.instances[i];
        NodeDesc child;
        child.mesh = kept_mesh(instance.mesh);
        if (Status s = add_child(frame, instance.name, world_to_frame * glm::dmat4(instance.mesh_to_world), child); !s)
          return s;
      }
      for (uint32_t i : world_.cells[c].lights) {
        const Light& light = world_.lights[i];
        NodeDesc child;
        child.light = int(scene_.lights.size());
        scene_.lights.push_back({light.name, light.type, light.color, light.intensity, light.range,
                                 light.inner_cone_rad, light.outer_cone_rad});
        const glm::dquat turn =
            glm::rotation(glm::dvec3(0.0, 0.0, -1.0), glm::normalize(glm::dvec3(light.direction_world)));
        const glm::dmat4 light_to_world =
            glm::translate(glm::dmat4(1.0), glm::dvec3(light.position_world)) * glm::mat4_cast(turn);
        if (Status s = add_child(frame, light.name, world_to_frame * light_to_world, child); !s) return s;
      }
    }
    return {};
  }

  // A portal between two merged cells hangs below its `from` cell, its polygon in that cell's space.
  void write_portal(uint32_t p) {
    const Portal& portal = world_.portals[p];
    const uint32_t from = plan_.group_of_cell[portal.from], to = plan_.group_of_cell[portal.to];
    if (from == to && !portal.linked()) return;  // inside a merged cell (a mirror's from is its to)
    MeshDesc mesh;
    mesh.name = portal.name;
    mesh.base_color = {1.0f, 0.8f, 0.2f, 0.0f};
    const bool same_frame = plan_.groups[from].size() == 1;
    for (size_t i = 0; i < portal.polygon_world.size(); ++i)
      mesh.positions.push_back(same_frame ? portal.polygon_from_cell[i]
                                          : glm::vec3(world_to_cell_[from] * glm::dvec4(portal.polygon_world[i], 1.0)));
    for (uint32_t i = 1; i + 1 < mesh.positions.size(); ++i) mesh.indices.insert(mesh.indices.end(), {0, i, i + 1});
    NodeDesc node;
    node.name = portal.name;
    node.parent = cell_node_[from];
    node.kind = NodeDesc::Kind::Portal;
    node.portal_from = world_.cells[plan_.groups[from][0]].name;
    node.portal_to = world_.cells[plan_.groups[to][0]].name;
    node.two_way = portal.two_way;
    node.portal_open = portal.open_from_to && portal.open_to_from;
    node.portal_mirror = portal.link == PortalLinkKind::Mirror;
    if (portal.link == PortalLinkKind::Teleport) {  // by its target's name, or its matrix
      if (portal.link_target >= 0)
        node.portal_link = world_.portals[size_t(portal.link_target)].name;
      else
        node.portal_link_matrix = portal.link_world;
    }
    node.mesh = int(scene_.meshes.size());
    scene_.meshes.push_back(std::move(mesh));
    scene_.nodes.push_back(std::move(node));
  }

  const World& world_;
  const optimize::CellMergePlan& plan_;
  SceneDesc scene_;
  std::map<uint32_t, int> mesh_index_;  // World mesh -> SceneDesc mesh, for meshes kept as they are
  std::vector<int> cell_node_;
  std::vector<glm::dmat4> world_to_cell_;
};

}  // namespace

Status optimize_world(const World& world, const OptimizeOptions& options, SceneDesc& out, OptimizeReport* report) {
  out = {};
  const optimize::CellMergePlan plan = optimize::plan_cell_merges(world, options);
  SceneDesc scene;
  if (Status s = SceneWriter(world, plan).write(scene); !s) return s;
  if (report) {
    *report = {};
    report->cells_before = uint32_t(world.cells.size());
    report->cells_after = uint32_t(plan.groups.size());
    report->portals_before = uint32_t(world.portals.size());
    for (const NodeDesc& node : scene.nodes) report->portals_after += node.kind == NodeDesc::Kind::Portal;
    report->open_wall_merges = plan.open_wall_merges;
    report->sliver_merges = plan.sliver_merges;
    report->closable_portals = plan.closable_portals;
    report->merged_cell_of = plan.group_of_cell;
  }
  out = std::move(scene);
  return {};
}

Status optimize_scene(const SceneDesc& scene, const std::string& label, const OptimizeOptions& options, SceneDesc& out,
                      OptimizeReport* report) {
  out = {};
  World world;
  if (Status s = build_world(scene, label, world); !s) return s;
  return optimize_world(world, options, out, report);
}

}  // namespace lintel
