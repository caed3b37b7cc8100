// The glTF JSON is built with nlohmann::ordered_json (insertion order = output order) and
// printed by hand at the top level, so that a .gltf diff in git shows which node or mesh changed.
#include "write/gltf_serialize.h"

#include "write/scene_desc_check.h"

#include <nlohmann/json.hpp>

#include <stb/stb_image_write.h>

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cstring>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

namespace lintel::scene_write {
namespace {

static_assert(std::endian::native == std::endian::little, "glTF buffers are little-endian; add byte swapping");

using Json = nlohmann::ordered_json;

constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr int kFloat = 5126;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;

// The double whose shortest decimal form is the float's shortest decimal form: "0.3", not
// "0.30000001192092896", and it reads back as exactly the same float.
double json_float(float f) {
  if (f == 0.0f) return 0.0;  // no "-0.0"
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, f).ptr;
  double d = 0.0;
  std::from_chars(text, end, d);
  return d;
}

Json vec(const glm::vec3& v) { return Json::array({json_float(v.x), json_float(v.y), json_float(v.z)}); }

class BinWriter {
 public:
  size_t append(const void* data, size_t bytes) {
    const size_t at = bytes_.size();
    bytes_.resize(at + bytes);
    std::memcpy(bytes_.data() + at, data, bytes);
    return at;
  }
  void align4() { bytes_.resize((bytes_.size() + 3) & ~size_t(3), 0); }
  size_t size() const { return bytes_.size(); }
  std::vector<uint8_t> take() { return std::move(bytes_); }

