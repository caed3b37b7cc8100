// The loader's entry points: load_world() reads the file (size-capped), load_world_from_memory()
// runs the pipeline: container -> bounded JSON, parsed once (without the accessors' bounds) ->
// preflight -> the model (gltf_model.h; images not decoded) -> nodes, hierarchy, Lintel extras ->
// World (decoding the base colour textures it draws with).
// Nothing throws past this file; on error `out` stays empty.
#include "read/file_read.h"
#include "read/glb_container.h"
#include "read/gltf_compact.h"
#include "read/gltf_json.h"
#include "read/gltf_model.h"
#include "read/gltf_preflight.h"
#include "read/lintel_extras.h"
#include "read/load_context.h"
#include "read/node_hierarchy.h"
#include "read/node_read.h"
#include "read/world_assemble.h"

#include <lintel/scene_io.h>
#include <lintel/timeline.h>

#include <tiny_gltf.h>

#include <algorithm>
#include <exception>

namespace lintel::scene_read {
namespace {

Status load_pipeline(const LoadContext& ctx, const uint8_t* bytes, size_t size, const std::string& base_dir,
                     World& out) {
  if (size == 0) return ctx.fail("", "the file is empty");
  if (size > kMaxSceneFileBytes)
    return ctx.fail("", "is " + std::to_string(size) + " bytes, over the limit of " +
                            std::to_string(kMaxSceneFileBytes) + " bytes");
  const bool glb = looks_like_glb(bytes, size);
  GlbChunks chunks;
  const char* json_text = reinterpret_cast<const char*>(bytes);
  size_t json_size = size;
  if (glb) {
    if (std::string why = split_glb(bytes, size, chunks); !why.empty()) return ctx.fail("", why);
    json_text = chunks.json;
    json_size = chunks.json_size;
  }
  nlohmann::json doc;
  bool integers_fit = false;
  CompactSections compact;  // the accessors and meshes, when clean, read without the DOM
  if (std::string why = parse_gltf_json(json_text, json_size, doc, &integers_fit, &compact); !why.empty())
    return ctx.fail("", why);

  PreflightResult preflight;
  if (Status s = preflight_gltf(ctx, doc, glb ? &chunks : nullptr, base_dir, preflight, integers_fit, &compact); !s)
    return s;
  tinygltf::Model model;
  if (Status s = read_gltf_model(ctx, doc, glb ? &chunks : nullptr, preflight, model, &compact); !s) return s;

  std::vector<NodeRecord> nodes;
  if (Status s = read_nodes(ctx, doc, model.meshes.size(), model.lights.size(), nodes); !s) return s;
  SceneChoice choice;
  if (Status s = read_scene_choice(ctx, doc, nodes.size(), choice); !s) return s;
  if (!choice.scene && !nodes.empty()) ctx.warn("", "the file has no scene; every root node is used");
  SceneGraph graph;
  if (Status s = build_scene_graph(ctx, nodes, choice, graph); !s) return s;
  size_t outside = 0;
  for (uint8_t in : graph.in_scene) outside += in ? 0 : 1;
  if (outside > 0) ctx.warn(choice.element, std::to_string(outside) + " nodes are not part of the scene (ignored)");

  SceneTag tag;
  if (Status s = read_scene_tag(ctx, choice.scene ? choice.element : "scene", choice.scene, tag); !s) return s;
  // A World without a cell has nowhere to put an eye, an instance or a light: every command would
  // fail later (or did: `lintel view` crashed on a plain glTF file). Said here, once, before the
  // assembly warns about each mesh node outside a cell.
  const bool has_cell = std::any_of(nodes.begin(), nodes.end(), [&](const NodeRecord& n) {
    return graph.in_scene[size_t(&n - nodes.data())] && n.tag.kind == NodeTag::Kind::Cell;
  });
  if (!has_cell)
    return ctx.fail(choice.scene ? choice.element : "scene",
                    "has no cells: mark cell nodes with extras.lintel.cell (docs/scene-format.md), or convert a file "
                    "whose rooms are named '<name>-room' with 'lintel import rooms' (docs/rooms.md)");
  // Nothing reads the DOM from here on (choice.scene points into it): freed now, its memory is
  // reused by the World instead of the World taking fresh pages while the DOM waits to be freed.
  choice.scene = nullptr;
  doc = nlohmann::json();

  World world;
  AssemblyState state{ctx, model, nodes, graph, {}, {}, {}, base_dir};
  if (Status s = assemble_world(state, world); !s) return s;
  world.source = ctx.label();
  world.version = tag.version;
  world.timelines = std::move(tag.timelines);
  world.environment = tag.environment_given        ? tag.environment
                      : !world.has_light_sources() ? glm::vec3(kDefaultEnvironmentRadiance)
                                                   : glm::vec3(0.0f);
  if (Status s = finalize_world(world); !s) return ctx.fail("", s.message());
  for (Timeline& timeline : world.timelines)
    if (Status s = resolve_timeline_events(world, timeline); !s) return ctx.fail("", s.message());
  out = std::move(world);
  return {};
}

// The boundary: bad_alloc and anything nlohmann or tinygltf's types might still throw become a status.
Status guarded_load(const std::string& label, const uint8_t* bytes, size_t size, const std::string& base_dir,
                    const LoadOptions& options, World& out, std::vector<std::string>* warnings) {
  out = World{};
  std::vector<std::string> local_warnings;
  LoadContext ctx(label, &local_warnings);
  ctx.set_allow_outside_paths(options.allow_outside_paths);
  ctx.set_max_memory_bytes(options.max_memory_bytes);
  Status status;
  try {
    status = load_pipeline(ctx, bytes, size, base_dir, out);
  } catch (const std::bad_alloc&) {
    status = ctx.fail("", "out of memory while loading");
  } catch (const std::exception& e) {
    status = ctx.fail("", std::string("internal error while loading: ") + e.what());
  } catch (...) {
    status = ctx.fail("", "internal error while loading");
  }
  if (!status) {
    out = World{};
    return status;
  }
  if (warnings) warnings->insert(warnings->end(), local_warnings.begin(), local_warnings.end());
  return status;
}

}  // namespace
}  // namespace lintel::scene_read

