// Rooms convention -> Lintel SceneDesc (see rooms_assemble.h). Works in world space in double;
// the output keeps the file's hierarchy and transforms so that the loader, run on the result,
// finds the same world positions. Each fault names the input file and node.
#include "rooms/rooms_assemble.h"

#include "read/closed_mesh.h"
#include "read/mesh_read.h"
#include "read/portal_polygon.h"
#include "rooms/rooms_hull.h"
#include "rooms/rooms_portal.h"
#include "rooms/rooms_trs.h"
#include "rooms/rooms_volume.h"
#include "read/texture_read.h"
#include "write/mesh_desc_of.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <map>

namespace lintel::rooms {
namespace {

using scene_read::describe;
using scene_read::NodeRecord;
using scene_read::number_text;

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

glm::dvec3 apply(const glm::dmat4& m, const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }

struct Assembly {
  const scene_read::LoadContext& ctx;
  const tinygltf::Model& model;
  const std::vector<NodeRecord>& nodes;
  const scene_read::SceneGraph& graph;
  scene_read::ReadBudget budget;
  std::vector<Texture> textures;
  scene_read::TextureTable texture_table;
  std::vector<NameRole> roles;
  std::vector<uint32_t> order;       // in-scene nodes, parents first
  std::vector<int> room_of;          // node -> room index of the nearest room at or above it, or -1
  std::vector<uint32_t> room_nodes;  // room index -> node
  std::vector<int> bound_of_room;    // room index -> bound node, or -1
  // Volumes the importer computed (convex hull, or the box of a shell-less room), written as a
  // volume node below the room: triangles in the room's space, and the node's name suffix.
  std::vector<std::vector<glm::vec3>> computed_volume_room;
  std::vector<std::string> computed_volume_kind;
  std::vector<RoomVolume> volumes;
  std::vector<std::string> room_names;
  std::map<int, Mesh> geometry;                // glTF mesh -> positions/indices (no textures)
  std::map<int, std::vector<int>> drawn_mesh;  // glTF mesh -> SceneDesc meshes (add_drawn_mesh)

  Assembly(const scene_read::LoadContext& c, const tinygltf::Model& m, const std::vector<NodeRecord>& n,
           const scene_read::SceneGraph& g, const std::string& base_dir)
      : ctx(c), model(m), nodes(n), graph(g), texture_table(c, m, base_dir, textures) {}

