// The glTF JSON as the loader reads it: parse_json_bounded's DOM without the accessors' bounds,
// which nothing reads (the loader computes every mesh's real extent from its positions) and which
// are a third of an imported level's text. This is the only parse of the text: preflight, the
// model (gltf_model.h) and the Lintel extras read this DOM, and the accessors and meshes that the
// parse read into structs instead (gltf_compact.h).
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>

namespace lintel::scene_read {

struct CompactSections;

// parse_json_bounded(text, size, out) -- the same limits, the same reasons on failure -- except
// that `out` leaves out each accessor's "min" and "max" (an accessor: an object in the top-level
// "accessors" array). Preflight's integer check (gltf_preflight.h) covers those parts too, so when
// any integer in them lies outside the 32-bit range, `out` is the whole document and preflight
// reports the first such integer as before.
//
// With `integers_fit`, also says whether every integer that preflight checks (all but those under
// an "extras" or "extensions" key) fits 32 bits, as seen while parsing; false when unsure.
// Preflight then need not walk the DOM to find out (gltf_preflight.h).
//
// With `compact`, the root's "accessors" and "meshes" are read into it instead of the DOM when
// they are clean (gltf_compact.h; `compact->has_*` says which); otherwise they are in the DOM.
std::string parse_gltf_json(const char* text, size_t size, nlohmann::json& out, bool* integers_fit = nullptr,
                            CompactSections* compact = nullptr);

}  // namespace lintel::scene_read
