// A map of a WAD copied into a small PWAD of its own, and where that PWAD's lumps lie: what the
// hostile-WAD tests (fuzz/doom_import_fuzz.cpp, tests/levels/import_cli_test.cpp) edit. Header
// only, for test code; the WAD is trusted here (Freedoom's).
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace lintel::test {

inline uint32_t wad_u32(const uint8_t* p) {
  return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}
inline void put_wad_u32(uint8_t* p, uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = uint8_t(v >> (8 * i));
}

// The map's marker and its ten lumps out of `wad`, as a PWAD (data first, directory last); empty
// when `wad` has no such map.
inline std::vector<uint8_t> map_pwad(const std::vector<uint8_t>& wad, const std::string& map) {
  const uint32_t count = wad_u32(&wad[4]), dir = wad_u32(&wad[8]);
  size_t first = count;
  for (uint32_t i = 0; i < count; ++i)
    if (std::strncmp(reinterpret_cast<const char*>(&wad[dir + 16 * i + 8]), map.c_str(), 8) == 0) first = i;
  if (first + 11 > count) return {};
  std::vector<uint8_t> out = {'P', 'W', 'A', 'D', 11, 0, 0, 0, 0, 0, 0, 0};
  std::vector<uint8_t> directory;
  for (uint32_t i = 0; i < 11; ++i) {
    const uint8_t* entry = &wad[dir + 16 * (first + i)];
    const uint32_t at = wad_u32(entry), size = wad_u32(entry + 4);
    uint8_t row[16];
    put_wad_u32(row, uint32_t(out.size()));
    put_wad_u32(row + 4, size);
    std::memcpy(row + 8, entry + 8, 8);
    directory.insert(directory.end(), row, row + 16);
    out.insert(out.end(), wad.begin() + long(at), wad.begin() + long(at + size));
  }
  put_wad_u32(&out[8], uint32_t(out.size()));
  out.insert(out.end(), directory.begin(), directory.end());
  return out;
}

// Where a lump of such a PWAD lies: its directory entry and its bytes.
struct PwadLump {
  std::string name;
  size_t entry = 0;  // offset of its directory entry
  size_t at = 0, size = 0;
};

inline std::vector<PwadLump> pwad_lumps(const std::vector<uint8_t>& pwad) {
  std::vector<PwadLump> out;
  const uint32_t dir = wad_u32(&pwad[8]);
  for (uint32_t i = 0; i < 11; ++i) {
    const size_t entry = dir + 16 * i;
    char name[9] = {};
    std::memcpy(name, &pwad[entry + 8], 8);
    out.push_back({name, entry, wad_u32(&pwad[entry]), wad_u32(&pwad[entry + 4])});
  }
  return out;
}

// Renames the map of a PWAD made by map_pwad (its marker, the first lump), e.g. to put two copies
// of one map in a PWAD.
inline void rename_pwad_map(std::vector<uint8_t>& pwad, const std::string& map) {
  uint8_t* name = &pwad[wad_u32(&pwad[8]) + 8];
  std::memset(name, 0, 8);
  std::memcpy(name, map.data(), std::min<size_t>(map.size(), 8));
}

// PWADs made by map_pwad joined into one PWAD holding all their maps, in order.
inline std::vector<uint8_t> join_pwads(const std::vector<std::vector<uint8_t>>& parts) {
  std::vector<uint8_t> out = {'P', 'W', 'A', 'D', 0, 0, 0, 0, 0, 0, 0, 0};
  std::vector<uint8_t> directory;
  for (const std::vector<uint8_t>& part : parts)
    for (const PwadLump& lump : pwad_lumps(part)) {
      uint8_t row[16] = {};
      put_wad_u32(row, uint32_t(out.size()));
      put_wad_u32(row + 4, uint32_t(lump.size));
      std::memcpy(row + 8, lump.name.data(), std::min<size_t>(lump.name.size(), 8));
      directory.insert(directory.end(), row, row + 16);
      out.insert(out.end(), part.begin() + long(lump.at), part.begin() + long(lump.at + lump.size));
    }
  put_wad_u32(&out[4], uint32_t(directory.size() / 16));
  put_wad_u32(&out[8], uint32_t(out.size()));
  out.insert(out.end(), directory.begin(), directory.end());
  return out;
}

}  // namespace lintel::test