 private:
  std::vector<uint8_t> bytes_;
};

Json vec3_accessor(size_t offset, const std::vector<glm::vec3>& values) {
  glm::vec3 lo = values[0], hi = values[0];
  for (const glm::vec3& v : values) {
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  return Json{{"bufferView", 0}, {"byteOffset", offset}, {"componentType", kFloat}, {"count", values.size()},
              {"type", "VEC3"},  {"min", vec(lo)},       {"max", vec(hi)}};
}

struct Buffers {
  Json accessors = Json::array();
  // position, normal (-1: none), indices, uv (-1: none), colour (-1: none)
  std::vector<std::array<int, 5>> mesh_accessors;
  Json views = Json::array();
  std::vector<int> image_views;  // per SceneDesc::textures
  std::vector<uint8_t> bin;
};

void append_png(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<uint8_t>*>(context);
  const auto* bytes = static_cast<const uint8_t*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

// stb_image_write's PNG encoder is deterministic (fixed compression level and filter choice), so
// the file stays byte for byte the same for the same pixels.
Status encode_png(const TextureDesc& t, size_t index, std::vector<uint8_t>& out) {
  out.clear();
  if (!stbi_write_png_to_func(&append_png, &out, int(t.width), int(t.height), 4, t.rgba8.data(), int(t.width * 4)))
    return Status::error("scene: texture " + std::to_string(index) + ": PNG encoding failed");
  return {};
}

// Vertex data first (one stride-12 view), then indices (one view), then, only when used, uvs (one
// stride-8 view), colours (one stride-16 view) and one view per texture's PNG; accessors point
// into them. A scene without uvs, colours and textures is written exactly as before they existed
// (the committed scenes must not change).
Status write_buffers(const SceneDesc& scene, Buffers& out) {
  BinWriter bin;
  for (const MeshDesc& m : scene.meshes) {
    std::array<int, 5> ids{-1, -1, -1, -1, -1};
    ids[0] = int(out.accessors.size());
    out.accessors.push_back(vec3_accessor(bin.append(m.positions.data(), m.positions.size() * 12), m.positions));
    if (!m.normals.empty()) {
      ids[1] = int(out.accessors.size());
      out.accessors.push_back(vec3_accessor(bin.append(m.normals.data(), m.normals.size() * 12), m.normals));
    }
    out.mesh_accessors.push_back(ids);
  }
  const size_t vertex_bytes = bin.size();
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    const MeshDesc& m = scene.meshes[i];
    uint32_t lo = UINT32_MAX, hi = 0;
    for (uint32_t v : m.indices) lo = std::min(lo, v), hi = std::max(hi, v);
    // glTF forbids the type's maximum value as an index (primitive restart), hence < 65535.
    const bool narrow = m.positions.size() < 65535;
    size_t offset = 0;
    if (narrow) {
      std::vector<uint16_t> narrowed(m.indices.begin(), m.indices.end());
      offset = bin.append(narrowed.data(), narrowed.size() * 2);
    } else {
      offset = bin.append(m.indices.data(), m.indices.size() * 4);
    }
    bin.align4();
    out.mesh_accessors[i][2] = int(out.accessors.size());
    out.accessors.push_back(Json{{"bufferView", 1},
                                 {"byteOffset", offset - vertex_bytes},
                                 {"componentType", narrow ? kUnsignedShort : kUnsignedInt},
                                 {"count", m.indices.size()},
                                 {"type", "SCALAR"},
                                 {"min", Json::array({lo})},
                                 {"max", Json::array({hi})}});
  }
  const size_t index_bytes = bin.size();
  out.views.push_back(Json{
      {"buffer", 0}, {"byteOffset", 0}, {"byteLength", vertex_bytes}, {"byteStride", 12}, {"target", kArrayBuffer}});
  out.views.push_back(Json{{"buffer", 0},
                           {"byteOffset", vertex_bytes},
                           {"byteLength", index_bytes - vertex_bytes},
                           {"target", kElementArrayBuffer}});
  if (scene.meshes.empty()) {  // no buffer is written at all (build_document)
    out.bin = bin.take();
    return {};
  }

  // An optional float attribute (uvs, colours) of every mesh that has it, in one view of its own
  // (written only when some mesh has it); `slot` is its place in mesh_accessors.
  auto attribute_view = [&](auto member, size_t slot, const char* type) {
    const size_t first_byte = bin.size();
    const int view = int(out.views.size());
    size_t stride = 0;
    for (size_t i = 0; i < scene.meshes.size(); ++i) {
      const auto& values = scene.meshes[i].*member;
      if (values.empty()) continue;
      stride = sizeof(values[0]);
      const size_t offset = bin.append(values.data(), values.size() * stride);
      out.mesh_accessors[i][slot] = int(out.accessors.size());
      out.accessors.push_back(Json{{"bufferView", view},
                                   {"byteOffset", offset - first_byte},
                                   {"componentType", kFloat},
                                   {"count", values.size()},
                                   {"type", type}});
    }
    if (bin.size() > first_byte)
      out.views.push_back(Json{{"buffer", 0},
                               {"byteOffset", first_byte},
                               {"byteLength", bin.size() - first_byte},
                               {"byteStride", stride},
                               {"target", kArrayBuffer}});
  };
  attribute_view(&MeshDesc::uvs, 3, "VEC2");
  attribute_view(&MeshDesc::colors, 4, "VEC4");

  std::vector<uint8_t> png;
  for (size_t t = 0; t < scene.textures.size(); ++t) {
    if (Status s = encode_png(scene.textures[t], t, png); !s) return s;
    bin.align4();
    const size_t offset = bin.append(png.data(), png.size());
    out.image_views.push_back(int(out.views.size()));
    out.views.push_back(Json{{"buffer", 0}, {"byteOffset", offset}, {"byteLength", png.size()}});
  }
  bin.align4();
  out.bin = bin.take();
  return {};
}

// The material of `m` (its textures as glTF texture indices, or -1).
Json material_json(const MeshDesc& m, int texture, int emissive_texture, size_t index) {
  const glm::vec4& c = m.base_color;
  Json pbr{{"baseColorFactor", Json::array({json_float(c.r), json_float(c.g), json_float(c.b), json_float(c.a)})}};
  if (texture >= 0) pbr["baseColorTexture"] = Json{{"index", texture}};
  pbr["metallicFactor"] = 0.0;
  pbr["roughnessFactor"] = 0.8;
  Json mat{{"name", "material_" + std::to_string(index)}, {"pbrMetallicRoughness", pbr}};
  if (m.double_sided) mat["doubleSided"] = true;  // glTF's default is false: written only when set
  if (m.alpha_mode == Mesh::AlphaMode::Mask) {
    mat["alphaMode"] = "MASK";
    if (m.alpha_cutoff != 0.5f) mat["alphaCutoff"] = json_float(m.alpha_cutoff);  // 0.5: glTF's default
  } else if (m.alpha_mode == Mesh::AlphaMode::Blend || c.a < 1.0f) {
    mat["alphaMode"] = "BLEND";  // volumes and portals (alpha < 1): invisible in a plain viewer
  }
  if (m.emissive != glm::vec3(0.0f) || emissive_texture >= 0) {
    // glTF's emissiveFactor is at most 1 per component: a brighter one is written as the factor
    // over its largest component times KHR_materials_emissive_strength.
    const float strength = std::max({m.emissive.r, m.emissive.g, m.emissive.b});
    const glm::vec3 factor = strength > 1.0f ? m.emissive / strength : m.emissive;
    mat["emissiveFactor"] = Json::array({json_float(factor.r), json_float(factor.g), json_float(factor.b)});
    if (strength > 1.0f)
      mat["extensions"] = Json{{"KHR_materials_emissive_strength", Json{{"emissiveStrength", json_float(strength)}}}};
    if (emissive_texture >= 0) mat["emissiveTexture"] = Json{{"index", emissive_texture}};
  }
  return mat;
}

// glTF's sampler codes, as the loader reads them (read/texture_read.cpp).
using SamplerKey = std::array<uint8_t, 5>;
SamplerKey sampler_key(const TextureSampler& s) {
  return {uint8_t(s.wrap_s), uint8_t(s.wrap_t), uint8_t(s.mag), uint8_t(s.min), uint8_t(s.mip)};
}

// Only what differs from the default: an undefined filter is what the loader reads as linear
// (with linear mipmapping for minFilter), and an undefined wrap mode is REPEAT.
Json sampler_json(const TextureSampler& s) {
  using Filter = TextureSampler::Filter;
  using MipMode = TextureSampler::MipMode;
  constexpr int kWrapCodes[] = {10497, 33071, 33648};  // TextureSampler::Wrap order
  Json j = Json::object();
  if (s.mag != Filter::Linear) j["magFilter"] = 9728;
  if (s.min != Filter::Linear || s.mip != MipMode::Linear) {
    const int linear = s.min == Filter::Linear ? 1 : 0;
    // 9728/9729: NEAREST/LINEAR; 9984 + linear + 2 * (mip linear): the *_MIPMAP_* modes.
    j["minFilter"] = s.mip == MipMode::None ? 9728 + linear : 9984 + linear + (s.mip == MipMode::Linear ? 2 : 0);
  }
  if (s.wrap_s != TextureSampler::Wrap::Repeat) j["wrapS"] = kWrapCodes[int(s.wrap_s)];
  if (s.wrap_t != TextureSampler::Wrap::Repeat) j["wrapT"] = kWrapCodes[int(s.wrap_t)];
  return j;
}

// glTF textures and samplers: texture t is image t (SceneDesc::textures[t]) with the sampler of the
// first mesh that uses it; a mesh that samples image t otherwise gets one more texture (image t,
// its sampler), shared by every mesh with the same pair. Default samplers are not written and
// equal samplers are written once, so a scene whose textures all sample with the default is
// written as before samplers existed.
struct TextureTable {
  std::vector<std::pair<int, int>> textures;  // (image, sampler index or -1)
  std::vector<TextureSampler> samplers;
  std::vector<int> mesh_texture;           // per mesh: its base colour's glTF texture, or -1
  std::vector<int> mesh_emissive_texture;  // per mesh: its emissive glTF texture, or -1
};

TextureTable texture_table(const SceneDesc& scene) {
  TextureTable out;
  std::map<SamplerKey, int> sampler_of;
  const SamplerKey default_key = sampler_key(TextureSampler{});
  auto sampler_index = [&](const TextureSampler& s) {
    const SamplerKey key = sampler_key(s);
    if (key == default_key) return -1;
    const auto [it, added] = sampler_of.emplace(key, int(out.samplers.size()));
    if (added) out.samplers.push_back(s);
    return it->second;
  };
  // Every (image, sampler) a mesh uses, base colour before emissive: glTF texture t is image t
  // with the first sampler it is used with; other pairs come after.
  struct Use {
    size_t mesh;
    bool emissive;
    int image, sampler;
  };
  std::vector<Use> uses;
  std::vector<int> first_sampler(scene.textures.size(), -1);
  std::vector<bool> used(scene.textures.size(), false);
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    const MeshDesc& m = scene.meshes[i];
    for (const auto& [emissive, image, sampler] :
         {std::tuple{false, m.texture, &m.sampler}, std::tuple{true, m.emissive_texture, &m.emissive_sampler}}) {
      if (image < 0) continue;
      uses.push_back({i, emissive, image, sampler_index(*sampler)});
      if (!used[size_t(image)]) first_sampler[size_t(image)] = uses.back().sampler;
      used[size_t(image)] = true;
    }
  }
  std::map<std::pair<int, int>, int> texture_of;
  for (size_t t = 0; t < scene.textures.size(); ++t) {
    out.textures.emplace_back(int(t), first_sampler[t]);
    texture_of.emplace(out.textures.back(), int(t));
  }
  out.mesh_texture.assign(scene.meshes.size(), -1);
  out.mesh_emissive_texture.assign(scene.meshes.size(), -1);
  for (const Use& u : uses) {
    const std::pair<int, int> pair{u.image, u.sampler};
    const auto [it, added] = texture_of.emplace(pair, int(out.textures.size()));
    if (added) out.textures.push_back(pair);
    (u.emissive ? out.mesh_emissive_texture : out.mesh_texture)[u.mesh] = it->second;
  }
  return out;
}

Json node_json(const NodeDesc& n, const std::vector<int>& children) {
  Json j = Json::object();
  if (!n.name.empty()) j["name"] = n.name;
  if (!children.empty()) j["children"] = children;
  if (n.mesh >= 0) j["mesh"] = n.mesh;
  if (n.translation != glm::vec3(0.0f)) j["translation"] = vec(n.translation);
  if (n.rotation != glm::quat(1.0f, 0.0f, 0.0f, 0.0f))
    j["rotation"] = Json::array(
        {json_float(n.rotation.x), json_float(n.rotation.y), json_float(n.rotation.z), json_float(n.rotation.w)});
  if (n.scale != glm::vec3(1.0f)) j["scale"] = vec(n.scale);
  if (n.light >= 0) j["extensions"] = Json{{"KHR_lights_punctual", Json{{"light", n.light}}}};
  switch (n.kind) {
    case NodeDesc::Kind::Cell:
      j["extras"] = Json{{"lintel", Json{{"cell", n.cell_name}}}};
      break;
    case NodeDesc::Kind::Portal: {
      Json portal{{"from", n.portal_from}, {"to", n.portal_to}, {"two_way", n.two_way}};
      if (!n.portal_open) portal["open"] = false;  // the default stays implicit: files without doors are unchanged
      if (n.portal_mirror) {                       // a mirror leads back into `from`
        portal.erase("to");
        portal["mirror"] = true;
      }
      if (!n.portal_link.empty()) portal["link"] = n.portal_link;
      if (n.portal_link_matrix) {  // 16 numbers, column-major, as the loader reads them
        Json m = Json::array();
        for (int c = 0; c < 4; ++c)
          for (int r = 0; r < 4; ++r) m.push_back((*n.portal_link_matrix)[c][r]);
        portal["link"] = m;
      }
      j["extras"] = Json{{"lintel", Json{{"portal", portal}}}};
      break;
    }
    case NodeDesc::Kind::Volume:
      j["extras"] = Json{{"lintel", Json{{"volume", true}}}};
      break;
    case NodeDesc::Kind::Plain:
      break;
  }
  return j;
}

Json light_json(const LightDesc& l) {
  static const char* const kTypes[] = {"point", "spot", "directional"};
  Json j{
      {"name", l.name}, {"type", kTypes[int(l.type)]}, {"color", vec(l.color)}, {"intensity", json_float(l.intensity)}};
  if (l.range > 0.0f && l.type != Light::Type::Directional) j["range"] = json_float(l.range);
  if (l.type == Light::Type::Spot)
    j["spot"] =
        Json{{"innerConeAngle", json_float(l.inner_cone_rad)}, {"outerConeAngle", json_float(l.outer_cone_rad)}};
  return j;
}

Json timeline_json(const Timeline& t) {
  Json keys = Json::array();
  for (const TimelineKey& k : t.keys)
    keys.push_back(Json{{"t", k.t}, {"eye", vec(k.eye_world)}, {"target", vec(k.target_world)}});
  Json out{{"name", t.name}, {"fps", t.fps}, {"fov_y_deg", t.fov_y_deg}, {"aspect", t.aspect}, {"keys", keys}};
  if (!t.events.empty()) {
    Json events = Json::array();
    for (const TimelineEvent& e : t.events) events.push_back(Json{{"t", e.t}, {"portal", e.portal}, {"open", e.open}});
    out["events"] = events;
  }
  if (!t.instance_keys.empty()) {
    Json keys_of_instances = Json::array();
    for (const TimelineInstanceKey& k : t.instance_keys) {
      Json j{{"t", k.t}, {"instance", k.instance}};
      if (k.has_translation) j["translation"] = vec(k.translation_world);
      const glm::vec4& q = k.rotation_xyzw;
      if (k.has_rotation)
        j["rotation"] = Json::array({json_float(q.x), json_float(q.y), json_float(q.z), json_float(q.w)});
      keys_of_instances.push_back(j);
    }
    out["instance_keys"] = keys_of_instances;
  }
  return out;
}

Json build_document(const SceneDesc& scene, const std::string& bin_uri, Buffers& buffers) {
  std::vector<std::vector<int>> children(scene.nodes.size());
  std::vector<int> roots;
  for (size_t i = 0; i < scene.nodes.size(); ++i)
    (scene.nodes[i].parent < 0 ? roots : children[size_t(scene.nodes[i].parent)]).push_back(int(i));

  Json doc = Json::object();
  doc["asset"] = Json{{"version", "2.0"}, {"generator", "Lintel scene writer"}};
  if (!scene.lights.empty()) {
    doc["extensionsUsed"] = Json::array({"KHR_lights_punctual"});
    Json lights = Json::array();
    for (const LightDesc& l : scene.lights) lights.push_back(light_json(l));
    doc["extensions"] = Json{{"KHR_lights_punctual", Json{{"lights", lights}}}};
  }
  Json timelines = Json::array();
  for (const Timeline& t : scene.timelines) timelines.push_back(timeline_json(t));
  doc["scene"] = 0;
  Json lintel{{"version", 1}, {"timelines", timelines}};
  if (scene.environment) lintel["environment"] = Json{{"color", vec(*scene.environment)}};  // intensity 1
  doc["scenes"] =
      Json::array({Json{{"name", "Lintel scene"}, {"nodes", roots}, {"extras", Json{{"lintel", std::move(lintel)}}}}});
  Json nodes = Json::array();
  for (size_t i = 0; i < scene.nodes.size(); ++i) nodes.push_back(node_json(scene.nodes[i], children[i]));
  doc["nodes"] = std::move(nodes);

  if (scene.meshes.empty()) return doc;
  // Identical colours (and textures, sidedness, alpha modes and emission) share one material. The texture is -1 or a glTF
  // texture index (an image with a sampler, texture_table).
  const TextureTable table = texture_table(scene);
  std::map<std::tuple<std::array<float, 4>, int, bool, Mesh::AlphaMode, float, std::array<float, 3>, int>, int>
      material_of;
  bool emissive_strength = false;
  Json materials = Json::array();
  Json meshes = Json::array();
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    const MeshDesc& m = scene.meshes[i];
    const int texture = table.mesh_texture[i];
    const std::array<float, 4> color{m.base_color.r, m.base_color.g, m.base_color.b, m.base_color.a};
    const float cutoff = m.alpha_mode == Mesh::AlphaMode::Mask ? m.alpha_cutoff : 0.5f;
    const int emissive_texture = table.mesh_emissive_texture[i];
    const std::array<float, 3> emissive{m.emissive.r, m.emissive.g, m.emissive.b};
    const auto [it, inserted] = material_of.emplace(
        std::make_tuple(color, texture, m.double_sided, m.alpha_mode, cutoff, emissive, emissive_texture),
        int(materials.size()));
    if (inserted) {
      materials.push_back(material_json(m, texture, emissive_texture, materials.size()));
      emissive_strength = emissive_strength || materials.back().contains("extensions");
    }
    const auto& ids = buffers.mesh_accessors[i];
    Json attributes{{"POSITION", ids[0]}};
    if (ids[1] >= 0) attributes["NORMAL"] = ids[1];
    if (ids[3] >= 0) attributes["TEXCOORD_0"] = ids[3];
    if (ids[4] >= 0) attributes["COLOR_0"] = ids[4];
    Json primitive{{"attributes", attributes}, {"indices", ids[2]}, {"material", it->second}, {"mode", 4}};
    Json mesh = Json::object();
    if (!m.name.empty()) mesh["name"] = m.name;
    mesh["primitives"] = Json::array({primitive});
    meshes.push_back(std::move(mesh));
  }
  doc["meshes"] = std::move(meshes);
  doc["materials"] = std::move(materials);
  if (emissive_strength) {
    if (!doc.contains("extensionsUsed")) doc["extensionsUsed"] = Json::array();
    doc["extensionsUsed"].push_back("KHR_materials_emissive_strength");
  }
  if (!scene.textures.empty()) {
    Json textures = Json::array(), images = Json::array();
    for (const auto& [image, sampler] : table.textures) {
      Json texture{{"source", image}};
      if (sampler >= 0) texture["sampler"] = sampler;
      textures.push_back(std::move(texture));
    }
    for (size_t t = 0; t < scene.textures.size(); ++t) {
      Json image = Json::object();
      if (!scene.textures[t].name.empty()) image["name"] = scene.textures[t].name;
      image["bufferView"] = buffers.image_views[t];
      image["mimeType"] = "image/png";
      images.push_back(std::move(image));
    }
    doc["textures"] = std::move(textures);
    if (!table.samplers.empty()) {
      Json samplers = Json::array();
      for (const TextureSampler& sampler : table.samplers) samplers.push_back(sampler_json(sampler));
      doc["samplers"] = std::move(samplers);
    }
    doc["images"] = std::move(images);
  }
  doc["accessors"] = std::move(buffers.accessors);
  doc["bufferViews"] = std::move(buffers.views);
  Json buffer{{"byteLength", buffers.bin.size()}};
  if (!bin_uri.empty()) buffer["uri"] = bin_uri;
  doc["buffers"] = Json::array({buffer});
  return doc;
}

