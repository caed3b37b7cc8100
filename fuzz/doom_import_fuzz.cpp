// Property test of `import doom` on hostile WADs (rapidcheck): a real map (freedoom1.wad's E2M8,
// copied into a small PWAD of its own) with its records edited field by field (indices, counts and
// coordinates set to the values at the reader's edges), its directory's sizes and offsets edited,
// and raw bytes flipped, cut, spliced or deleted. A fixed seed and case count keep ctest fast;
// LINTEL_SOAK=1 runs many more, RC_PARAMS (rapidcheck's own settings) overrides both. Skipped
// (exit 0, with the reason) when the Debian package `freedoom` is not installed.
#include "map_pwad.h"
#include "world_invariants.h"

#include <lintel/doom_import.h>
#include <lintel/scene_io.h>

#include <rapidcheck.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

using Bytes = std::vector<uint8_t>;

const char* const kWad = "/usr/share/games/doom/freedoom1.wad";
const char* const kMap = "E2M8";
const char* const kLabel = "fuzz.wad";

using lintel::test::map_pwad;
using LumpAt = lintel::test::PwadLump;

// Record sizes of the map lumps the importer reads (vanilla Doom format).
size_t record_size(const std::string& lump) {
  if (lump == "THINGS") return 10;
  if (lump == "LINEDEFS") return 14;
  if (lump == "SIDEDEFS") return 30;
  if (lump == "VERTEXES") return 4;
  if (lump == "SEGS") return 12;
  if (lump == "SSECTORS") return 4;
  if (lump == "NODES") return 28;
  if (lump == "SECTORS") return 26;
  return 0;
}

// One 16-bit field of one record set to a value at an edge: 0, 1, -1, the extremes, and the
// lump's own record count and its neighbours (an index just in or out of range).
void edit_field(Bytes& pwad, const LumpAt& lump) {
  const size_t record = record_size(lump.name);
  if (record == 0 || lump.size < record || lump.at + lump.size > pwad.size()) return;
  const size_t r = *rc::gen::inRange<size_t>(0, lump.size / record);
  const size_t field = 2 * *rc::gen::inRange<size_t>(0, record / 2);
  const int count = int(lump.size / record);
  const int values[] = {0, 1, -1, 2, 0x7fff, -0x8000, 0x8000 | 1, count, count - 1, count + 1, 4096, -4096};
  const int v = values[*rc::gen::inRange<size_t>(0, std::size(values))];
  uint8_t* p = &pwad[lump.at + r * record + field];
  p[0] = uint8_t(v & 0xff);
  p[1] = uint8_t((v >> 8) & 0xff);
}

// A directory entry's size or offset moved by a little or a lot.
void edit_directory(Bytes& pwad, const LumpAt& lump) {
  const size_t field = lump.entry + (*rc::gen::inRange(0, 2) == 0 ? 0 : 4);
  const int64_t deltas[] = {-1, 1, -2, 2, -4, 4, -14, 14, -28, 28, 1 << 20, -(int64_t(1) << 31)};
  const int64_t d = deltas[*rc::gen::inRange<size_t>(0, std::size(deltas))];
  lintel::test::put_wad_u32(&pwad[field], uint32_t(int64_t(lintel::test::wad_u32(&pwad[field])) + d));
}

void edit_bytes(Bytes& data) {
  const size_t at = *rc::gen::inRange<size_t>(0, data.size());
  switch (*rc::gen::inRange(0, 4)) {
    case 0:
      data[at] ^= *rc::gen::inRange<uint8_t>(1, 255);
      break;
    case 1:
      data.resize(at);
      break;
    case 2: {  // a copy of a slice, spliced in
      const size_t from = *rc::gen::inRange<size_t>(0, data.size());
      const size_t length = std::min<size_t>(*rc::gen::inRange<size_t>(1, 64), data.size() - from);
      const Bytes slice(data.begin() + long(from), data.begin() + long(from + length));
      data.insert(data.begin() + long(at), slice.begin(), slice.end());
      break;
    }
    default: {
      const size_t length = std::min<size_t>(*rc::gen::inRange<size_t>(1, 64), data.size() - at);
      data.erase(data.begin() + long(at), data.begin() + long(at + length));
    }
  }
}

