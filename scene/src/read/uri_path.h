// Where a relative buffer or image URI of a .gltf points on disk, and whether it may be read:
// after percent-decoding and symlink resolution the file must lie inside the scene's folder,
// unless the caller allowed paths outside it (LoadOptions::allow_outside_paths).
#pragma once

#include <string>

namespace lintel::scene_read {

// Resolves `uri` (not a data: URI) against `base_dir`. On success returns an empty string and sets
// `path` to base_dir joined with the decoded URI (the spelling tinygltf uses too). Otherwise a
// one-line reason: remote or absolute URI, a NUL byte, a missing file, or a real path outside
// the real `base_dir`.
// `kind` ("buffer", "image") names the file in messages.
std::string resolve_relative_uri(const std::string& kind, const std::string& base_dir, const std::string& uri,
                                 bool allow_outside, std::string& path);

}  // namespace lintel::scene_read
