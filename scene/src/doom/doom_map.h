// A Doom map's records, decoded and cross-checked: every index (vertex, sidedef, sector, seg,
// child node) is in range, so the geometry code never checks again. Units are map units; the
// scene builder scales them (docs/levels.md).
#pragma once

#include "doom/doom_wad.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace lintel::doom {

inline constexpr uint16_t kNoSide = 0xffff;
inline constexpr uint16_t kSubsectorBit = 0x8000;  // in a node's child: the rest is a subsector index

struct Thing {
  glm::dvec2 position{0.0};
  int angle_deg = 0;  // 0 = east (+x), counter-clockwise
  uint16_t type = 0;
  uint16_t flags = 0;
};

struct Linedef {
  uint16_t v1 = 0, v2 = 0;
  uint16_t flags = 0, special = 0, tag = 0;
  uint16_t front = kNoSide, back = kNoSide;  // sidedefs: front lies to the right of v1 -> v2
};

struct Sidedef {
  uint16_t sector = 0;
};

struct Seg {
  uint16_t v1 = 0, v2 = 0;
  uint16_t linedef = 0;
  bool reversed = false;  // the seg runs v2 -> v1 of its linedef (it is the back side's)
};

struct Subsector {
  uint16_t seg_count = 0, first_seg = 0;
};

struct Node {
  glm::dvec2 origin{0.0}, direction{0.0};  // partition line; the right side is child[0]
  uint16_t child[2] = {0, 0};              // kSubsectorBit set: a subsector index
};

struct Sector {
  int floor = 0, ceiling = 0;  // heights, map units
  std::string floor_flat, ceiling_flat;
  int light = 0;  // 0..255
  uint16_t special = 0, tag = 0;
};

struct Map {
  std::string name;
  std::vector<Thing> things;
  std::vector<Linedef> linedefs;
  std::vector<Sidedef> sidedefs;
  std::vector<glm::dvec2> vertices;
  std::vector<Seg> segs;
  std::vector<Subsector> subsectors;
  std::vector<Node> nodes;
  std::vector<Sector> sectors;

  // The sector a seg's side faces (its linedef's front sidedef, or back when reversed).
  uint16_t seg_sector(const Seg& seg) const;
};

// Decodes the lumps. Empty string on success, otherwise "PATH: map E1M1: lump LINEDEFS: size 15
// is not a multiple of 14" or "...: linedef 12: vertex 900 out of range (0..466)".
std::string read_map(const Wad& wad, const MapLumps& lumps, Map& out);

}  // namespace lintel::doom
