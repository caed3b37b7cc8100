// BuildingPlan -> SceneDesc. Every cell node gets the plan's frame; its shell, volume and portal
// vertices are the world geometry mapped back through the inverse of the node's world transform
// (as the loader will compute it from the stored float TRS), so the world geometry stays the same
// whatever the frames are. Furniture and lights keep rigid world transforms: below a cell with a
// non-uniform scale they hang from an intermediate node that undoes the scale.
#pragma once

#include "generate/building_plan.h"

#include <lintel/scene_desc.h>

namespace lintel::gen {

SceneDesc assemble_scene(const BuildingPlan& plan);

// The world transform of node `index` as a loader computes it: float TRS read back in double,
// quaternion normalized, parents first.
glm::dmat4 node_world_matrix(const SceneDesc& scene, int index);

}  // namespace lintel::gen