  Status mesh_geometry(int mesh, const Mesh*& out) {
    auto it = geometry.find(mesh);
    if (it == geometry.end()) {
      Mesh read;
      if (Status s = scene_read::read_mesh(ctx, model, mesh, budget, nullptr, read); !s) return s;
      it = geometry.emplace(mesh, std::move(read)).first;
    }
    out = &it->second;
    return {};
  }
};

// Roles, the parent-first order, and the nearest room of every node.
Status classify_nodes(Assembly& a) {
  const size_t n_nodes = a.nodes.size();
  a.roles.resize(n_nodes);
  size_t outside = 0;
  for (size_t n = 0; n < n_nodes; ++n) {
    a.roles[n] = role_of_name(a.nodes[n].name);
    outside += a.graph.in_scene[n] ? 0 : 1;
    if (a.graph.in_scene[n] && a.nodes[n].tag.kind != scene_read::NodeTag::Kind::None)
      a.ctx.warn(a.nodes[n].element, "extras.lintel is ignored: the rooms importer reads roles from node names");
  }
  if (outside > 0) a.ctx.warn("", std::to_string(outside) + " nodes are not part of the scene (ignored)");
  std::vector<uint32_t> stack;
  for (size_t n = n_nodes; n-- > 0;)
    if (a.graph.in_scene[n] && a.graph.parent[n] < 0) stack.push_back(uint32_t(n));
  while (!stack.empty()) {  // the graph has no cycles (build_scene_graph checked)
    const uint32_t n = stack.back();
    stack.pop_back();
    a.order.push_back(n);
    const std::vector<uint32_t>& children = a.nodes[n].children;
    for (size_t c = children.size(); c-- > 0;) stack.push_back(children[c]);
  }
  a.room_of.assign(n_nodes, -1);
  std::map<std::string, uint32_t> room_by_name;
  for (uint32_t n : a.order) {
    const int parent = a.graph.parent[n];
    a.room_of[n] = parent >= 0 ? a.room_of[size_t(parent)] : -1;
    if (a.roles[n].role != Role::Room) continue;
    const std::string& name = a.roles[n].base;
    if (name.empty()) return a.ctx.fail(a.nodes[n].element, "room name is empty (the node is named only '-room')");
    if (auto [it, fresh] = room_by_name.emplace(name, n); !fresh)
      return a.ctx.fail(a.nodes[n].element, "duplicate room name '" + scene_read::one_line(name, 64) + "' (also " +
                                                a.nodes[it->second].element + ")");
    a.room_of[n] = int(a.room_nodes.size());
    a.room_nodes.push_back(n);
    a.room_names.push_back(name);
  }
  if (a.room_nodes.empty())
    return a.ctx.fail("", "no room: no node of the scene is named '<name>-room' (the rooms convention, docs/rooms.md)");
  a.bound_of_room.assign(a.room_nodes.size(), -1);
  for (uint32_t n : a.order) {
    const NameRole& r = a.roles[n];
    const std::string& element = a.nodes[n].element;
    const bool portal = r.role == Role::Portal || r.role == Role::OneWayPortal || r.role == Role::Mirror;
    if ((portal || r.role == Role::Bound) && a.nodes[n].mesh < 0)
      return a.ctx.fail(element, std::string(r.role == Role::Bound ? "bound" : "portal") + " node has no mesh");
    if (portal) {
      if (r.base.empty()) return a.ctx.fail(element, "portal name is empty (the node is named only by its suffix)");
      continue;
    }
    if (r.role != Role::Bound) continue;
    const int parent = a.graph.parent[n];
    const int room = parent >= 0 ? a.room_of[size_t(parent)] : -1;
    if (room < 0) return a.ctx.fail(element, "bound node is not below any room");
    if (a.bound_of_room[size_t(room)] >= 0)
      return a.ctx.fail(element, "room '" + a.room_names[size_t(room)] + "' has a second bound (also " +
                                     a.nodes[size_t(a.bound_of_room[size_t(room)])].element + ")");
    a.bound_of_room[size_t(room)] = int(n);
  }
  return {};
}

bool is_instance(const Assembly& a, uint32_t n) {
  return a.roles[n].role == Role::Plain && a.nodes[n].mesh >= 0 && a.room_of[n] >= 0;
}

// The points a room without a bound is wrapped around, in its own frame: its shell's vertices,
// else those of its instances.
Status room_points(Assembly& a, size_t r, std::vector<glm::dvec3>& points) {
  const uint32_t node = a.room_nodes[r];
  if (a.nodes[node].mesh >= 0) {
    const Mesh* mesh = nullptr;
    if (Status s = a.mesh_geometry(a.nodes[node].mesh, mesh); !s) return s;
    for (uint32_t i : mesh->indices) points.emplace_back(mesh->positions[i]);
  }
  if (!points.empty()) return {};
  const glm::dmat4 world_to_room = glm::inverse(a.graph.world[node]);
  for (uint32_t n : a.order) {
    if (!is_instance(a, n) || a.room_of[n] != int(r)) continue;
    const Mesh* mesh = nullptr;
    if (Status s = a.mesh_geometry(a.nodes[n].mesh, mesh); !s) return s;
    const glm::dmat4 to_room = world_to_room * a.graph.world[n];
    for (uint32_t i : mesh->indices)
      points.push_back(glm::dvec3(glm::vec3(apply(to_room, glm::dvec3(mesh->positions[i])))));
  }
  return {};
}

// Volumes: the bound mesh; else the convex hull of the room's points (its shell's vertices, or
// its instances' when it has no shell) in its frame; else (flat, or too many points) their box.
// Computed volumes are written as volume nodes, except a shell's box, which is the loader's own
// default.
Status build_volumes(Assembly& a) {
  a.volumes.resize(a.room_nodes.size());
  a.computed_volume_room.assign(a.room_nodes.size(), {});
  a.computed_volume_kind.assign(a.room_nodes.size(), {});
  for (size_t r = 0; r < a.room_nodes.size(); ++r) {
    const uint32_t node = a.room_nodes[r];
    const glm::dmat4& room_to_world = a.graph.world[node];
    if (const int bound = a.bound_of_room[r]; bound >= 0) {
      const Mesh* mesh = nullptr;
      if (Status s = a.mesh_geometry(a.nodes[size_t(bound)].mesh, mesh); !s) return s;
      std::vector<glm::vec3> soup;
      std::vector<glm::dvec3> world;
      for (uint32_t i : mesh->indices) {
        soup.push_back(mesh->positions[i]);
        world.push_back(apply(a.graph.world[size_t(bound)], glm::dvec3(mesh->positions[i])));
      }
      if (soup.empty()) return a.ctx.fail(a.nodes[size_t(bound)].element, "bound mesh has no triangles");
      if (size_t open = scene_read::count_open_edges(soup); open > 0)
        return a.ctx.fail(a.nodes[size_t(bound)].element, "bound mesh is not closed (" + std::to_string(open) +
                                                              " open edges; vertices are matched by exact position)");
      set_mesh_volume(std::move(world), a.volumes[r]);
      continue;
    }
    std::vector<glm::dvec3> points;
    if (Status s = room_points(a, r, points); !s) return s;
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const glm::dvec3& p : points) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z))
      return a.ctx.fail(a.nodes[node].element, "room '" + a.room_names[r] +
                                                   "' has no volume: no '-bound' mesh below it and no triangles "
                                                   "(its own mesh, or below it) spanning a box");
    const bool from_shell = a.nodes[node].mesh >= 0 && a.geometry.count(a.nodes[node].mesh) &&
                            !a.geometry.at(a.nodes[node].mesh).indices.empty();
    const double magnitude = std::max({glm::length(hi - lo), std::fabs(lo.x), std::fabs(lo.y), std::fabs(lo.z),
                                       std::fabs(hi.x), std::fabs(hi.y), std::fabs(hi.z)});
    std::vector<glm::dvec3> hull;
    if (convex_hull_3d(points, 1e-6 * glm::length(hi - lo) + 4.0 * FLT_EPSILON * magnitude, hull)) {
      std::vector<glm::dvec3> world;
      for (const glm::dvec3& p : hull) {
        a.computed_volume_room[r].push_back(glm::vec3(p));
        world.push_back(apply(room_to_world, p));
      }
      a.computed_volume_kind[r] = "convex hull";
      set_mesh_volume(std::move(world), a.volumes[r]);
      continue;
    }
    set_box_volume(room_to_world, lo, hi, a.volumes[r]);
    if (from_shell) continue;
    const uint32_t box_idx[] = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                                2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
    for (uint32_t c : box_idx)
      a.computed_volume_room[r].emplace_back((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
    a.computed_volume_kind[r] = "box of its meshes";
  }
  return {};
}

Status check_overlaps(const Assembly& a) {
  for (size_t i = 0; i < a.volumes.size(); ++i)
    for (size_t j = i + 1; j < a.volumes.size(); ++j) {
      const RoomVolume &va = a.volumes[i], &vb = a.volumes[j];
      double reach = 0.0;
      for (const glm::dvec3& c : {va.bounds_min, va.bounds_max, vb.bounds_min, vb.bounds_max})
        reach = std::max({reach, std::fabs(c.x), std::fabs(c.y), std::fabs(c.z)});
      const double tolerance = std::max(1e-3 * std::min(volume_size(va), volume_size(vb)), 4.0 * FLT_EPSILON * reach);
      glm::dvec3 p;
      if (!volumes_overlap(va, vb, tolerance, p)) continue;
      return a.ctx.fail(a.nodes[a.room_nodes[j]].element,
                        "room '" + a.room_names[j] + "' overlaps room '" + a.room_names[i] + "' (" +
                            a.nodes[a.room_nodes[i]].element + "): the point (" + number_text(p.x) + ", " +
                            number_text(p.y) + ", " + number_text(p.z) + ") lies inside both volumes by more than " +
                            number_text(tolerance) + " m");
    }
  return {};
}

struct PortalPlan {
  std::vector<glm::vec3> corners_node;  // in the portal node's space, wound about the face normal
  int from = -1, to = -1;
};

Status plan_portal(Assembly& a, uint32_t n, PortalPlan& out) {
  const NodeRecord& node = a.nodes[n];
  const Mesh* mesh = nullptr;
  if (Status s = a.mesh_geometry(node.mesh, mesh); !s) return s;
  std::vector<glm::dvec3> world;
  for (const glm::vec3& p : mesh->positions) world.push_back(apply(a.graph.world[n], glm::dvec3(p)));
  const double rounding = scene_read::rounding_floor(a.graph.world[n], mesh->positions);
  HullPolygon polygon;
  if (std::string why = hull_polygon(world, mesh->indices, rounding, polygon); !why.empty())
    return a.ctx.fail(node.element, "portal mesh " + why);
  if (polygon.size < scene_read::kMinSizeOverRounding * rounding)
    return a.ctx.fail(node.element, "portal mesh is too small for its coordinates: size " + number_text(polygon.size) +
                                        " m, rounding " + number_text(rounding) + " m");
  if (a.roles[n].role == Role::OneWayPortal && !polygon.winding_consistent)
    return a.ctx.fail(node.element,
                      "one-way portal's triangles face both ways: its direction is its face normal "
                      "(right-hand rule), so all triangles must face one way");
  if (a.roles[n].role == Role::Mirror && !polygon.winding_consistent)
    return a.ctx.fail(node.element,
                      "mirror's triangles face both ways: its face (right-hand rule) must look into the room it "
                      "reflects, so all triangles must face one way");
  PortalLinkResult link;
  if (a.roles[n].role == Role::Mirror) {
    if (std::string why = link_mirror(polygon, a.volumes, a.room_names, link); !why.empty())
      return a.ctx.fail(node.element, why);
  } else if (std::string why = link_portal(polygon, a.volumes, a.room_names, link); !why.empty()) {
    return a.ctx.fail(node.element, why);
  }
  const glm::dmat4 world_to_node = glm::inverse(a.graph.world[n]);
  for (const glm::dvec3& c : polygon.corners_world) out.corners_node.push_back(glm::vec3(apply(world_to_node, c)));
  out.from = link.from;
  out.to = link.to;
  return {};
}

// The SceneDesc meshes drawing glTF mesh `gltf_mesh`: one per material it uses
// (scene_read::read_mesh_parts), parts without triangles left out; empty (with a warning) when it
// has none.
const std::vector<int>& add_drawn_mesh(Assembly& a, int gltf_mesh, SceneDesc& scene, Status& status) {
  static const std::vector<int> kNone;
  if (auto it = a.drawn_mesh.find(gltf_mesh); it != a.drawn_mesh.end()) return it->second;
  std::vector<Mesh> parts;
  status = scene_read::read_mesh_parts(a.ctx, a.model, gltf_mesh, a.budget, a.texture_table, parts);
  if (!status) return kNone;
  std::vector<int> indices;
  for (const Mesh& mesh : parts) {
    if (mesh.indices.empty()) continue;
    indices.push_back(int(scene.meshes.size()));
    scene.meshes.push_back(mesh_desc_of(mesh));
  }
  if (indices.empty())
    a.ctx.warn(describe("mesh", size_t(gltf_mesh), a.model.meshes[size_t(gltf_mesh)].name),
               "has no triangles; the nodes using it draw nothing");
  return a.drawn_mesh.emplace(gltf_mesh, std::move(indices)).first->second;
}

Status read_light(const Assembly& a, int index, const std::string& node_name, LightDesc& out) {
  const tinygltf::Light& l = a.model.lights[size_t(index)];
  const std::string element = describe("light", size_t(index), l.name);
  if (l.type == "point")
    out.type = Light::Type::Point;
  else if (l.type == "spot")
    out.type = Light::Type::Spot;
  else if (l.type == "directional")
    out.type = Light::Type::Directional;
  else
    return a.ctx.fail(element, "unknown KHR_lights_punctual type '" + scene_read::one_line(l.type, 64) + "'");
  if (l.color.size() == 3) out.color = glm::vec3(float(l.color[0]), float(l.color[1]), float(l.color[2]));
  out.intensity = float(l.intensity);
  out.range = float(l.range);
  out.inner_cone_rad = float(l.spot.innerConeAngle);
  out.outer_cone_rad = float(l.spot.outerConeAngle);
  out.name = node_name.empty() ? l.name : node_name;
  return {};
}

Status write_scene(Assembly& a, SceneDesc& scene, RoomsImportStats& stats) {
  std::vector<int> out_index(a.nodes.size(), -1);
  for (uint32_t n : a.order) {
    const NodeRecord& node = a.nodes[n];
    const NameRole& role = a.roles[n];
    NodeDesc desc;
    desc.name = node.name;
    const int parent = a.graph.parent[n];
    desc.parent = parent >= 0 ? out_index[size_t(parent)] : -1;
    if (!rooms::set_trs_from_matrix(node.local, desc))
      return a.ctx.fail(node.element,
                        "transform is sheared: it cannot be stored as translation, "
                        "rotation and scale");
    Status status;
    std::vector<int> other_parts;  // a mesh's parts beyond the first: drawn by child nodes, below
    auto draw = [&](int gltf_mesh) {
      const std::vector<int>& parts = add_drawn_mesh(a, gltf_mesh, scene, status);
      if (!parts.empty()) {
        desc.mesh = parts.front();
        other_parts.assign(parts.begin() + 1, parts.end());
      }
    };
    switch (role.role) {
      case Role::Room: {
        desc.kind = NodeDesc::Kind::Cell;
        desc.name = desc.cell_name = role.base;
        if (node.mesh >= 0) draw(node.mesh);
        ++stats.rooms;
        break;
      }
      case Role::Bound: {
        desc.kind = NodeDesc::Kind::Volume;
        const Mesh* mesh = nullptr;
        if (Status s = a.mesh_geometry(node.mesh, mesh); !s) return s;
        MeshDesc volume;
        volume.name = mesh->name;
        volume.positions = mesh->positions;
        volume.indices = mesh->indices;
        desc.mesh = int(scene.meshes.size());
        scene.meshes.push_back(std::move(volume));
        ++stats.bounds;
        break;
      }
      case Role::Portal:
      case Role::OneWayPortal:
      case Role::Mirror: {
        PortalPlan plan;
        if (Status s = plan_portal(a, n, plan); !s) return s;
        desc.kind = NodeDesc::Kind::Portal;
        desc.name = role.base;
        desc.portal_from = a.room_names[size_t(plan.from)];
        desc.portal_to = a.room_names[size_t(plan.to)];
        desc.two_way = role.role == Role::Portal;
        desc.portal_mirror = role.role == Role::Mirror;
        MeshDesc polygon;
        polygon.name = role.base;
        polygon.positions = plan.corners_node;
        for (uint32_t i = 1; i + 1 < plan.corners_node.size(); ++i)
          polygon.indices.insert(polygon.indices.end(), {0, i, i + 1});
        desc.mesh = int(scene.meshes.size());
        scene.meshes.push_back(std::move(polygon));
        ++stats.portals;
        stats.one_way += desc.two_way ? 0 : 1;
        break;
      }
      case Role::Plain: {
        if (node.mesh >= 0 && a.room_of[n] >= 0) {
          draw(node.mesh);
          stats.instances += desc.mesh >= 0 ? 1 : 0;
        } else if (node.mesh >= 0) {
          a.ctx.warn(node.element, "mesh node outside any room and not a portal (ignored)");
        }
        break;
      }
    }
    if (!status) return status;
    if (node.light >= 0 && a.room_of[n] >= 0) {
      LightDesc light;
      if (Status s = read_light(a, node.light, node.name, light); !s) return s;
      desc.light = int(scene.lights.size());
      scene.lights.push_back(light);
      ++stats.lights;
    } else if (node.light >= 0) {
      a.ctx.warn(node.element, "light outside any room (ignored)");
    }
    out_index[n] = int(scene.nodes.size());
    const std::string name = desc.name;
    scene.nodes.push_back(std::move(desc));
    // The other materials of its mesh: children of the node's name in its place, instances of the
    // room (one object: a timeline key naming it moves them all).
    for (const int part : other_parts) {
      NodeDesc child;
      child.name = name;
      child.parent = out_index[n];
      child.mesh = part;
      scene.nodes.push_back(std::move(child));
    }
    if (role.role == Role::Room && !a.computed_volume_room[size_t(a.room_of[n])].empty()) {
      const size_t r = size_t(a.room_of[n]);
      MeshDesc mesh;
      mesh.name = role.base + " " + a.computed_volume_kind[r];
      mesh.positions = a.computed_volume_room[r];
      for (uint32_t i = 0; i < mesh.positions.size(); ++i) mesh.indices.push_back(i);
      NodeDesc volume;
      volume.name = role.base + "-bound (" + a.computed_volume_kind[r] + ")";
      volume.parent = out_index[n];
      volume.kind = NodeDesc::Kind::Volume;
      volume.mesh = int(scene.meshes.size());
      scene.meshes.push_back(std::move(mesh));
      scene.nodes.push_back(std::move(volume));
    }
  }
  scene.textures = std::move(a.textures);
  return {};
}

}  // namespace

