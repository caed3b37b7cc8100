// Node transforms for the rooms convention: SceneDesc nodes carry translation / rotation / scale,
// while the importer reads matrices and the exporter composes them; this splits an affine matrix
// back into TRS when it has no shear (what a Blender or Godot node transform always is).
#pragma once

#include <lintel/scene_desc.h>

#include <glm/glm.hpp>

namespace lintel::rooms {

// Sets `node`'s translation, rotation and scale from `m` (node space -> parent space). Returns
// false, leaving `node` unchanged, when the 3x3 part is sheared (its columns are not orthogonal
// within 1e-5 relative) or degenerate: TRS cannot hold it. A mirror becomes a negative x scale.
bool set_trs_from_matrix(const glm::dmat4& m, NodeDesc& node);

}  // namespace lintel::rooms
