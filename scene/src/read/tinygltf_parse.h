// Runs tinygltf on bytes that passed the container and preflight checks, with images not decoded
// (texture_read.cpp decodes the used ones; data: URI bytes are kept in Image::image with as_is)
// and file access limited to the external buffers preflight allowed. Every exception tinygltf or
// nlohmann may throw stops here.
#pragma once

#include "read/glb_container.h"
#include "read/load_context.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace lintel::scene_read {

// `glb` is true when `bytes` is a GLB container (already checked by split_glb).
Status parse_with_tinygltf(const LoadContext& ctx, const uint8_t* bytes, size_t size, bool glb,
                           const std::string& base_dir, const std::vector<std::string>& external_files,
                           tinygltf::Model& model);

}  // namespace lintel::scene_read
