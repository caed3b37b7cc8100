// The binary glTF container (GLB): a 12-byte header, a JSON chunk, an optional BIN chunk.
// Checked here, completely, before tinygltf sees the bytes: its own check of the BIN chunk
// length forgets the 8-byte chunk header and can read past the end of a truncated file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace lintel::scene_read {

struct GlbChunks {
  const char* json = nullptr;
  size_t json_size = 0;
  const uint8_t* bin = nullptr;  // null when the file has no BIN chunk
  size_t bin_size = 0;
};

// True when the bytes start with the GLB magic "glTF" (then the file is read as GLB, whatever
// its extension says).
bool looks_like_glb(const uint8_t* bytes, size_t size);

// Splits a GLB into its chunks. Returns an empty string on success, otherwise a one-line reason
// ("truncated GLB: the header says 4096 bytes, the file has 1000").
std::string split_glb(const uint8_t* bytes, size_t size, GlbChunks& out);

}  // namespace lintel::scene_read
