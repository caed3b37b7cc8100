// glTF nodes and scenes read from the JSON: name, mesh, light, children, the local transform
// (validated: finite as float, positive scale, affine) and the Lintel tag. Read here rather than
// from tinygltf because tinygltf silently ignores wrong types in these fields.
#pragma once

#include "read/lintel_extras.h"
#include "read/load_context.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace lintel::scene_read {

struct NodeRecord {
  std::string name;
  std::string element;  // "node 7 'Door.001'", for messages
  int mesh = -1;
  int light = -1;  // KHR_lights_punctual light index
  std::vector<uint32_t> children;
  glm::dmat4 local{1.0};  // node space -> parent space
  NodeTag tag;
};

Status read_nodes(const LoadContext& ctx, const nlohmann::json& doc, size_t mesh_count, size_t light_count,
                  std::vector<NodeRecord>& out);

struct SceneChoice {
  const nlohmann::json* scene = nullptr;  // null when the file has no scenes
  std::string element;                    // "scene 0 'Main'"
  std::vector<uint32_t> roots;            // the scene's root nodes; empty with no scene
};

// The default scene ("scene", else scene 0) and its root node list.
Status read_scene_choice(const LoadContext& ctx, const nlohmann::json& doc, size_t node_count, SceneChoice& out);

}  // namespace lintel::scene_read