namespace lintel {

Status load_world(const std::string& path, World& out, std::vector<std::string>* warnings) {
  return load_world(path, LoadOptions{}, out, warnings);
}

Status load_world(const std::string& path, const LoadOptions& options, World& out, std::vector<std::string>* warnings) {
  out = World{};
  std::vector<uint8_t> bytes;
  size_t file_size = 0;
  if (options.max_memory_bytes > 0 && scene_read::regular_file_size(path, file_size).empty() &&
      file_size > options.max_memory_bytes)
    return scene_read::LoadContext(path, nullptr)
        .fail("", "is " + std::to_string(file_size) + " bytes, over the memory budget of " +
                      std::to_string(options.max_memory_bytes) + " bytes (--max-memory)");
  try {
    if (std::string why = scene_read::read_file_bounded(path, kMaxSceneFileBytes, bytes); !why.empty())
      return scene_read::LoadContext(path, nullptr).fail("", why);
  } catch (const std::exception& e) {
    return scene_read::LoadContext(path, nullptr).fail("", std::string("cannot read: ") + e.what());
  }
  return scene_read::guarded_load(path, bytes.data(), bytes.size(), scene_read::directory_of(path), options, out,
                                  warnings);
}

Status load_world_from_memory(const uint8_t* bytes, size_t size, const std::string& label, const std::string& base_dir,
                              World& out, std::vector<std::string>* warnings) {
  if (!bytes && size > 0) return scene_read::LoadContext(label, nullptr).fail("", "no data (null pointer)");
  return scene_read::guarded_load(label, bytes, size, base_dir, LoadOptions{}, out, warnings);
}

}  // namespace lintel
