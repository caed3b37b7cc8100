// A Freedoom map imported as the CLI imports it and written as GLB: the loader's tests on real,
// large input. The WAD comes from Debian's freedoom package; without it the tests skip.
#pragma once

#include <lintel/doom_import.h>
#include <lintel/scene_io.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace lintel::test {

inline const std::string kFreedoomWad = "/usr/share/games/doom/freedoom1.wad";

inline bool freedoom_installed() { return std::filesystem::exists(kFreedoomWad); }

// `map` of freedoom1.wad as GLB bytes, or false when the import or the writer fails.
inline bool imported_level_glb(const std::string& map, std::vector<uint8_t>& glb) {
  SceneDesc scene;
  return import_doom(kFreedoomWad, map, {}, scene).ok() && scene_to_glb(scene, glb).ok();
}

}  // namespace lintel::test