NameRole role_of_name(const std::string& name) {
  // A Blender duplicate tail (".001") after the suffix is kept in the base name.
  std::string core = name, tail;
  if (const size_t dot = name.rfind('.'); dot != std::string::npos && dot + 1 < name.size() &&
                                          name.find_first_not_of("0123456789", dot + 1) == std::string::npos) {
    core = name.substr(0, dot);
    tail = name.substr(dot);
  }
  const std::pair<const char*, Role> suffixes[] = {{kOneWayPortalSuffix, Role::OneWayPortal},
                                                   {kPortalSuffix, Role::Portal},
                                                   {kMirrorSuffix, Role::Mirror},
                                                   {kRoomSuffix, Role::Room},
                                                   {kBoundSuffix, Role::Bound}};
  for (const auto& [suffix, role] : suffixes)
    if (ends_with(core, suffix)) return {role, core.substr(0, core.size() - std::string(suffix).size()) + tail};
  return {Role::Plain, name};
}

Status assemble_rooms_scene(const scene_read::LoadContext& ctx, const tinygltf::Model& model,
                            const std::vector<NodeRecord>& nodes, const scene_read::SceneGraph& graph,
                            const std::string& base_dir, SceneDesc& out, RoomsImportStats& stats) {
  Assembly a(ctx, model, nodes, graph, base_dir);
  if (Status s = classify_nodes(a); !s) return s;
  if (Status s = build_volumes(a); !s) return s;
  if (Status s = check_overlaps(a); !s) return s;
  SceneDesc scene;
  if (Status s = write_scene(a, scene, stats); !s) return s;
  out = std::move(scene);
  return {};
}

}  // namespace lintel::rooms
