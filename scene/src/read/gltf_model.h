// The parts of a glTF file that Lintel reads -- buffers, buffer views, accessors, meshes,
// materials, textures, samplers, images and KHR_lights_punctual lights -- filled into tinygltf's
// Model types from the loader's one DOM (gltf_json.h). tinygltf's own parser is not run: it parsed
// the whole text a second time into a DOM of its own and then into every Model field, which was
// more than half of loading an imported level. The readers (mesh_read.h, texture_read.h,
// light_assemble.cpp) take the Model as before.
//
// Fields are read strictly: where tinygltf silently kept its default for a value of the wrong
// JSON type (an "indices" that is a string, a "baseColorTexture" without "index"), this is a fault
// naming the element. Sections Lintel does not read (animations, skins, cameras) are only checked
// to be arrays of objects, as tinygltf did before reading them.
#pragma once

#include "read/glb_container.h"
#include "read/gltf_compact.h"
#include "read/gltf_preflight.h"
#include "read/load_context.h"

#include <nlohmann/json.hpp>

namespace tinygltf {
class Model;
}

namespace lintel::scene_read {

// `doc` passed preflight_gltf, which returned `preflight`; `glb` is null for a .gltf text file.
// Buffers are read whole: the GLB's BIN chunk, a data: URI, or the file preflight resolved.
// `compact`: the accessors and meshes the parse read into structs (gltf_compact.h), moved into
// the model instead of being read from `doc`.
Status read_gltf_model(const LoadContext& ctx, const nlohmann::json& doc, const GlbChunks* glb,
                       const PreflightResult& preflight, tinygltf::Model& model, CompactSections* compact = nullptr);

// The two halves of read_gltf_model. Data: buffers, buffer views, accessors, meshes
// (gltf_model_data.cpp). Looks: materials, images (after the buffer views, which they may name),
// textures, samplers, lights (gltf_model_looks.cpp).
Status read_gltf_data(const LoadContext& ctx, const nlohmann::json& doc, const GlbChunks* glb,
                      const PreflightResult& preflight, tinygltf::Model& model, CompactSections* compact);
Status read_gltf_looks(const LoadContext& ctx, const nlohmann::json& doc, tinygltf::Model& model);

}  // namespace lintel::scene_read
