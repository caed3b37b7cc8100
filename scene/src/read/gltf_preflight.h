// Checks on the raw glTF JSON before tinygltf parses it: integers that tinygltf would silently
// truncate to 32 bits, buffer sizes and URIs (so memory stays bounded and missing files are named),
// buffer views against their buffers, and the accessor fields tinygltf reports without an index.
#pragma once

#include "read/glb_container.h"
#include "read/load_context.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace lintel::scene_read {

struct PreflightResult {
  // Paths (base_dir joined with the decoded URI) of the external buffer files tinygltf may read;
  // tinygltf opens nothing else (texture_read.cpp reads an external image only when it is used).
  std::vector<std::string> external_files;
};

// `glb` is null for a .gltf text file. `base_dir` may be empty: then external URIs are errors.
Status preflight_gltf(const LoadContext& ctx, const nlohmann::json& doc, const GlbChunks* glb,
                      const std::string& base_dir, PreflightResult& out);

// URI percent-decoding exactly as tinygltf does it ('+' is a space, "%41" is 'A'), so that the
// paths in PreflightResult match the ones tinygltf asks for.
std::string decode_uri_like_tinygltf(const std::string& uri);

}  // namespace lintel::scene_read
