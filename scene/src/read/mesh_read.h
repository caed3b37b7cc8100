// One glTF mesh -> lintel::Mesh: triangle primitives merged into one vertex and index array,
// normals from the file or computed, the uvs, the real extent of the positions, and the looks
// (base colour factor and texture, sidedness) of the first triangle primitive's material. A drawn
// mesh whose primitives use several materials becomes one Mesh per material (read_mesh_parts).
#pragma once

#include "read/accessor_read.h"
#include "read/load_context.h"
#include "read/texture_read.h"

#include <lintel/world.h>

#include <vector>

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

// A drawn mesh (shell or instance) as one Mesh per material its triangle primitives use, in order
// of first use: each holds that material's primitives merged, with its looks. One material (or
// none) gives one part, the same Mesh read_mesh gives. Parts may have no triangles (callers skip).
Status read_mesh_parts(const LoadContext& ctx, const tinygltf::Model& model, int index, ReadBudget& budget,
                       TextureTable& textures, std::vector<Mesh>& parts);

}  // namespace lintel::scene_read
