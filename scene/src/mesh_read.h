// One glTF mesh -> lintel::Mesh: all triangle-list primitives merged into one vertex and index
// array, normals from the file or computed, the real extent of the positions, and the base colour
// of the first primitive's material.
#pragma once

#include "accessor_read.h"
#include "load_context.h"

#include <lintel/world.h>

namespace tinygltf {
class Model;
}

namespace lintel::scene_read {

// Reads mesh `index` (already known to exist). Primitives that are not triangle lists are
// skipped with a warning; the result may then have no triangles (callers decide what that means).
Status read_mesh(const LoadContext& ctx, const tinygltf::Model& model, int index, ReadBudget& budget, Mesh& out);

}  // namespace lintel::scene_read