std::string dump(const Json& j) { return j.dump(-1, ' ', false, Json::error_handler_t::replace); }

// {"asset":...,\n"nodes":[\n{...},\n{...}],\n...}: one line per top-level member and per
// element of a top-level array.
std::string readable_text(const Json& doc) {
  std::string out = "{\n";
  bool first = true;
  for (const auto& [key, value] : doc.items()) {
    if (!first) out += ",\n";
    first = false;
    out += dump(Json(key)) + ":";
    if (value.is_array() && !value.empty() && value.front().is_object()) {
      out += "[\n";
      for (size_t i = 0; i < value.size(); ++i) out += (i ? ",\n" : "") + dump(value[i]);
      out += "\n]";
    } else {
      out += dump(value);
    }
  }
  return out + "\n}\n";
}

}  // namespace

Status serialize_scene(const SceneDesc& scene, const std::string& bin_uri, bool readable, SerializedScene& out) {
  out = {};
  if (Status s = check_scene_desc(scene); !s) return s;
  try {
    Buffers buffers;
    if (Status s = write_buffers(scene, buffers); !s) return s;
    const Json doc = build_document(scene, bin_uri, buffers);
    out.json = readable ? readable_text(doc) : dump(doc);
    out.bin = std::move(buffers.bin);
  } catch (const std::exception& e) {  // allocation failure; nothing else in here throws
    out = {};
    return Status::error(std::string("scene: cannot serialize: ") + e.what());
  }
  return {};
}

