// read_gltf_model and its data half: buffers (their bytes), buffer views, accessors and meshes.
// Preflight already proved the buffers, views and accessors well-formed (types, ranges, sizes),
// so those are copied; meshes are checked here, field by field.
#include "read/gltf_model.h"

#include "read/file_read.h"
#include "read/json_fields.h"
#include "read/load_limits.h"

#include <tiny_gltf.h>

namespace lintel::scene_read {
namespace {

using nlohmann::json;

// An optional integer member: `out` keeps its default when absent.
std::string optional_int(const json& obj, const char* key, int& out) {
  const json* v = member(obj, key);
  if (!v) return {};
  if (std::string why = read_int(*v, out); !why.empty()) return std::string(key) + " " + why;
  return {};
}

// An optional glTF index member (>= 0); the range is checked by whoever follows it.
std::string optional_index(const json& obj, const char* key, int& out) {
  int v = out;
  if (std::string why = optional_int(obj, key, v); !why.empty()) return why;
  if (v < 0 && member(obj, key)) return std::string(key) + " " + std::to_string(v) + " is negative";
  out = v;
  return {};
}

// Preflight proved this member present and an integer that fits 32 bits (or absent: `fallback`).
int64_t checked_integer(const json& obj, const char* key, int64_t fallback) {
  const json* v = member(obj, key);
  int64_t out = fallback;
  if (v) read_integer(*v, out);
  return out;
}

Status read_buffers(const LoadContext& ctx, const json& doc, const GlbChunks* glb, const PreflightResult& preflight,
                    tinygltf::Model& model) {
  const json* buffers = member(doc, "buffers");
  if (!buffers) return {};
  model.buffers.resize(buffers->size());
  for (size_t i = 0; i < buffers->size(); ++i) {
    const json& b = (*buffers)[i];
    const std::string element = "buffer " + std::to_string(i);
    const auto length = static_cast<size_t>(checked_integer(b, "byteLength", 0));
    tinygltf::Buffer& out = model.buffers[i];
    if (const json* uri = member(b, "uri")) out.uri = uri->get_ref<const std::string&>();
    if (!preflight.buffer_files[i].empty()) {
      // Preflight compared the file's size with byteLength; the file may have changed since.
      if (std::string why = read_file_bounded(preflight.buffer_files[i], kMaxTotalBufferBytes, out.data); !why.empty())
        return ctx.fail(element, "cannot read '" + out.uri + "': " + why);
      if (out.data.size() != length)
        return ctx.fail(element, "'" + out.uri + "' has " + std::to_string(out.data.size()) +
                                     " bytes, byteLength says " + std::to_string(length));
    } else if (!out.uri.empty()) {
      std::string mime;  // preflight checked the MIME type, the base64 text and its decoded size
      if (!tinygltf::DecodeDataURI(&out.data, mime, out.uri, length, true))
        return ctx.fail(element, "data URI could not be decoded");
    } else {
      out.data.assign(glb->bin, glb->bin + length);  // preflight: within the BIN chunk
    }
  }
  return {};
}

void read_buffer_views(const json& doc, tinygltf::Model& model) {
  const json* views = member(doc, "bufferViews");
  if (!views) return;
  model.bufferViews.resize(views->size());
  for (size_t i = 0; i < views->size(); ++i) {
    const json& v = (*views)[i];
    tinygltf::BufferView& out = model.bufferViews[i];
    out.buffer = int(checked_integer(v, "buffer", -1));
    out.byteOffset = size_t(checked_integer(v, "byteOffset", 0));
    out.byteLength = size_t(checked_integer(v, "byteLength", 0));
    out.byteStride = size_t(checked_integer(v, "byteStride", 0));
  }
}

void read_accessors(const json& doc, tinygltf::Model& model) {
  const json* accessors = member(doc, "accessors");
  if (!accessors) return;
  model.accessors.resize(accessors->size());
  for (size_t i = 0; i < accessors->size(); ++i) {
    const json& a = (*accessors)[i];
    tinygltf::Accessor& out = model.accessors[i];
    out.bufferView = int(checked_integer(a, "bufferView", -1));
    out.byteOffset = size_t(checked_integer(a, "byteOffset", 0));
    out.componentType = int(checked_integer(a, "componentType", 0));
    out.count = size_t(checked_integer(a, "count", 0));
    out.type = gltf_accessor_type(member(a, "type")->get_ref<const std::string&>());  // preflight allowed no other
    if (const json* normalized = member(a, "normalized"); normalized && normalized->is_boolean())
      out.normalized = normalized->get<bool>();
    // Sparse substitutions (vertex attributes only: accessor_read.cpp checks what they hold). A
    // field that is missing or not an integer reads as -1, which the reader refuses.
    out.sparse.isSparse = false;
    out.sparse.count = 0;
    out.sparse.indices = {0, -1, -1};
    out.sparse.values = {-1, 0};
    if (const json* sparse = member(a, "sparse")) {
      out.sparse.isSparse = true;
      if (!sparse->is_object()) continue;
      out.sparse.count = int(checked_integer(*sparse, "count", -1));
      if (const json* indices = member(*sparse, "indices"); indices && indices->is_object()) {
        out.sparse.indices.bufferView = int(checked_integer(*indices, "bufferView", -1));
        out.sparse.indices.byteOffset = int(checked_integer(*indices, "byteOffset", 0));
        out.sparse.indices.componentType = int(checked_integer(*indices, "componentType", -1));
      }
      if (const json* values = member(*sparse, "values"); values && values->is_object()) {
        out.sparse.values.bufferView = int(checked_integer(*values, "bufferView", -1));
        out.sparse.values.byteOffset = int(checked_integer(*values, "byteOffset", 0));
      }
    }
  }
}

// As tinygltf did for every mesh, used or not: a primitive's index data must exist.
std::string indices_exist(const tinygltf::Primitive& p, const tinygltf::Model& model) {
  if (p.indices < 0) return {};
  if (size_t(p.indices) >= model.accessors.size())
    return "indices accessor " + std::to_string(p.indices) + " does not exist (" +
           std::to_string(model.accessors.size()) + " accessors)";
  if (model.accessors[size_t(p.indices)].bufferView < 0)
    return "indices accessor " + std::to_string(p.indices) + " has no bufferView";
  return {};
}

// The compact meshes (clean: gltf_compact.h), moved in, with read_meshes' remaining checks.
Status take_compact_meshes(const LoadContext& ctx, CompactSections& compact, tinygltf::Model& model) {
  if (compact.meshes.size() > kMaxMeshes)
    return ctx.fail(
        "meshes", std::to_string(compact.meshes.size()) + " elements, over the limit of " + std::to_string(kMaxMeshes));
  model.meshes = std::move(compact.meshes);
  for (size_t i = 0; i < model.meshes.size(); ++i)
    for (size_t p = 0; p < model.meshes[i].primitives.size(); ++p)
      if (std::string why = indices_exist(model.meshes[i].primitives[p], model); !why.empty())
        return ctx.fail(describe("mesh", i, model.meshes[i].name) + " primitive " + std::to_string(p), why);
  return {};
}

// The fault of one primitive in words, or empty; the caller names the element (only on failure:
// building "mesh 12 'name' primitive 0" for each of an imported level's 8,000 meshes costs more
// than reading them).
std::string read_primitive(const json& p, const tinygltf::Model& model, tinygltf::Primitive& out) {
  out.mode = TINYGLTF_MODE_TRIANGLES;  // glTF's default; tinygltf's Primitive() says -1
  if (!p.is_object()) return "must be an object, got " + json_kind(p);
  const json* attributes = member(p, "attributes");
  if (!attributes) return "'attributes' is missing";
  if (!attributes->is_object()) return "attributes must be an object, got " + json_kind(*attributes);
  for (const auto& [name, value] : attributes->get_ref<const json::object_t&>()) {
    int index = -1;
    if (std::string why = read_int(value, index); !why.empty()) return "attributes." + name + " " + why;
    out.attributes.emplace(name, index);
  }
  for (auto [key, field] : {std::pair{"indices", &out.indices}, std::pair{"material", &out.material}})
    if (std::string why = optional_index(p, key, *field); !why.empty()) return why;
  if (std::string why = optional_int(p, "mode", out.mode); !why.empty()) return why;
  return indices_exist(out, model);
}

Status read_meshes(const LoadContext& ctx, const json& doc, tinygltf::Model& model) {
  const json* meshes = nullptr;
  if (Status s = top_level_objects(ctx, doc, "meshes", kMaxMeshes, meshes); !s) return s;
  if (!meshes) return {};
  model.meshes.resize(meshes->size());
  for (size_t i = 0; i < meshes->size(); ++i) {
    const json& m = (*meshes)[i];
    tinygltf::Mesh& out = model.meshes[i];
    if (const json* name = member(m, "name"); name && name->is_string()) out.name = name->get<std::string>();
    const json* primitives = member(m, "primitives");
    if (!primitives) continue;
    if (!primitives->is_array())
      return ctx.fail(describe("mesh", i, out.name), "primitives must be an array, got " + json_kind(*primitives));
    out.primitives.resize(primitives->size());
    for (size_t p = 0; p < primitives->size(); ++p)
      if (std::string why = read_primitive((*primitives)[p], model, out.primitives[p]); !why.empty())
        return ctx.fail(describe("mesh", i, out.name) + " primitive " + std::to_string(p), why);
  }
  return {};
}

}  // namespace

Status read_gltf_data(const LoadContext& ctx, const json& doc, const GlbChunks* glb, const PreflightResult& preflight,
                      tinygltf::Model& model, CompactSections* compact) {
  if (Status s = read_buffers(ctx, doc, glb, preflight, model); !s) return s;
  read_buffer_views(doc, model);
  if (compact && compact->has_accessors)
    model.accessors = std::move(compact->accessors);
  else
    read_accessors(doc, model);
  if (compact && compact->has_meshes) return take_compact_meshes(ctx, *compact, model);
  return read_meshes(ctx, doc, model);
}

Status read_gltf_model(const LoadContext& ctx, const json& doc, const GlbChunks* glb, const PreflightResult& preflight,
                       tinygltf::Model& model, CompactSections* compact) {
  model = tinygltf::Model{};
  if (Status s = read_gltf_data(ctx, doc, glb, preflight, model, compact); !s) return s;
  return read_gltf_looks(ctx, doc, model);
}

}  // namespace lintel::scene_read
