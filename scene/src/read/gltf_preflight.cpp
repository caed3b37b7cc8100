// Pre-checks of the glTF JSON (see gltf_preflight.h for why each exists): the document's shape
// and the buffers, views and accessors every later read relies on; the rest is checked where it
// is read (gltf_model*.cpp, then the mesh, texture and light readers).
#include "read/gltf_preflight.h"

#include "read/file_read.h"
#include "read/json_fields.h"
#include "read/load_limits.h"
#include "read/uri_path.h"

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <string_view>

namespace lintel::scene_read {
namespace {

using nlohmann::json;

// The model holds glTF indices as int (tinygltf's types), so 4294967296 must not become 0.
// Integers inside extras and extensions are user data and stay unchecked.
bool skipped_key(std::string_view key) { return key == "extras" || key == "extensions"; }

// Whether every checked integer fits: check_integer_ranges' walk without building the element
// paths, which cost more than the walk itself (a JSON value each) and are needed only to report.
bool integers_fit(const json& value) {
  switch (value.type()) {
    case json::value_t::number_unsigned:
      return value.get<uint64_t>() <= uint64_t(INT32_MAX);
    case json::value_t::number_integer: {
      const int64_t v = value.get<int64_t>();
      return v >= INT32_MIN && v <= INT32_MAX;
    }
    case json::value_t::object:  // the containers themselves: nlohmann's iterators cost more
      for (const auto& [key, child] : value.get_ref<const json::object_t&>())
        if (!skipped_key(key) && !integers_fit(child)) return false;
      return true;
    case json::value_t::array:
      for (const json& element : value.get_ref<const json::array_t&>())
        if (!integers_fit(element)) return false;
      return true;
    default:
      return true;
  }
}

// The first integer out of range, named by its path (after integers_fit found one).
Status check_integer_ranges(const LoadContext& ctx, const json& value, std::string& path) {
  if (value.is_number_integer()) {
    int64_t v = 0;
    if (!read_integer(value, v).empty() || v < INT32_MIN || v > INT32_MAX)
      return ctx.fail(path, "integer " + value.dump() + " is out of the 32-bit range glTF readers support");
    return {};
  }
  const size_t length = path.size();
  if (value.is_object()) {
    for (const auto& [key, child] : value.items()) {
      if (skipped_key(key)) continue;
      if (!path.empty()) path += '.';
      path += key;
      Status s = check_integer_ranges(ctx, child, path);
      path.resize(length);
      if (!s) return s;
    }
  } else if (value.is_array()) {
    for (size_t i = 0; i < value.size(); ++i) {
      // Appended piecewise: GCC 12's -Wrestrict misfires on `"[" + std::to_string(i)` at -O3.
      path += '[';
      path += std::to_string(i);
      path += ']';
      Status s = check_integer_ranges(ctx, value[i], path);
      path.resize(length);
      if (!s) return s;
    }
  }
  return {};
}

Status check_asset(const LoadContext& ctx, const json& doc) {
  const json* asset = member(doc, "asset");
  if (!asset) return ctx.fail("", "no 'asset' object: not a glTF 2.0 file");
  std::string version;
  const json* v = member(*asset, "version");
  if (!v) return ctx.fail("asset", "'version' is missing: not a glTF 2.0 file");
  if (std::string why = read_string(*v, version); !why.empty()) return ctx.fail("asset.version", why);
  if (version.rfind("2.", 0) != 0) return ctx.fail("asset.version", "glTF version '" + version + "' is not 2.x");
  return {};
}

// glTF 2.0: a loader that does not implement an extension the file lists in extensionsRequired must
// refuse it. Lintel reads these four (KHR_texture_transform on the base colour and emissive
// textures, which must then agree: mesh_read.cpp); any
// other required one (mesh compression, Basis textures, ...) would load wrong or fail later with a
// message about its symptom.
Status check_required_extensions(const LoadContext& ctx, const json& doc) {
  const json* required = member(doc, "extensionsRequired");
  if (!required) return {};
  if (!required->is_array()) return ctx.fail("extensionsRequired", "must be an array of names");
  static constexpr const char* kRead[] = {"KHR_lights_punctual", "KHR_materials_emissive_strength",
                                          "KHR_mesh_quantization", "KHR_texture_transform"};
  for (size_t i = 0; i < required->size(); ++i) {
    const json& name = (*required)[i];
    if (!name.is_string()) return ctx.fail("extensionsRequired[" + std::to_string(i) + "]", "is not a string");
    const std::string& text = name.get_ref<const std::string&>();
    if (std::none_of(std::begin(kRead), std::end(kRead), [&](const char* known) { return text == known; }))
      return ctx.fail("extensionsRequired[" + std::to_string(i) + "]",
                      "extension '" + one_line(text, 64) +
                          "' is required by the file and not read by Lintel (it reads KHR_lights_punctual, "
                          "KHR_materials_emissive_strength, KHR_mesh_quantization and KHR_texture_transform)");
  }
  return {};
}

// Decoded size of a base64 payload, or an error. Checked here so that a wrong byteLength is
// reported as such (a decoder would just give fewer bytes).
std::string base64_size(const std::string& uri, uint64_t& size) {
  const size_t comma = uri.find(',');
  const size_t n = uri.size() - comma - 1;
  if (n % 4 != 0) return "data URI is not valid base64 (length " + std::to_string(n) + " is not a multiple of 4)";
  size_t padding = 0;
  for (size_t i = comma + 1; i < uri.size(); ++i) {
    const char c = uri[i];
    const bool digit =
        (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '+' || c == '/';
    if (c == '=' && i + 2 >= uri.size()) {
      ++padding;
    } else if (!digit || padding > 0) {
      return "data URI is not valid base64 (bad character at offset " + std::to_string(i - comma - 1) + ")";
    }
  }
  size = n / 4 * 3 - padding;
  return {};
}

bool is_supported_data_uri(const std::string& uri) {
  // The two MIME types glTF 2.0 allows for buffers; any other "data:" URI would be taken for
  // a file name.
  return uri.rfind("data:application/octet-stream;base64,", 0) == 0 ||
         uri.rfind("data:application/gltf-buffer;base64,", 0) == 0;
}

Status check_buffers(const LoadContext& ctx, const json& doc, const GlbChunks* glb, const std::string& base_dir,
                     std::vector<uint64_t>& byte_lengths, PreflightResult& out) {
  const json* buffers = nullptr;
  if (Status s = top_level_objects(ctx, doc, "buffers", kMaxBuffers, buffers); !s) return s;
  if (!buffers) return {};
  uint64_t total = 0;
  for (size_t i = 0; i < buffers->size(); ++i) {
    const json& b = (*buffers)[i];
    const std::string element = "buffer " + std::to_string(i);
    const json* length_json = member(b, "byteLength");
    if (!length_json) return ctx.fail(element, "'byteLength' is missing");
    int64_t length = 0;
    if (std::string why = read_integer(*length_json, length); !why.empty())
      return ctx.fail(element, "byteLength " + why);
    if (length < 1) return ctx.fail(element, "byteLength " + std::to_string(length) + " is not positive");
    total += uint64_t(length);
    if (total > kMaxTotalBufferBytes)
      return ctx.fail(element, "buffers add up to more than " + std::to_string(kMaxTotalBufferBytes) + " bytes");
    // The buffers are read whole: refuse before reading what the caller's budget cannot hold.
    if (ctx.max_memory_bytes() > 0 && total > ctx.max_memory_bytes())
      return ctx.fail(element, "buffers add up to " + std::to_string(total) + " bytes, over the memory budget of " +
                                   std::to_string(ctx.max_memory_bytes()) + " bytes (--max-memory)");
    byte_lengths.push_back(uint64_t(length));

    const json* uri_json = member(b, "uri");
    if (!uri_json) {
      if (!glb) return ctx.fail(element, "has no 'uri' (only the first buffer of a .glb may omit it)");
      if (i != 0) return ctx.fail(element, "has no 'uri'; only buffer 0 can be the GLB's BIN chunk");
      if (!glb->bin) return ctx.fail(element, "refers to the GLB's BIN chunk, but the file has none");
      if (uint64_t(length) > glb->bin_size)
        return ctx.fail(element, "byteLength " + std::to_string(length) + " exceeds the GLB BIN chunk (" +
                                     std::to_string(glb->bin_size) + " bytes)");
      out.buffer_files.emplace_back();
      continue;
    }
    std::string uri;
    if (std::string why = read_string(*uri_json, uri); !why.empty()) return ctx.fail(element, "uri " + why);
    if (uri.rfind("data:", 0) == 0) {
      if (!is_supported_data_uri(uri))
        return ctx.fail(element, "data URI is not base64 application/octet-stream or application/gltf-buffer");
      uint64_t decoded = 0;
      if (std::string why = base64_size(uri, decoded); !why.empty()) return ctx.fail(element, why);
      if (decoded != uint64_t(length))
        return ctx.fail(
            element, "data URI holds " + std::to_string(decoded) + " bytes, byteLength says " + std::to_string(length));
      out.buffer_files.emplace_back();
      continue;
    }
    std::string path;
    if (std::string why = resolve_relative_uri("buffer", base_dir, uri, ctx.allow_outside_paths(), path); !why.empty())
      return ctx.fail(element, why);
    size_t file_size = 0;
    if (std::string why = regular_file_size(path, file_size); !why.empty())
      return ctx.fail(element, "cannot read '" + uri + "': " + why);
    if (file_size != uint64_t(length))
      return ctx.fail(element, "'" + uri + "' has " + std::to_string(file_size) + " bytes, byteLength says " +
                                   std::to_string(length));
    out.buffer_files.push_back(path);
  }
  return {};
}

Status check_buffer_views(const LoadContext& ctx, const json& doc, const std::vector<uint64_t>& buffer_lengths) {
  const json* views = nullptr;
  if (Status s = top_level_objects(ctx, doc, "bufferViews", kMaxBufferViews, views); !s) return s;
  if (!views) return {};
  for (size_t i = 0; i < views->size(); ++i) {
    const json& v = (*views)[i];
    const std::string element = "bufferView " + std::to_string(i);
    size_t buffer = 0;
    const json* buffer_json = member(v, "buffer");
    if (!buffer_json) return ctx.fail(element, "'buffer' is missing");
    if (std::string why = read_index(*buffer_json, buffer_lengths.size(), buffer); !why.empty())
      return ctx.fail(element, "buffer " + why);
    int64_t offset = 0, length = 0, stride = 0;
    if (const json* o = member(v, "byteOffset"))
      if (std::string why = read_integer(*o, offset); !why.empty()) return ctx.fail(element, "byteOffset " + why);
    const json* length_json = member(v, "byteLength");
    if (!length_json) return ctx.fail(element, "'byteLength' is missing");
    if (std::string why = read_integer(*length_json, length); !why.empty())
      return ctx.fail(element, "byteLength " + why);
    if (offset < 0 || length < 1) return ctx.fail(element, "byteOffset must be >= 0 and byteLength >= 1");
    if (uint64_t(offset) + uint64_t(length) > buffer_lengths[buffer])
      return ctx.fail(element, "bytes " + std::to_string(offset) + ".." + std::to_string(offset + length) +
                                   " exceed buffer " + std::to_string(buffer) + " (" +
                                   std::to_string(buffer_lengths[buffer]) + " bytes)");
    if (const json* s = member(v, "byteStride")) {
      if (std::string why = read_integer(*s, stride); !why.empty()) return ctx.fail(element, "byteStride " + why);
      if (stride < 4 || stride > 252 || stride % 4 != 0)
        return ctx.fail(element, "byteStride " + std::to_string(stride) + " is not a multiple of 4 in 4..252");
    }
  }
  return {};
}

// The compact accessors: clean (gltf_compact.h), so what is left is their number and whether
// their buffer views exist -- with check_accessors' messages.
Status check_compact_accessors(const LoadContext& ctx, const json& doc, const CompactSections& compact) {
  if (compact.accessors.size() > kMaxAccessors)
    return ctx.fail("accessors", std::to_string(compact.accessors.size()) + " elements, over the limit of " +
                                     std::to_string(kMaxAccessors));
  const json* views = member(doc, "bufferViews");
  const size_t view_count = views ? views->size() : 0;
  for (size_t i = 0; i < compact.accessors.size(); ++i) {
    const int view = compact.accessors[i].bufferView;  // -1: absent
    if (view >= 0 && size_t(view) >= view_count)
      return ctx.fail("accessor " + std::to_string(i), "bufferView index " + std::to_string(view) +
                                                           " is out of range (" + std::to_string(view_count) +
                                                           " elements)");
  }
  return {};
}

Status check_accessors(const LoadContext& ctx, const json& doc) {
  const json* accessors = nullptr;
  if (Status s = top_level_objects(ctx, doc, "accessors", kMaxAccessors, accessors); !s) return s;
  if (!accessors) return {};
  const json* views = member(doc, "bufferViews");
  const size_t view_count = views ? views->size() : 0;
  for (size_t i = 0; i < accessors->size(); ++i) {
    const json& a = (*accessors)[i];
    const std::string element = "accessor " + std::to_string(i);
    const json* component_json = member(a, "componentType");
    if (!component_json) return ctx.fail(element, "'componentType' is missing");
    int64_t component = 0;
    if (std::string why = read_integer(*component_json, component); !why.empty())
      return ctx.fail(element, "componentType " + why);
    if (component != 5120 && component != 5121 && component != 5122 && component != 5123 && component != 5125 &&
        component != 5126)
      return ctx.fail(element, "componentType " + std::to_string(component) + " is not a glTF component type");
    const json* count_json = member(a, "count");
    if (!count_json) return ctx.fail(element, "'count' is missing");
    int64_t count = 0;
    if (std::string why = read_integer(*count_json, count); !why.empty()) return ctx.fail(element, "count " + why);
    if (count < 1) return ctx.fail(element, "count " + std::to_string(count) + " is not positive");
    const json* type_json = member(a, "type");
    std::string type;
    if (!type_json) return ctx.fail(element, "'type' is missing");
    if (std::string why = read_string(*type_json, type); !why.empty()) return ctx.fail(element, "type " + why);
    if (type != "SCALAR" && type != "VEC2" && type != "VEC3" && type != "VEC4" && type != "MAT2" && type != "MAT3" &&
        type != "MAT4")
      return ctx.fail(element, "type '" + type + "' is not a glTF accessor type");
    if (const json* v = member(a, "bufferView")) {
      size_t view = 0;
      if (std::string why = read_index(*v, view_count, view); !why.empty())
        return ctx.fail(element, "bufferView " + why);
    }
    if (const json* o = member(a, "byteOffset")) {
      int64_t offset = 0;
      if (std::string why = read_integer(*o, offset); !why.empty() || offset < 0)
        return ctx.fail(element, "byteOffset must be a non-negative integer");
    }
  }
  return {};
}

}  // namespace

Status top_level_objects(const LoadContext& ctx, const json& doc, const char* key, size_t max_count, const json*& out) {
  out = member(doc, key);
  if (!out) return {};
  if (!out->is_array()) return ctx.fail(key, "must be an array, got " + json_kind(*out));
  if (out->size() > max_count)
    return ctx.fail(key, std::to_string(out->size()) + " elements, over the limit of " + std::to_string(max_count));
  for (size_t i = 0; i < out->size(); ++i)
    if (!(*out)[i].is_object())
      return ctx.fail(std::string(key) + "[" + std::to_string(i) + "]",
                      "must be an object, got " + json_kind((*out)[i]));
  return {};
}

std::string decode_uri_like_tinygltf(const std::string& uri) {
  auto from_hex = [](unsigned char c) -> unsigned char {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return 0;
  };
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      out += ' ';
    } else if (uri[i] == '%' && uri.size() > i + 2) {
      out += static_cast<char>(from_hex(static_cast<unsigned char>(uri[i + 1])) << 4 |
                               from_hex(static_cast<unsigned char>(uri[i + 2])));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

Status preflight_gltf(const LoadContext& ctx, const json& doc, const GlbChunks* glb, const std::string& base_dir,
                      PreflightResult& out, bool known_to_fit, const CompactSections* compact) {
  out = {};
  if (!doc.is_object()) return ctx.fail("", "the glTF JSON root must be an object, got " + json_kind(doc));
  if (Status s = check_asset(ctx, doc); !s) return s;
  if (Status s = check_required_extensions(ctx, doc); !s) return s;
  if (std::string path; !known_to_fit && !integers_fit(doc))
    if (Status s = check_integer_ranges(ctx, doc, path); !s) return s;
  std::vector<uint64_t> buffer_lengths;
  if (Status s = check_buffers(ctx, doc, glb, base_dir, buffer_lengths, out); !s) return s;
  if (Status s = check_buffer_views(ctx, doc, buffer_lengths); !s) return s;
  if (compact && compact->has_accessors) return check_compact_accessors(ctx, doc, *compact);
  return check_accessors(ctx, doc);
}

}  // namespace lintel::scene_read
