// Turns the validated node tree into a World: cells (transforms, shells, volumes), instances and
// draw groups, portals with their links, lights. Split over world_assemble.cpp (cells, meshes,
// instances), portal_assemble.cpp and light_assemble.cpp, which share AssemblyState.
#pragma once

#include "read/accessor_read.h"
#include "read/load_context.h"
#include "read/node_hierarchy.h"
#include "read/node_read.h"

#include <lintel/world.h>

#include <string>
#include <unordered_map>
#include <vector>

namespace tinygltf {
class Model;
}

namespace lintel::scene_read {

struct AssemblyState {
  const LoadContext& ctx;
  const tinygltf::Model& model;
  const std::vector<NodeRecord>& nodes;
  const SceneGraph& graph;
  ReadBudget budget;
  std::vector<int> cell_of_node;  // node index -> cell index, or -1
  std::unordered_map<std::string, uint32_t> cell_by_name;
  std::string base_dir;  // resolves external image URIs (empty: embedded images only)
};

// Fills `world` (cells, meshes, textures, instances, groups, portals, lights; not source, version or
// timelines). Orders: cells, portals, instances and lights by node index; meshes and groups by
// glTF mesh index.
Status assemble_world(AssemblyState& state, World& world);

Status assemble_portals(AssemblyState& state, World& world);
Status assemble_lights(AssemblyState& state, World& world);

// Conversions shared by the assembly steps.
glm::mat4 to_float(const glm::dmat4& m);
glm::dvec3 transform_point(const glm::dmat4& m, const glm::vec3& p);

}  // namespace lintel::scene_read
