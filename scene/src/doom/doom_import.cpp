// `import doom`: WAD -> map records -> level (pieces, heights) -> SceneDesc (cells, portals,
// things, lights, walk). Every failure before the scene is built names the file, map and lump.
#include <lintel/doom_import.h>

#include "doom/doom_level.h"
#include "doom/doom_map.h"
#include "doom/doom_wad.h"

namespace lintel {
namespace {

Status import_map(const doom::Wad& wad, const std::string& map_name, const DoomImportOptions& options, SceneDesc& out,
                  DoomImportStats* stats) {
  out = {};
  doom::MapLumps lumps;
  if (std::string why = doom::find_map(wad, map_name, lumps); !why.empty()) return Status::error(why);
  doom::Map map;
  if (std::string why = doom::read_map(wad, lumps, map); !why.empty()) return Status::error(why);
  doom::Level level;
  DoomImportStats counts;
  doom::prepare_level(std::move(map), level, counts.doors, counts.lowered_floors);
  SceneDesc scene;
  doom::add_cells_and_portals(level, options, scene, counts);
  if (counts.cells == 0)
    return Status::error(wad.path + ": map " + lumps.map +
                         ": lump SECTORS: no sector has a floor area and an open height");
  doom::add_things_and_lights(level, scene, counts);
  doom::add_doorway_walk(level, options.walk_crossings, scene, counts);
  out = std::move(scene);
  if (stats) *stats = counts;
  return {};
}

}  // namespace

Status import_doom(const std::string& wad_path, const std::string& map, const DoomImportOptions& options,
                   SceneDesc& out, DoomImportStats* stats) {
  out = {};
  doom::Wad wad;
  if (std::string why = doom::read_wad(wad_path, wad); !why.empty()) return Status::error(why);
  return import_map(wad, map, options, out, stats);
}

Status import_doom_from_memory(std::vector<uint8_t> wad_bytes, const std::string& label, const std::string& map,
                               const DoomImportOptions& options, SceneDesc& out, DoomImportStats* stats) {
  out = {};
  doom::Wad wad;
  if (std::string why = doom::parse_wad(std::move(wad_bytes), label, wad); !why.empty()) return Status::error(why);
  return import_map(wad, map, options, out, stats);
}

Status doom_map_names(const std::string& wad_path, std::vector<std::string>& out) {
  out.clear();
  doom::Wad wad;
  if (std::string why = doom::read_wad(wad_path, wad); !why.empty()) return Status::error(why);
  out = doom::map_names(wad);
  if (out.empty()) return Status::error(wad_path + ": directory: no map (no marker lump followed by THINGS)");
  return {};
}

}  // namespace lintel
