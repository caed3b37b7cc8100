// Checks on the raw glTF JSON before the model is read from it (gltf_model.h): integers outside
// the 32 bits the model's fields hold, buffer sizes and URIs (so memory stays bounded and missing
// files are named), buffer views against their buffers, and the accessors' required fields.
#pragma once

#include "read/glb_container.h"
#include "read/gltf_compact.h"
#include "read/load_context.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace lintel::scene_read {

struct PreflightResult {
  // One per buffer: the path (base_dir joined with the decoded URI) of its external file, or empty
  // for the GLB's BIN chunk or a data: URI. The model reads these files and opens nothing else
  // (texture_read.cpp reads an external image only when it is used).
  std::vector<std::string> buffer_files;
};

// The top-level array `key` (absent: `out` is null), at most `max_count` elements, each an object.
// Preflight checks "buffers" and "bufferViews" with it, the model readers the other sections.
Status top_level_objects(const LoadContext& ctx, const nlohmann::json& doc, const char* key, size_t max_count,
                         const nlohmann::json*& out);

// `glb` is null for a .gltf text file. `base_dir` may be empty: then external URIs are errors.
// `known_to_fit`: the parse already proved every checked integer within 32 bits
// (parse_gltf_json), so the DOM is not walked for one.
// `compact`: the accessors the parse read into structs (gltf_compact.h), already proven clean,
// so only their buffer views are checked here.
Status preflight_gltf(const LoadContext& ctx, const nlohmann::json& doc, const GlbChunks* glb,
                      const std::string& base_dir, PreflightResult& out, bool known_to_fit = false,
                      const CompactSections* compact = nullptr);

// URI percent-decoding as tinygltf does it ('+' is a space, "%41" is 'A'): buffer and image URIs
// name the same files they named when tinygltf read them.
std::string decode_uri_like_tinygltf(const std::string& uri);

}  // namespace lintel::scene_read
