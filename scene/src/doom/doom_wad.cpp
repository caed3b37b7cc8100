// WAD header and directory: every lump must lie inside the file, so that the map reader can trust
// offsets. Maps are found by their marker lump and the named lumps that follow it.
#include "doom/doom_wad.h"

#include "read/file_read.h"

#include <algorithm>
#include <array>
#include <cctype>

namespace lintel::doom {
namespace {

constexpr size_t kMaxWadBytes = size_t{1} << 30;  // Freedoom's largest IWAD is 28 MB
constexpr size_t kHeaderBytes = 12;
constexpr size_t kDirectoryEntryBytes = 16;
// The lumps of a map in their canonical order; the first eight are needed.
constexpr std::array<const char*, 10> kMapLumps = {"THINGS",   "LINEDEFS", "SIDEDEFS", "VERTEXES", "SEGS",
                                                   "SSECTORS", "NODES",    "SECTORS",  "REJECT",   "BLOCKMAP"};

std::string upper(std::string s) {
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::string read_name8(const uint8_t* p) {
  std::string name;
  for (int i = 0; i < 8 && p[i] != 0; ++i) name.push_back(char(std::toupper(p[i])));
  return name;
}

std::string parse_wad(std::vector<uint8_t> bytes, const std::string& label, Wad& out) {
  out = {};
  out.path = label;
  if (bytes.size() < kHeaderBytes)
    return label + ": header: file is " + std::to_string(bytes.size()) + " bytes, too short for a WAD";
  const std::string magic(bytes.begin(), bytes.begin() + 4);
  if (magic != "IWAD" && magic != "PWAD") return label + ": header: not a WAD file (magic is not IWAD or PWAD)";
  const uint32_t count = read_u32(&bytes[4]), directory = read_u32(&bytes[8]);
  if (uint64_t(directory) + uint64_t(count) * kDirectoryEntryBytes > bytes.size())
    return label + ": directory: " + std::to_string(count) + " entries at offset " + std::to_string(directory) +
           " run past the end of the file (" + std::to_string(bytes.size()) + " bytes; truncated?)";
  out.lumps.reserve(count);
  for (uint32_t i = 0; i < count; ++i) {
    const uint8_t* e = &bytes[directory + size_t(i) * kDirectoryEntryBytes];
    WadLump lump{read_name8(e + 8), read_u32(e), read_u32(e + 4)};
    if (uint64_t(lump.offset) + lump.size > bytes.size())
      return label + ": lump " + std::to_string(i) + " '" + lump.name + "': bytes " + std::to_string(lump.offset) +
             ".." + std::to_string(uint64_t(lump.offset) + lump.size) + " run past the end of the file (" +
             std::to_string(bytes.size()) + " bytes; truncated?)";
    out.lumps.push_back(std::move(lump));
  }
  out.bytes = std::move(bytes);
  return {};
}

std::string read_wad(const std::string& path, Wad& out) {
  std::vector<uint8_t> bytes;
  if (std::string why = scene_read::read_file_bounded(path, kMaxWadBytes, bytes); !why.empty())
    return path + ": " + why;
  return parse_wad(std::move(bytes), path, out);
}

std::string find_map(const Wad& wad, const std::string& map, MapLumps& out) {
  out = {};
  const std::string want = upper(map);
  out.map = want;
  size_t marker = wad.lumps.size();
  for (size_t i = 0; i < wad.lumps.size(); ++i)
    if (wad.lumps[i].name == want) {
      marker = i;
      break;
    }
  if (marker == wad.lumps.size()) return wad.path + ": map '" + map + "' not found (no lump of that name)";
  // Formats of the same family this reader does not parse, named instead of misread: their
  // records have other sizes, and a size can still divide by the vanilla one (16-byte Hexen
  // linedefs, 7 of them, are 8 vanilla ones).
  if (marker + 1 < wad.lumps.size() && wad.lumps[marker + 1].name == "TEXTMAP")
    return wad.path + ": map " + want + ": UDMF map (lump TEXTMAP): only the vanilla Doom format is read";
  for (size_t i = marker + 1; i < wad.lumps.size() && i <= marker + kMapLumps.size() + 1; ++i)
    if (wad.lumps[i].name == "BEHAVIOR")
      return wad.path + ": map " + want + ": Hexen-format map (lump BEHAVIOR): only the vanilla Doom format is read";
  struct Slot {
    const uint8_t** data;
    size_t* size;
  };
  const std::array<Slot, 8> slots = {{{&out.things, &out.things_size},
                                      {&out.linedefs, &out.linedefs_size},
                                      {&out.sidedefs, &out.sidedefs_size},
                                      {&out.vertexes, &out.vertexes_size},
                                      {&out.segs, &out.segs_size},
                                      {&out.ssectors, &out.ssectors_size},
                                      {&out.nodes, &out.nodes_size},
                                      {&out.sectors, &out.sectors_size}}};
  // The map's lumps are the named ones right after the marker (stop at the first other name).
  for (size_t i = marker + 1; i < wad.lumps.size() && i <= marker + kMapLumps.size(); ++i) {
    const auto known =
        std::find_if(kMapLumps.begin(), kMapLumps.end(), [&](const char* n) { return wad.lumps[i].name == n; });
    if (known == kMapLumps.end()) break;
    const size_t k = size_t(known - kMapLumps.begin());
    if (k >= slots.size()) continue;
    *slots[k].data = wad.bytes.data() + wad.lumps[i].offset;
    *slots[k].size = wad.lumps[i].size;
  }
  for (size_t k = 0; k < slots.size(); ++k)
    if (*slots[k].data == nullptr)
      return wad.path + ": map " + want + ": lump " + kMapLumps[k] + " missing after the map marker";
  // ZDoom's extended and compressed node formats start with their signature.
  if (out.nodes_size >= 4) {
    const std::string signature(reinterpret_cast<const char*>(out.nodes), 4);
    for (const char* zdoom : {"XNOD", "ZNOD", "XGLN", "ZGLN", "XGL2", "ZGL2", "XGL3", "ZGL3"})
      if (signature == zdoom)
        return wad.path + ": map " + want + ": lump NODES: ZDoom " + signature +
               " nodes: only vanilla nodes are read (rebuild the nodes with a vanilla node builder)";
  }
  return {};
}

std::vector<std::string> map_names(const Wad& wad) {
  std::vector<std::string> names;
  for (size_t i = 0; i + 1 < wad.lumps.size(); ++i)
    if (wad.lumps[i + 1].name == "THINGS" && wad.lumps[i].size == 0) names.push_back(wad.lumps[i].name);
  return names;
}

}  // namespace lintel::doom