std::vector<uint8_t> pack_glb(const SerializedScene& scene) {
  std::string json = scene.json;
  json.resize((json.size() + 3) & ~size_t(3), ' ');
  const size_t bin_size = (scene.bin.size() + 3) & ~size_t(3);
  const size_t total = 12 + 8 + json.size() + (scene.bin.empty() ? 0 : 8 + bin_size);
  std::vector<uint8_t> out;
  out.reserve(total);
  auto u32 = [&](uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(uint8_t(v >> (8 * i)));
  };
  u32(0x46546C67);  // "glTF"
  u32(2);
  u32(uint32_t(total));
  u32(uint32_t(json.size()));
  u32(0x4E4F534A);  // "JSON"
  out.insert(out.end(), json.begin(), json.end());
  if (!scene.bin.empty()) {
    u32(uint32_t(bin_size));
    u32(0x004E4942);  // "BIN\0"
    out.insert(out.end(), scene.bin.begin(), scene.bin.end());
    out.resize(total, 0);
  }
  return out;
}

std::string uri_escape(const std::string& name) {
  static const char* const kHex = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : name) {
    const bool alnum = (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    if (alnum || c == '-' || c == '.' || c == '_' || c == '~') {
      out += char(c);
    } else {
      out += '%';
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  return out;
}

}  // namespace lintel::scene_write
