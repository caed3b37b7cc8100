// One glTF mesh -> lintel::Mesh: all triangle-list primitives merged into one vertex and index
// array, normals from the file or computed, TEXCOORD_0, the real extent of the positions, and the
// base colour factor and texture of the first primitive's material.
#pragma once

#include "read/accessor_read.h"
#include "read/load_context.h"
#include "read/texture_read.h"

#include <lintel/world.h>

namespace tinygltf {
class Model;
}

namespace lintel::scene_read {

// Reads mesh `index` (already known to exist). Primitives that are not triangle lists are
// skipped with a warning; the result may then have no triangles (callers decide what that means).
// With `textures` (drawn meshes) TEXCOORD_0 is read into `uvs` and the base colour texture is
// resolved through it; without (portal and volume meshes, whose looks do not matter) neither is,
// and normals are only read where given (checked as for drawn meshes), never computed (zero).
Status read_mesh(const LoadContext& ctx, const tinygltf::Model& model, int index, ReadBudget& budget,
                 TextureTable* textures, Mesh& out);

}  // namespace lintel::scene_read
