// Doom map lumps into records (Unofficial Doom Specs, section 4): fixed record sizes, every index
// checked against its table so that a damaged or hostile WAD ends in a message, not a crash.
#include "doom/doom_map.h"

namespace lintel::doom {
namespace {

struct LumpReader {
  const Wad& wad;
  const std::string& map;
  std::string fail(const std::string& lump, const std::string& why) const {
    return wad.path + ": map " + map + ": lump " + lump + ": " + why;
  }
  // Record count of a lump of `record` bytes each, or an error when the size does not divide.
  std::string count(const char* lump, size_t size, size_t record, size_t& n) const {
    if (size % record != 0)
      return fail(lump,
                  "size " + std::to_string(size) + " is not a multiple of its record size " + std::to_string(record));
    n = size / record;
    return {};
  }
};

std::string range_text(size_t count) {
  return count ? "(0.." + std::to_string(count - 1) + ")" : "(the table is empty)";
}

}  // namespace

uint16_t Map::seg_sector(const Seg& seg) const {
  const Linedef& line = linedefs[seg.linedef];
  return sidedefs[seg.reversed ? line.back : line.front].sector;
}

std::string read_map(const Wad& wad, const MapLumps& l, Map& out) {
  out = {};
  out.name = l.map;
  const LumpReader r{wad, l.map};
  size_t n = 0;
  if (auto e = r.count("VERTEXES", l.vertexes_size, 4, n); !e.empty()) return e;
  for (size_t i = 0; i < n; ++i)
    out.vertices.emplace_back(read_i16(l.vertexes + 4 * i), read_i16(l.vertexes + 4 * i + 2));
  if (auto e = r.count("SECTORS", l.sectors_size, 26, n); !e.empty()) return e;
  if (n == 0) return r.fail("SECTORS", "no sectors");
  for (size_t i = 0; i < n; ++i) {
    const uint8_t* p = l.sectors + 26 * i;
    out.sectors.push_back({read_i16(p), read_i16(p + 2), read_name8(p + 4), read_name8(p + 12), read_i16(p + 20),
                           read_u16(p + 22), read_u16(p + 24)});
  }
  if (auto e = r.count("SIDEDEFS", l.sidedefs_size, 30, n); !e.empty()) return e;
  for (size_t i = 0; i < n; ++i) {
    const uint16_t sector = read_u16(l.sidedefs + 30 * i + 28);
    if (sector >= out.sectors.size())
      return r.fail("SIDEDEFS", "sidedef " + std::to_string(i) + ": sector " + std::to_string(sector) +
                                    " out of range " + range_text(out.sectors.size()));
    out.sidedefs.push_back({sector});
  }
  if (auto e = r.count("LINEDEFS", l.linedefs_size, 14, n); !e.empty()) return e;
  for (size_t i = 0; i < n; ++i) {
    const uint8_t* p = l.linedefs + 14 * i;
    Linedef line{read_u16(p),     read_u16(p + 2),  read_u16(p + 4), read_u16(p + 6),
                 read_u16(p + 8), read_u16(p + 10), read_u16(p + 12)};
    const std::string name = "linedef " + std::to_string(i) + ": ";
    if (line.v1 >= out.vertices.size() || line.v2 >= out.vertices.size())
      return r.fail("LINEDEFS", name + "vertex " + std::to_string(std::max(line.v1, line.v2)) + " out of range " +
                                    range_text(out.vertices.size()));
    if (line.front == kNoSide || line.front >= out.sidedefs.size())
      return r.fail("LINEDEFS", name + "front sidedef " + std::to_string(line.front) + " out of range " +
                                    range_text(out.sidedefs.size()));
    if (line.back != kNoSide && line.back >= out.sidedefs.size())
      return r.fail("LINEDEFS", name + "back sidedef " + std::to_string(line.back) + " out of range " +
                                    range_text(out.sidedefs.size()));
    out.linedefs.push_back(line);
  }
  if (auto e = r.count("SEGS", l.segs_size, 12, n); !e.empty()) return e;
  for (size_t i = 0; i < n; ++i) {
    const uint8_t* p = l.segs + 12 * i;
    Seg seg{read_u16(p), read_u16(p + 2), read_u16(p + 6), read_u16(p + 8) != 0};
    const std::string name = "seg " + std::to_string(i) + ": ";
    if (seg.v1 >= out.vertices.size() || seg.v2 >= out.vertices.size())
      return r.fail("SEGS", name + "vertex out of range " + range_text(out.vertices.size()));
    if (seg.linedef >= out.linedefs.size())
      return r.fail(
          "SEGS", name + "linedef " + std::to_string(seg.linedef) + " out of range " + range_text(out.linedefs.size()));
    if (seg.reversed && out.linedefs[seg.linedef].back == kNoSide)
      return r.fail("SEGS", name + "lies on the back of one-sided linedef " + std::to_string(seg.linedef));
    out.segs.push_back(seg);
  }
  if (auto e = r.count("SSECTORS", l.ssectors_size, 4, n); !e.empty()) return e;
  if (n == 0) return r.fail("SSECTORS", "no subsectors (the map has no node build)");
  for (size_t i = 0; i < n; ++i) {
    const Subsector s{read_u16(l.ssectors + 4 * i), read_u16(l.ssectors + 4 * i + 2)};
    if (s.seg_count == 0 || size_t(s.first_seg) + s.seg_count > out.segs.size())
      return r.fail("SSECTORS", "subsector " + std::to_string(i) + ": segs " + std::to_string(s.first_seg) + "+" +
                                    std::to_string(s.seg_count) + " out of range " + range_text(out.segs.size()));
    out.subsectors.push_back(s);
  }
  if (auto e = r.count("NODES", l.nodes_size, 28, n); !e.empty()) return e;
  for (size_t i = 0; i < n; ++i) {
    const uint8_t* p = l.nodes + 28 * i;
    Node node{{read_i16(p), read_i16(p + 2)}, {read_i16(p + 4), read_i16(p + 6)}, {read_u16(p + 24), read_u16(p + 26)}};
    if (node.direction == glm::dvec2(0.0))
      return r.fail("NODES", "node " + std::to_string(i) + ": partition has no direction");
    for (uint16_t child : node.child) {
      // Children come before their parent in the lump (the builder writes them bottom-up), which
      // also rules out cycles.
      const bool leaf = (child & kSubsectorBit) != 0;
      const size_t index = child & ~kSubsectorBit;
      if (leaf ? index >= out.subsectors.size() : index >= i)
        return r.fail("NODES", "node " + std::to_string(i) + ": child " + std::to_string(index) +
                                   (leaf ? " is not a subsector " + range_text(out.subsectors.size())
                                         : " is not an earlier node"));
    }
    out.nodes.push_back(node);
  }
  if (out.nodes.empty() && out.subsectors.size() != 1) return r.fail("NODES", "no nodes for several subsectors");
  if (auto e = r.count("THINGS", l.things_size, 10, n); !e.empty()) return e;
  for (size_t i = 0; i < n; ++i) {
    const uint8_t* p = l.things + 10 * i;
    out.things.push_back({{read_i16(p), read_i16(p + 2)}, read_i16(p + 4), read_u16(p + 6), read_u16(p + 8)});
  }
  return {};
}

}  // namespace lintel::doom
