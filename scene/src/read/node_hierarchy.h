// The node tree of the chosen scene: one parent per node, no cycles (detected without recursion,
// so a hostile file cannot hang or overflow the stack), world transforms, and for every node the
// nearest cell at or above it.
#pragma once

#include "read/node_read.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lintel::scene_read {

struct SceneGraph {
  std::vector<int> parent;         // -1 for a root
  std::vector<uint8_t> in_scene;   // 1 when reachable from the chosen scene's roots
  std::vector<glm::dmat4> world;   // node space -> world, valid where in_scene
  std::vector<int> cell_ancestor;  // nearest cell node strictly above the node, or -1
};

// Builds the graph. With `choice.scene` null every parentless node is a root. Faults: a node
// listed as a child twice or by two parents, a cycle, a scene root that has a parent, a world
// transform that overflows float.
Status build_scene_graph(const LoadContext& ctx, const std::vector<NodeRecord>& nodes, const SceneChoice& choice,
                         SceneGraph& out);

}  // namespace lintel::scene_read
