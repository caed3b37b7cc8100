// Doom-format maps (Freedoom, Debian package `freedoom`) as Lintel scenes: sectors become cells,
// two-sided lines portals over their open span, things instances, bright sectors lights, plus a
// walk through doorways. Scale, axes and every rule: docs/levels.md.
#pragma once

#include <lintel/scene_desc.h>
#include <lintel/status.h>

#include <string>
#include <vector>

namespace lintel {

inline constexpr double kDoomMetersPerUnit = 1.0 / 32.0;  // a 56-unit player is 1.75 m tall

struct DoomImportOptions {
  // Doors (closed sectors next to a door line or tagged by one) are opened to their neighbours'
  // lowest ceiling minus 4 units either way; closed: their portals carry
  // extras.lintel.portal.open = false.
  bool doors_open = true;
  uint32_t walk_crossings = 24;  // lines (portals and teleporters) the "doorway" timeline crosses at most
  // Non-convex sectors as several cells: the sector's outline (its lines) cut exactly into convex
  // pieces, merged greedily into unions whose convex hull exceeds their area by at most
  // `convex_hull_excess` (relative), each union a cell, joined by always-open portals along the
  // cuts (floor to ceiling); disjoint loops become separate cells. A sector whose lines do not
  // bound it as a polygon with holes, or that lies beside a self-referencing line, stays one cell,
  // as does one whose own convex hull exceeds its area by no more than
  // `convex_min_sector_excess`. Off: one cell per sector (docs/levels.md, "Convex cells").
  bool convex_cells = false;
  double convex_hull_excess = 0.1;
  double convex_min_sector_excess = 0.0;
};

struct DoomImportStats {
  uint32_t sectors = 0, cells = 0, solid_sectors = 0, doors = 0;
  uint32_t lowered_floors = 0;  // sealed platforms imported with their floor lowered (docs/levels.md)
  uint32_t portals = 0, instances = 0, lights = 0, walk_crossings = 0;
  uint32_t walk_teleports = 0;    // teleporter lines the doorway walk takes (not in walk_crossings)
  uint32_t split_sectors = 0;     // sectors imported as more than one cell (convex_cells)
  uint32_t inner_portals = 0;     // portals between cells of one sector (counted in `portals` too)
  uint32_t outline_failures = 0;  // sectors kept whole because their lines do not bound them exactly
};

// Reads map `map` ("E1M1", "MAP01"; case-insensitive) of the WAD at `wad_path` into `out`.
// Errors (bad input): one line naming the file, map and lump ("freedoom1.wad: map E1M1: lump
// LINEDEFS: size 15 is not a multiple of its record size 14"). `out` is left empty on error.
Status import_doom(const std::string& wad_path, const std::string& map, const DoomImportOptions& options,
                   SceneDesc& out, DoomImportStats* stats = nullptr);

// The same from WAD bytes in memory (tests); `label` names them in messages.
Status import_doom_from_memory(std::vector<uint8_t> wad_bytes, const std::string& label, const std::string& map,
                               const DoomImportOptions& options, SceneDesc& out, DoomImportStats* stats = nullptr);

// The maps of a WAD in directory order ("E1M1", ...). Errors as above.
Status doom_map_names(const std::string& wad_path, std::vector<std::string>& out);

}  // namespace lintel
