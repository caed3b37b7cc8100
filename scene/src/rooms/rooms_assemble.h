// The rooms importer after parsing: node names -> roles (room, portal, one-way portal, bound,
// plain), room volumes and the overlap check, portal polygons and links, then the Lintel
// SceneDesc (same hierarchy, TRS transforms, Lintel tags). Rules: docs/rooms.md.
#pragma once

#include "read/load_context.h"
#include "read/node_hierarchy.h"
#include "read/node_read.h"

#include <lintel/rooms_import.h>
#include <lintel/scene_desc.h>

#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace lintel::rooms {

enum class Role { Plain, Room, Portal, OneWayPortal, Mirror, Bound };

struct NameRole {
  Role role = Role::Plain;
  std::string base;  // the name without its suffix (a Blender ".001" tail kept): the cell/portal name
};

// "Hall-room" -> Room "Hall"; "Door-portal.001" -> Portal "Door.001"; "Sofa" -> Plain "Sofa".
NameRole role_of_name(const std::string& name);

Status assemble_rooms_scene(const scene_read::LoadContext& ctx, const tinygltf::Model& model,
                            const std::vector<scene_read::NodeRecord>& nodes, const scene_read::SceneGraph& graph,
                            const std::string& base_dir, SceneDesc& out, RoomsImportStats& stats);

}  // namespace lintel::rooms
