// `import rooms` entry points: the loader's own safe reading path (size-capped file, GLB
// container, bounded JSON, preflight of buffers and URIs, the model, nodes and hierarchy), then
// rooms_assemble.cpp, then the loader once more on the result (with a doorway walk added), so an
// imported scene always loads and `lintel walk` runs on it.
#include "read/file_read.h"
#include "read/glb_container.h"
#include "read/gltf_model.h"
#include "read/gltf_preflight.h"
#include "read/json_bounded.h"
#include "read/load_context.h"
#include "read/node_hierarchy.h"
#include "read/node_read.h"
#include "rooms/rooms_assemble.h"
#include "rooms/rooms_walk.h"

#include <lintel/rooms_import.h>
#include <lintel/scene_io.h>

#include <tiny_gltf.h>

#include <exception>

namespace lintel {
namespace {

using scene_read::LoadContext;

Status import_pipeline(const LoadContext& ctx, const uint8_t* bytes, size_t size, const std::string& base_dir,
                       SceneDesc& out, RoomsImportStats& stats) {
  if (size == 0) return ctx.fail("", "the file is empty");
  if (size > kMaxSceneFileBytes) return ctx.fail("", "is " + std::to_string(size) + " bytes, over the limit");
  const bool glb = scene_read::looks_like_glb(bytes, size);
  scene_read::GlbChunks chunks;
  const char* json_text = reinterpret_cast<const char*>(bytes);
  size_t json_size = size;
  if (glb) {
    if (std::string why = scene_read::split_glb(bytes, size, chunks); !why.empty()) return ctx.fail("", why);
    json_text = chunks.json;
    json_size = chunks.json_size;
  }
  nlohmann::json doc;
  if (std::string why = scene_read::parse_json_bounded(json_text, json_size, doc); !why.empty())
    return ctx.fail("", why);
  scene_read::PreflightResult preflight;
  if (Status s = scene_read::preflight_gltf(ctx, doc, glb ? &chunks : nullptr, base_dir, preflight); !s) return s;
  tinygltf::Model model;
  if (Status s = scene_read::read_gltf_model(ctx, doc, glb ? &chunks : nullptr, preflight, model); !s) return s;
  std::vector<scene_read::NodeRecord> nodes;
  if (Status s = scene_read::read_nodes(ctx, doc, model.meshes.size(), model.lights.size(), nodes); !s) return s;
  scene_read::SceneChoice choice;
  if (Status s = scene_read::read_scene_choice(ctx, doc, nodes.size(), choice); !s) return s;
  scene_read::SceneGraph graph;
  if (Status s = scene_read::build_scene_graph(ctx, nodes, choice, graph); !s) return s;
  return rooms::assemble_rooms_scene(ctx, model, nodes, graph, base_dir, out, stats);
}

Status guarded_import(const std::string& label, const uint8_t* bytes, size_t size, const std::string& base_dir,
                      SceneDesc& out, std::vector<std::string>* warnings, RoomsImportStats* stats) {
  out = {};
  std::vector<std::string> local_warnings;
  LoadContext ctx(label, &local_warnings);
  RoomsImportStats counts;
  SceneDesc scene;
  Status status;
  try {
    status = import_pipeline(ctx, bytes, size, base_dir, scene, counts);
  } catch (const std::bad_alloc&) {
    status = ctx.fail("", "out of memory while importing");
  } catch (const std::exception& e) {
    status = ctx.fail("", std::string("internal error while importing: ") + e.what());
  }
  if (!status) return status;
  // The result must be a scene the loader accepts; a refusal here is a gap in the importer's own
  // checks, reported against the input file.
  World world;
  if (Status s = build_world(scene, label + " (imported)", world); !s)
    return Status::error(label + ": the imported scene does not load: " + s.message());
  Timeline walk;
  if (rooms::doorway_walk(world, walk)) {
    scene.timelines.push_back(std::move(walk));
    if (Status s = build_world(scene, label + " (imported)", world); !s)
      return Status::error(label + ": the imported scene's doorway walk does not load: " + s.message());
  }
  out = std::move(scene);
  if (warnings) warnings->insert(warnings->end(), local_warnings.begin(), local_warnings.end());
  if (stats) *stats = counts;
  return {};
}

}  // namespace

Status import_rooms(const std::string& path, SceneDesc& out, std::vector<std::string>* warnings,
                    RoomsImportStats* stats) {
  out = {};
  std::vector<uint8_t> bytes;
  try {
    if (std::string why = scene_read::read_file_bounded(path, kMaxSceneFileBytes, bytes); !why.empty())
      return LoadContext(path, nullptr).fail("", why);
  } catch (const std::exception& e) {
    return LoadContext(path, nullptr).fail("", std::string("cannot read: ") + e.what());
  }
  return guarded_import(path, bytes.data(), bytes.size(), scene_read::directory_of(path), out, warnings, stats);
}

Status import_rooms_from_memory(const uint8_t* bytes, size_t size, const std::string& label,
                                const std::string& base_dir, SceneDesc& out, std::vector<std::string>* warnings,
                                RoomsImportStats* stats) {
  out = {};
  if (!bytes && size > 0) return LoadContext(label, nullptr).fail("", "no data (null pointer)");
  return guarded_import(label, bytes, size, base_dir, out, warnings, stats);
}

}  // namespace lintel
