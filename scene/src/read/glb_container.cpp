// GLB header and chunk checks (glTF 2.0 spec, section "Binary glTF Layout"). All arithmetic is
// done in 64 bits so that no length field can wrap.
#include "read/glb_container.h"

#include <cstring>

namespace lintel::scene_read {
namespace {

constexpr uint32_t kChunkJson = 0x4E4F534A;  // "JSON" little-endian
constexpr uint32_t kChunkBin = 0x004E4942;   // "BIN\0"

uint32_t read_u32(const uint8_t* p) {
  // GLB is little-endian by definition; assemble bytes so that the host order does not matter.
  return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

}  // namespace

bool looks_like_glb(const uint8_t* bytes, size_t size) { return size >= 4 && std::memcmp(bytes, "glTF", 4) == 0; }

std::string split_glb(const uint8_t* bytes, size_t size, GlbChunks& out) {
  out = {};
  if (size < 20) return "truncated GLB: " + std::to_string(size) + " bytes is shorter than the 20-byte header";
  if (!looks_like_glb(bytes, size)) return "not a GLB file (no 'glTF' magic)";
  const uint32_t version = read_u32(bytes + 4);
  if (version != 2) return "GLB container version " + std::to_string(version) + " is not 2";
  const uint64_t length = read_u32(bytes + 8);
  if (length > size)
    return "truncated GLB: the header says " + std::to_string(length) + " bytes, the file has " + std::to_string(size);
  if (length < size)
    return "GLB header says " + std::to_string(length) + " bytes but the file has " + std::to_string(size);

  const uint64_t json_size = read_u32(bytes + 12);
  if (read_u32(bytes + 16) != kChunkJson) return "GLB: the first chunk is not JSON";
  if (json_size == 0) return "GLB: the JSON chunk is empty";
  const uint64_t json_end = 20 + json_size;
  if (json_end > length)
    return "truncated GLB: the JSON chunk needs " + std::to_string(json_end) + " bytes, the file has " +
           std::to_string(length);
  out.json = reinterpret_cast<const char*>(bytes + 20);
  out.json_size = static_cast<size_t>(json_size);
  if (json_end == length) return {};

  // tinygltf reads only a BIN chunk right after the JSON chunk; anything else is refused here
  // with a clear reason rather than passed on.
  if (json_end % 4 != 0) return "GLB: the JSON chunk length is not a multiple of 4";
  if (json_end + 8 > length) return "truncated GLB: a chunk header is cut off after the JSON chunk";
  const uint64_t bin_size = read_u32(bytes + json_end);
  if (read_u32(bytes + json_end + 4) != kChunkBin) return "GLB: the second chunk is not BIN (unsupported chunk type)";
  const uint64_t bin_end = json_end + 8 + bin_size;
  if (bin_end > length)
    return "truncated GLB: the BIN chunk needs " + std::to_string(bin_end) + " bytes, the file has " +
           std::to_string(length);
  if (bin_size < 4 || bin_size % 4 != 0)
    return "GLB: the BIN chunk length " + std::to_string(bin_size) + " is not a positive multiple of 4";
  out.bin = bytes + json_end + 8;
  out.bin_size = static_cast<size_t>(bin_size);
  return {};
}

}  // namespace lintel::scene_read
