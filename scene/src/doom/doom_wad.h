// Doom WAD files: the 12-byte header, the lump directory and the lumps of one map (the marker
// lump "E1M1" or "MAP01" followed by THINGS, LINEDEFS, ...). Little-endian throughout; every
// offset and size is checked against the file before it is used. Format: the Unofficial Doom
// Specs (M. S. Fell, 1994), section 2.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace lintel::doom {

struct WadLump {
  std::string name;  // up to 8 characters, NUL padding removed
  uint32_t offset = 0;
  uint32_t size = 0;
};

struct Wad {
  std::string path;  // for messages
  std::vector<uint8_t> bytes;
  std::vector<WadLump> lumps;
};

// The bytes of one lump of a map, by name.
struct MapLumps {
  std::string map;
  const uint8_t* things = nullptr;
  size_t things_size = 0;
  const uint8_t* linedefs = nullptr;
  size_t linedefs_size = 0;
  const uint8_t* sidedefs = nullptr;
  size_t sidedefs_size = 0;
  const uint8_t* vertexes = nullptr;
  size_t vertexes_size = 0;
  const uint8_t* segs = nullptr;
  size_t segs_size = 0;
  const uint8_t* ssectors = nullptr;
  size_t ssectors_size = 0;
  const uint8_t* nodes = nullptr;
  size_t nodes_size = 0;
  const uint8_t* sectors = nullptr;
  size_t sectors_size = 0;
};

// Reads and checks the header and directory (magic IWAD/PWAD, directory and every lump inside
// the file). Empty string on success, otherwise "PATH: fault" (one line).
std::string read_wad(const std::string& path, Wad& out);

// The same on bytes already in memory (tests); `label` names them in messages.
std::string parse_wad(std::vector<uint8_t> bytes, const std::string& label, Wad& out);

// Finds map `map` (case-insensitive) and the eight lumps it needs among those after its marker.
// Empty string on success, otherwise "PATH: map 'E1M9' not found" or "PATH: map E1M1: lump NODES
// missing".
std::string find_map(const Wad& wad, const std::string& map, MapLumps& out);

// Names of all maps in the WAD (marker lumps followed by THINGS), in directory order.
std::vector<std::string> map_names(const Wad& wad);

// Little-endian readers (no alignment assumed).
inline int16_t read_i16(const uint8_t* p) { return int16_t(uint16_t(p[0] | (p[1] << 8))); }
inline uint16_t read_u16(const uint8_t* p) { return uint16_t(p[0] | (p[1] << 8)); }
inline uint32_t read_u32(const uint8_t* p) {
  return uint32_t(p[0]) | (uint32_t(p[1]) << 8) | (uint32_t(p[2]) << 16) | (uint32_t(p[3]) << 24);
}
// An 8-byte name field without its NUL padding, upper-cased.
std::string read_name8(const uint8_t* p);

}  // namespace lintel::doom
