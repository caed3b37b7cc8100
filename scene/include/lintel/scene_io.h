// Reading and writing Lintel scenes (glTF 2.0 with extras.lintel, docs/scene-format.md).
// All functions report bad data through Status with a one-line message naming the file, the
// element (node index and name, accessor, key) and the fault; none throws, none crashes on any
// input, and memory stays bounded (files over kMaxSceneFileBytes are refused).
#pragma once

#include <lintel/scene_desc.h>
#include <lintel/status.h>
#include <lintel/world.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace lintel {

inline constexpr size_t kMaxSceneFileBytes = size_t{1} << 30;  // 1 GiB: no scene we know is near it

// Loads and validates `path` (.gltf with its buffers, or .glb) into `out`. On error `out` is left
// empty. Suspicious but usable data (a cell without portals, ...) adds lines to `warnings`.
// The content decides GLB vs JSON (the "glTF" magic), not the extension; external buffers are
// resolved beside `path`. The rules, tolerances, limits and every message are listed in
// docs/scene-format.md. A failed load adds no warnings.
Status load_world(const std::string& path, World& out, std::vector<std::string>* warnings = nullptr);

struct LoadOptions {
  // Buffer and image URIs must resolve (after percent-decoding, "..", and symlinks) to files
  // inside the scene's folder; true lifts that rule for users who keep assets elsewhere.
  bool allow_outside_paths = false;
  // Memory the load may use: the scene file plus its buffers must fit, checked from their sizes
  // before anything is read. 0: only the fixed limits (docs/scene-format.md) apply.
  uint64_t max_memory_bytes = 0;
};
Status load_world(const std::string& path, const LoadOptions& options, World& out,
                  std::vector<std::string>* warnings = nullptr);

// The same validation on an in-memory file; `label` names it in messages, `base_dir` resolves
// external buffer URIs (may be empty: then only embedded/GLB buffers are allowed).
Status load_world_from_memory(const uint8_t* bytes, size_t size, const std::string& label, const std::string& base_dir,
                              World& out, std::vector<std::string>* warnings = nullptr);

// Writes `scene` to `path`: .gltf (+ a .bin beside it) or .glb, chosen by the extension. Writes
// to temporary files and renames, so a failure leaves nothing half-written.
Status save_scene(const SceneDesc& scene, const std::string& path);

// Serializes `scene` to GLB bytes in memory (what the property tests load back).
Status scene_to_glb(const SceneDesc& scene, std::vector<uint8_t>& out);

// SceneDesc -> GLB -> load_world: how tests and generators obtain a validated World.
Status build_world(const SceneDesc& scene, const std::string& label, World& out,
                   std::vector<std::string>* warnings = nullptr);

// Reads a standalone timeline file (the timeline object of the scene format, as JSON, at most
// 64 MiB). On error `out` is left as a default Timeline (no keys).
Status load_timeline_file(const std::string& path, Timeline& out);

}  // namespace lintel
