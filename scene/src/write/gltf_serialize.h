// SceneDesc -> glTF 2.0 JSON text and binary buffer, in memory, deterministic to the byte: keys in
// a fixed order, floats printed as the shortest decimal that reads back to the same float, no
// time stamps. Layout: one vertex bufferView (positions and normals, stride 12), one index
// bufferView (16-bit indices where a mesh has < 65535 vertices, else 32-bit), then only when used
// one uv bufferView (TEXCOORD_0, stride 8) and one bufferView per texture holding its PNG.
// Texture samplers and the environment are written only where they differ from the default.
#pragma once

#include <lintel/scene_desc.h>
#include <lintel/status.h>

#include <cstdint>
#include <string>
#include <vector>

namespace lintel::scene_write {

struct SerializedScene {
  std::string json;
  std::vector<uint8_t> bin;  // length a multiple of 4
};

// `bin_uri`: the buffer's uri for a .gltf (already URI-escaped), or empty for a GLB's BIN chunk.
// `readable`: one top-level member per line and one array element per line (for .gltf files
// kept in git); otherwise compact. Checks the scene first (check_scene_desc).
Status serialize_scene(const SceneDesc& scene, const std::string& bin_uri, bool readable, SerializedScene& out);

// The GLB container (header, JSON chunk padded with spaces, BIN chunk padded with zeros).
std::vector<uint8_t> pack_glb(const SerializedScene& scene);

// Percent-escapes everything but RFC 3986 unreserved characters (for a buffer file name).
std::string uri_escape(const std::string& name);

}  // namespace lintel::scene_write
