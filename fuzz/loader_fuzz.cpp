// Property tests of the scene loader on mutated fixtures (rapidcheck): byte flips, truncations,
// splices and deletions of the raw file, and JSON value swaps inside the glTF (GLB containers are
// re-packed around the edited JSON, so the edits reach the parser instead of breaking the header).
// A fixed seed and case count keep ctest fast and repeatable; LINTEL_SOAK=1 runs many more cases,
// and RC_PARAMS (rapidcheck's own settings) overrides both.
#include "world_invariants.h"

#include <lintel/scene_io.h>

#include <nlohmann/json.hpp>
#include <rapidcheck.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

using Bytes = std::vector<uint8_t>;
using nlohmann::json;

Bytes read_fixture(const std::string& relative) {
  std::ifstream in(std::string(LINTEL_SOURCE_DIR) + "/tests/scene/fixtures/" + relative, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Glb {
  std::string json_text;
  Bytes bin;  // the whole BIN chunk payload
};

uint32_t u32(const uint8_t* p) {
  return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}
void put_u32(Bytes& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(uint8_t(v >> (8 * i)));
}

// The fixtures' own GLB, so its layout is known: header, JSON chunk, BIN chunk.
Glb split(const Bytes& glb) {
  const uint32_t json_size = u32(&glb[12]);
  Glb out;
  out.json_text.assign(reinterpret_cast<const char*>(&glb[20]), json_size);
  const size_t bin_at = 20 + json_size;
  out.bin.assign(glb.begin() + long(bin_at + 8), glb.begin() + long(bin_at + 8 + u32(&glb[bin_at])));
  return out;
}

Bytes pack(const Glb& g) {
  std::string js = g.json_text;
  while (js.size() % 4) js += ' ';
  Bytes out = {'g', 'l', 'T', 'F'};
  put_u32(out, 2);
  put_u32(out, uint32_t(12 + 8 + js.size() + 8 + g.bin.size()));
  put_u32(out, uint32_t(js.size()));
  out.insert(out.end(), {'J', 'S', 'O', 'N'});
  out.insert(out.end(), js.begin(), js.end());
  put_u32(out, uint32_t(g.bin.size()));
  out.insert(out.end(), {'B', 'I', 'N', 0});
  out.insert(out.end(), g.bin.begin(), g.bin.end());
  return out;
}

// Values that sit on the loader's edges: index and size limits, float overflow, wrong types,
// and Lintel tags that change a node's role.
const std::vector<json>& interesting_values() {
  static const std::vector<json> values = {-1,
                                           0,
                                           1,
                                           2,
                                           3,
                                           4,
                                           5,
                                           63,
                                           64,
                                           65,
                                           255,
                                           256,
                                           65535,
                                           65536,
                                           2147483647,
                                           2147483648LL,
                                           4294967296LL,
                                           1e308,
                                           -1e308,
                                           1e39,
                                           0.5,
                                           -0.0,
                                           "",
                                           "Hall",
                                           "Kitchen",
                                           "Cellar",
                                           "spot",
                                           "x",
                                           json::array(),
                                           json::object(),
                                           json::array({0, 0, 0}),
                                           json::array({1, 0, 0, 0}),
                                           json::array({0, 0, 0, 0}),
                                           true,
                                           false,
                                           nullptr,
                                           json{{"cell", "Hall"}},
                                           json{{"portal", {{"from", "Hall"}, {"to", "Kitchen"}}}},
                                           json{{"volume", true}},
                                           json{{"lintel", {{"cell", "Kitchen"}}}}};
  return values;
}

// Pointers to every value in `doc`, parents before children (a swap may replace a parent).
void collect(json& value, std::vector<json*>& out) {
  std::vector<json*> stack{&value};
  while (!stack.empty()) {
    json* v = stack.back();
    stack.pop_back();
    out.push_back(v);
    if (v->is_structured())
      for (auto& child : *v) stack.push_back(&child);
  }
}

// Replaces 1..4 values of the JSON text, each by a copy of another value of the same document
// or by an interesting value. Returns false when the text is not JSON (then nothing changes).
bool swap_json_values(std::string& text) {
  json doc = json::parse(text, nullptr, false);
  if (doc.is_discarded()) return false;
  const int swaps = *rc::gen::inRange(1, 5);
  for (int s = 0; s < swaps; ++s) {
    std::vector<json*> values;
    collect(doc, values);
    json* target = values[*rc::gen::inRange<size_t>(0, values.size())];
    if (*rc::gen::inRange(0, 2) == 0) {
      json copy = *values[*rc::gen::inRange<size_t>(0, values.size())];
      *target = std::move(copy);
    } else {
      *target = interesting_values()[*rc::gen::inRange<size_t>(0, interesting_values().size())];
    }
  }
  text = doc.dump();
  return true;
}

void mutate_bytes(Bytes& data) {
  const int edits = *rc::gen::inRange(1, 9);
  for (int e = 0; e < edits && !data.empty(); ++e) {
    const size_t at = *rc::gen::inRange<size_t>(0, data.size());
    switch (*rc::gen::inRange(0, 4)) {
      case 0:
        data[at] ^= *rc::gen::inRange<uint8_t>(1, 255);
        break;  // flip bits
      case 1:
        data.resize(at);
        break;   // truncate
      case 2: {  // splice a copy of a slice
        const size_t from = *rc::gen::inRange<size_t>(0, data.size());
        const size_t length = std::min<size_t>(*rc::gen::inRange<size_t>(1, 256), data.size() - from);
        const Bytes slice(data.begin() + long(from), data.begin() + long(from + length));
        data.insert(data.begin() + long(at), slice.begin(), slice.end());
        break;
      }
      default: {  // delete a range
        const size_t length = std::min<size_t>(*rc::gen::inRange<size_t>(1, 64), data.size() - at);
        data.erase(data.begin() + long(at), data.begin() + long(at + length));
      }
    }
  }
}

// The outcome every input must have: a World that holds together, or an empty World and one
// proper error line. (Crashes, hangs and sanitizer reports fail the test run by themselves.)
void check_outcome(const Bytes& input, const std::string& label) {
  lintel::World world;
  std::vector<std::string> warnings;
  const lintel::Status s = lintel::load_world_from_memory(input.data(), input.size(), label, "", world, &warnings);
  RC_TAG(s.ok() ? "loaded" : "refused");  // the report shows how many mutants still load
  if (s.ok()) {
    const std::string why = lintel::fuzz::world_invariant_violation(world);
    RC_ASSERT(why == "");
    for (const std::string& w : warnings) RC_ASSERT(lintel::fuzz::error_message_violation(w, label) == "");
  } else {
    RC_ASSERT(lintel::fuzz::error_message_violation(s.message(), label) == "");
    RC_ASSERT(world.cells.empty() && world.meshes.empty() && world.portals.empty() && world.source.empty());
  }
}

}  // namespace

int main() {
  const bool soak = std::getenv("LINTEL_SOAK") != nullptr;
  if (!std::getenv("RC_PARAMS")) setenv("RC_PARAMS", soak ? "max_success=20000" : "max_success=300 seed=20240601", 1);

  const Bytes gltf = read_fixture("good/three_rooms.gltf");
  const Bytes glb = read_fixture("good/three_rooms.glb");
  const Bytes warn = read_fixture("warn/cell_without_portals.gltf");
  const Bytes colored = read_fixture("good/vertex_colors.gltf");    // COLOR_0 in every form
  const Bytes cut_out = read_fixture("good/cut_out_table.gltf");    // alphaMode MASK, alphaCutoff, a PNG with alpha
  const Bytes emissive = read_fixture("good/emissive_table.gltf");  // emissiveFactor, -Texture, -Strength
  const Bytes timeline = read_fixture("timelines/orbit.json");
  if (gltf.empty() || glb.empty() || warn.empty() || colored.empty() || cut_out.empty() || emissive.empty() ||
      timeline.empty()) {
    std::fprintf(stderr, "loader_fuzz: fixtures not found under %s/tests/scene/fixtures\n", LINTEL_SOURCE_DIR);
    return 1;
  }
  bool ok = true;

  // Property: any byte-level corruption of a valid .gltf or .glb (flips, truncation, splices,
  // deletions) either loads into a consistent World or fails with one line naming the input;
  // the loader never crashes, hangs or leaves a half-filled World.
  ok &= rc::check("byte mutations of valid scenes load consistently or fail with one line", [&] {
    Bytes data = *rc::gen::element(gltf, glb, warn, colored, cut_out, emissive);
    mutate_bytes(data);
    check_outcome(data, "mutated.bin");
  });

  // Property: swapping JSON values inside a valid scene (copies of other values, or edge values:
  // huge integers, 1e39, wrong types, Lintel tags) either loads into a consistent World or fails
  // with one line naming the input. GLB inputs keep a well-formed container around the new JSON.
  ok &= rc::check("JSON value swaps in valid scenes load consistently or fail with one line", [&] {
    const bool as_glb = *rc::gen::arbitrary<bool>();
    if (as_glb) {
      Glb parts = split(glb);
      swap_json_values(parts.json_text);
      check_outcome(pack(parts), "swapped.glb");
    } else {
      const Bytes* source = *rc::gen::element(&gltf, &colored, &cut_out, &emissive);
      std::string text(source->begin(), source->end());
      swap_json_values(text);
      check_outcome(Bytes(text.begin(), text.end()), "swapped.gltf");
    }
  });

  // Property: a mutated timeline file is either read with its preconditions intact (keys present
  // and increasing, fps and field of view in range) or refused with one line naming the file.
  const std::string timeline_path =
      (std::filesystem::temp_directory_path() / ("lintel_timeline_fuzz_" + std::to_string(::getpid()) + ".json"))
          .string();
  ok &= rc::check("mutated timeline files load within preconditions or fail with one line", [&] {
    std::string text(timeline.begin(), timeline.end());
    if (*rc::gen::arbitrary<bool>()) {
      swap_json_values(text);
    } else {
      Bytes b(text.begin(), text.end());
      mutate_bytes(b);
      text.assign(b.begin(), b.end());
    }
    std::ofstream(timeline_path, std::ios::binary) << text;
    lintel::Timeline t;
    const lintel::Status s = lintel::load_timeline_file(timeline_path, t);
    if (s.ok()) {
      lintel::World w;
      w.timelines.push_back(t);
      RC_ASSERT(lintel::fuzz::world_invariant_violation(w) == "");
    } else {
      RC_ASSERT(lintel::fuzz::error_message_violation(s.message(), timeline_path) == "");
      RC_ASSERT(t.keys.empty());
    }
  });
  std::remove(timeline_path.c_str());
  return ok ? 0 : 1;
}