// The outcome every input must have: a scene the loader accepts or refuses with one proper line,
// or one proper error line from the importer and an empty scene. (Crashes, hangs and sanitizer
// reports fail the run by themselves.)
void check_outcome(const Bytes& input, bool convex) {
  lintel::DoomImportOptions options;
  options.convex_cells = convex;
  lintel::SceneDesc scene;
  const lintel::Status imported = lintel::import_doom_from_memory(input, kLabel, kMap, options, scene);
  if (!imported) {
    RC_TAG("refused");
    RC_ASSERT(imported.kind() == lintel::StatusKind::BadInput);
    RC_ASSERT(lintel::fuzz::error_message_violation(imported.message(), kLabel) == "");
    RC_ASSERT(scene.nodes.empty() && scene.meshes.empty());
    return;
  }
  lintel::World world;
  const lintel::Status loaded = lintel::build_world(scene, kLabel, world);
  RC_TAG(loaded.ok() ? "imported and loaded" : "imported, refused by the loader");
  if (loaded.ok()) {
    RC_ASSERT(lintel::fuzz::world_invariant_violation(world) == "");
  } else {
    RC_ASSERT(lintel::fuzz::error_message_violation(loaded.message(), kLabel) == "");
  }
}

}  // namespace

int main() {
  if (!std::filesystem::exists(kWad)) {
    std::printf("doom_import_fuzz: skipped, %s is missing (apt-get install freedoom)\n", kWad);
    return 0;
  }
  const bool soak = std::getenv("LINTEL_SOAK") != nullptr;
  if (!std::getenv("RC_PARAMS")) setenv("RC_PARAMS", soak ? "max_success=5000" : "max_success=400 seed=20261127", 1);
  std::ifstream in(kWad, std::ios::binary);
  const Bytes wad{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const Bytes base = map_pwad(wad, kMap);
  if (base.empty()) {
    std::printf("doom_import_fuzz: %s has no map %s\n", kWad, kMap);
    return 1;
  }

  bool ok = true;
  // Property: whatever the records hold (indices and counts at the reader's edges, coordinates at
  // the extremes), the importer answers with a scene or one proper error line, never a crash.
  ok &= rc::check("an edited record gives a scene or one error line", [&base] {
    Bytes pwad = base;
    const std::vector<LumpAt> lumps = lintel::test::pwad_lumps(pwad);
    const int edits = *rc::gen::inRange(1, 5);
    for (int e = 0; e < edits; ++e) edit_field(pwad, lumps[*rc::gen::inRange<size_t>(1, lumps.size())]);
    check_outcome(pwad, *rc::gen::arbitrary<bool>());
  });
  // Property: a directory whose sizes or offsets lie (truncated lumps, overlaps, offsets past the
  // end) gives one proper error line or a scene.
  ok &= rc::check("an edited directory gives a scene or one error line", [&base] {
    Bytes pwad = base;
    const std::vector<LumpAt> lumps = lintel::test::pwad_lumps(pwad);
    edit_directory(pwad, lumps[*rc::gen::inRange<size_t>(0, lumps.size())]);
    check_outcome(pwad, *rc::gen::arbitrary<bool>());
  });
  // Property: raw byte edits anywhere in the file (header, data, directory) likewise.
  ok &= rc::check("edited bytes give a scene or one error line", [&base] {
    Bytes pwad = base;
    const int edits = *rc::gen::inRange(1, 5);
    for (int e = 0; e < edits && !pwad.empty(); ++e) edit_bytes(pwad);
    check_outcome(pwad, *rc::gen::arbitrary<bool>());
  });
  return ok ? 0 : 1;
}
