// read_gltf_model's second half: what meshes look like and what lights them -- materials, images,
// textures, samplers, KHR_lights_punctual lights. Each field Lintel reads is type-checked here;
// values (ranges, finiteness, which indices exist) are checked by the readers that use them.
#include "read/gltf_model.h"

#include "read/json_fields.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace lintel::scene_read {
namespace {

using nlohmann::json;

// No limit of their own: the JSON value count (json_bounded.h) bounds these arrays.
constexpr size_t kUnlimited = SIZE_MAX;

// Names only label messages: a name that is not a string is ignored, as tinygltf did.
std::string name_of(const json& obj) {
  const json* name = member(obj, "name");
  return name && name->is_string() ? name->get<std::string>() : std::string();
}

std::string optional_int(const json& obj, const char* key, int& out) {
  const json* v = member(obj, key);
  if (!v) return {};
  if (std::string why = read_int(*v, out); !why.empty()) return std::string(key) + " " + why;
  return {};
}

std::string optional_number(const json& obj, const char* key, double& out) {
  const json* v = member(obj, key);
  if (!v) return {};
  if (!v->is_number()) return std::string(key) + " must be a number, got " + json_kind(*v);
  out = v->get<double>();
  return {};
}

// An optional array of numbers, kept whole (the readers check its length and finiteness).
std::string optional_numbers(const json& obj, const char* key, std::vector<double>& out) {
  const json* v = member(obj, key);
  if (!v) return {};
  if (!v->is_array()) return std::string(key) + " must be an array of numbers, got " + json_kind(*v);
  out.clear();
  for (const json& e : *v) {
    if (!e.is_number())
      return std::string(key) + " element " + std::to_string(out.size()) + " must be a number, got " + json_kind(e);
    out.push_back(e.get<double>());
  }
  return {};
}

Status read_texture_info(const LoadContext& ctx, const json& info, const std::string& element,
                         tinygltf::TextureInfo& out) {
  if (!info.is_object()) return ctx.fail(element, "must be an object, got " + json_kind(info));
  const json* index = member(info, "index");
  if (!index) return ctx.fail(element, "'index' is missing");
  if (std::string why = read_int(*index, out.index); !why.empty()) return ctx.fail(element, "index " + why);
  if (std::string why = optional_int(info, "texCoord", out.texCoord); !why.empty()) return ctx.fail(element, why);
  if (out.texCoord < 0 || out.texCoord > 31)
    return ctx.fail(element, "texCoord " + std::to_string(out.texCoord) + " is not a uv set (0..31)");
  // KHR_texture_transform: kept as four numbers for mesh_read.cpp, which applies it to the uvs.
  const json* extensions = member(info, "extensions");
  const json* transform =
      extensions && extensions->is_object() ? member(*extensions, "KHR_texture_transform") : nullptr;
  if (!transform) return {};
  const std::string where = element + ".extensions.KHR_texture_transform";
  if (!transform->is_object()) return ctx.fail(where, "must be an object, got " + json_kind(*transform));
  std::vector<double> offset{0.0, 0.0}, scale{1.0, 1.0};
  double rotation = 0.0;
  for (const auto& [key, pair] : {std::pair{"offset", &offset}, std::pair{"scale", &scale}}) {
    if (std::string why = optional_numbers(*transform, key, *pair); !why.empty()) return ctx.fail(where, why);
    if (pair->size() != 2) return ctx.fail(where, std::string(key) + " must have 2 numbers");
  }
  if (std::string why = optional_number(*transform, "rotation", rotation); !why.empty()) return ctx.fail(where, why);
  for (double v : {offset[0], offset[1], scale[0], scale[1], rotation})
    if (!std::isfinite(v) || std::fabs(v) > 1e9) return ctx.fail(where, "a number is not finite or beyond 1e9");
  tinygltf::Value::Object kept;
  kept["offset_u"] = tinygltf::Value(offset[0]);
  kept["offset_v"] = tinygltf::Value(offset[1]);
  kept["scale_u"] = tinygltf::Value(scale[0]);
  kept["scale_v"] = tinygltf::Value(scale[1]);
  kept["rotation"] = tinygltf::Value(rotation);
  out.extensions["KHR_texture_transform"] = tinygltf::Value(std::move(kept));
  return {};
}

// emissiveFactor, emissiveTexture and KHR_materials_emissive_strength. The strength is folded
// into out.emissiveFactor (mesh_read.cpp takes that as Mesh::emissive).
Status read_emission(const LoadContext& ctx, const json& m, size_t i, const std::string& element,
                     tinygltf::Material& out) {
  std::vector<double>& factor = out.emissiveFactor;
  factor = {0.0, 0.0, 0.0};  // glTF's default
  if (std::string why = optional_numbers(m, "emissiveFactor", factor); !why.empty()) return ctx.fail(element, why);
  if (factor.size() != 3)
    return ctx.fail(element, "emissiveFactor must have 3 numbers, has " + std::to_string(factor.size()));
  for (double v : factor)
    if (!(v >= 0.0 && v <= 1e9))
      return ctx.fail(element, "emissiveFactor " + number_text(v) + " is negative or beyond 1e9");
  if (const json* t = member(m, "emissiveTexture"))
    if (Status s =
            read_texture_info(ctx, *t, "materials[" + std::to_string(i) + "].emissiveTexture", out.emissiveTexture);
        !s)
      return s;
  const json* extensions = member(m, "extensions");
  const json* strength_ext =
      extensions && extensions->is_object() ? member(*extensions, "KHR_materials_emissive_strength") : nullptr;
  if (!strength_ext) return {};
  const std::string where = element + ".extensions.KHR_materials_emissive_strength";
  if (!strength_ext->is_object()) return ctx.fail(where, "must be an object, got " + json_kind(*strength_ext));
  double strength = 1.0;
  if (std::string why = optional_number(*strength_ext, "emissiveStrength", strength); !why.empty())
    return ctx.fail(where, why);
  if (!(strength >= 0.0 && strength <= 1e9))
    return ctx.fail(where, "emissiveStrength " + number_text(strength) + " is negative or beyond 1e9");
  for (double& v : factor) v = std::min(v * strength, 1e9);
  return {};
}

Status read_material(const LoadContext& ctx, const json& m, size_t i, tinygltf::Material& out) {
  out.name = name_of(m);
  const std::string element = describe("material", i, out.name);
  if (Status s = read_emission(ctx, m, i, element, out); !s) return s;
  if (const json* d = member(m, "doubleSided"))
    if (std::string why = read_bool(*d, out.doubleSided); !why.empty()) return ctx.fail(element, "doubleSided " + why);
  if (const json* a = member(m, "alphaMode")) {
    if (!a->is_string()) return ctx.fail(element, "alphaMode must be a string, got " + json_kind(*a));
    out.alphaMode = a->get<std::string>();
    if (out.alphaMode != "OPAQUE" && out.alphaMode != "MASK" && out.alphaMode != "BLEND")
      return ctx.fail(element, "alphaMode must be OPAQUE, MASK or BLEND, got '" + one_line(out.alphaMode, 32) + "'");
  }
  if (const json* c = member(m, "alphaCutoff")) {
    if (!c->is_number()) return ctx.fail(element, "alphaCutoff must be a number, got " + json_kind(*c));
    out.alphaCutoff = c->get<double>();
    // glTF: minimum 0. Above 1 is allowed (nothing is drawn); beyond float range is not.
    if (!(out.alphaCutoff >= 0.0 && out.alphaCutoff <= 1e9))
      return ctx.fail(element, "alphaCutoff " + number_text(out.alphaCutoff) + " is negative or beyond 1e9");
  }
  const json* pbr = member(m, "pbrMetallicRoughness");
  if (!pbr) return {};
  if (!pbr->is_object()) return ctx.fail(element, "pbrMetallicRoughness must be an object, got " + json_kind(*pbr));
  std::vector<double>& factor = out.pbrMetallicRoughness.baseColorFactor;
  if (std::string why = optional_numbers(*pbr, "baseColorFactor", factor); !why.empty()) return ctx.fail(element, why);
  if (factor.size() != 4)
    return ctx.fail(element, "baseColorFactor must have 4 numbers, has " + std::to_string(factor.size()));
  if (const json* t = member(*pbr, "baseColorTexture"))
    return read_texture_info(ctx, *t, "materials[" + std::to_string(i) + "].pbrMetallicRoughness.baseColorTexture",
                             out.pbrMetallicRoughness.baseColorTexture);
  return {};
}

// An image is a bufferView or a URI; a data: URI is decoded now and its bytes kept (as_is), an
// external file is only named here (texture_read.cpp reads it when a drawn mesh uses it).
Status read_image(const LoadContext& ctx, const json& im, size_t i, const tinygltf::Model& model,
                  tinygltf::Image& out) {
  out.name = name_of(im);
  const std::string element =
      "images[" + std::to_string(i) + "]" + (out.name.empty() ? "" : " '" + one_line(out.name, 64) + "'");
  const json* view = member(im, "bufferView");
  const json* uri = member(im, "uri");
  if (view && uri) return ctx.fail(element, "has both 'bufferView' and 'uri' (glTF allows one)");
  if (!view && !uri) return ctx.fail(element, "has neither 'bufferView' nor 'uri'");
  if (view) {
    size_t index = 0;
    if (std::string why = read_index(*view, model.bufferViews.size(), index); !why.empty())
      return ctx.fail(element, "bufferView " + why);
    out.bufferView = int(index);
    if (const json* mime = member(im, "mimeType"); mime && mime->is_string()) out.mimeType = mime->get<std::string>();
    return {};
  }
  std::string text;
  if (std::string why = read_string(*uri, text); !why.empty()) return ctx.fail(element, "uri " + why);
  if (!tinygltf::IsDataURI(text)) {
    out.uri = std::move(text);
    return {};
  }
  if (!tinygltf::DecodeDataURI(&out.image, out.mimeType, text, 0, false) || out.image.empty())
    return ctx.fail(element, "data URI could not be decoded (base64 with an image, octet-stream or text MIME type)");
  out.as_is = true;
  return {};
}

Status read_light(const LoadContext& ctx, const json& l, size_t i, tinygltf::Light& out) {
  out.name = name_of(l);
  const std::string element = describe("light", i, out.name);
  if (!l.is_object()) return ctx.fail(element, "must be an object, got " + json_kind(l));
  const json* type = member(l, "type");
  if (!type) return ctx.fail(element, "'type' is missing");
  if (std::string why = read_string(*type, out.type); !why.empty()) return ctx.fail(element, "type " + why);
  for (auto [key, field] : {std::pair{"intensity", &out.intensity}, std::pair{"range", &out.range}})
    if (std::string why = optional_number(l, key, *field); !why.empty()) return ctx.fail(element, why);
  if (std::string why = optional_numbers(l, "color", out.color); !why.empty()) return ctx.fail(element, why);
  if (out.type != "spot") return {};
  const json* spot = member(l, "spot");
  if (!spot) return ctx.fail(element, "a spot light needs a 'spot' object");
  if (!spot->is_object()) return ctx.fail(element, "spot must be an object, got " + json_kind(*spot));
  for (auto [key, field] :
       {std::pair{"innerConeAngle", &out.spot.innerConeAngle}, std::pair{"outerConeAngle", &out.spot.outerConeAngle}})
    if (std::string why = optional_number(*spot, key, *field); !why.empty()) return ctx.fail(element, "spot." + why);
  return {};
}

Status read_lights(const LoadContext& ctx, const json& doc, tinygltf::Model& model) {
  const json* extensions = member(doc, "extensions");
  const json* punctual = extensions ? member(*extensions, "KHR_lights_punctual") : nullptr;
  if (!punctual) return {};
  const std::string element = "extensions.KHR_lights_punctual";
  if (!punctual->is_object()) return ctx.fail(element, "must be an object, got " + json_kind(*punctual));
  const json* lights = member(*punctual, "lights");
  if (!lights) return {};
  if (!lights->is_array()) return ctx.fail(element, "lights must be an array, got " + json_kind(*lights));
  model.lights.resize(lights->size());
  for (size_t i = 0; i < lights->size(); ++i)
    if (Status s = read_light(ctx, (*lights)[i], i, model.lights[i]); !s) return s;
  return {};
}

}  // namespace

Status read_gltf_looks(const LoadContext& ctx, const json& doc, tinygltf::Model& model) {
  const json* array = nullptr;
  if (Status s = top_level_objects(ctx, doc, "materials", kUnlimited, array); !s) return s;
  if (array) {
    model.materials.resize(array->size());
    for (size_t i = 0; i < array->size(); ++i)
      if (Status s = read_material(ctx, (*array)[i], i, model.materials[i]); !s) return s;
  }
  if (Status s = top_level_objects(ctx, doc, "images", kUnlimited, array); !s) return s;
  if (array) {
    model.images.resize(array->size());
    for (size_t i = 0; i < array->size(); ++i)
      if (Status s = read_image(ctx, (*array)[i], i, model, model.images[i]); !s) return s;
  }
  if (Status s = top_level_objects(ctx, doc, "textures", kUnlimited, array); !s) return s;
  if (array) {
    model.textures.resize(array->size());
    for (size_t i = 0; i < array->size(); ++i) {
      const std::string element = "textures[" + std::to_string(i) + "]";
      tinygltf::Texture& out = model.textures[i];
      for (auto [key, field] : {std::pair{"source", &out.source}, std::pair{"sampler", &out.sampler}})
        if (std::string why = optional_int((*array)[i], key, *field); !why.empty()) return ctx.fail(element, why);
    }
  }
  if (Status s = top_level_objects(ctx, doc, "samplers", kUnlimited, array); !s) return s;
  if (array) {
    model.samplers.resize(array->size());
    for (size_t i = 0; i < array->size(); ++i) {
      const std::string element = "samplers[" + std::to_string(i) + "]";
      tinygltf::Sampler& out = model.samplers[i];
      for (auto [key, field] : {std::pair{"magFilter", &out.magFilter}, std::pair{"minFilter", &out.minFilter},
                                std::pair{"wrapS", &out.wrapS}, std::pair{"wrapT", &out.wrapT}})
        if (std::string why = optional_int((*array)[i], key, *field); !why.empty()) return ctx.fail(element, why);
    }
  }
  // Not read by Lintel; tinygltf refused them when they were not arrays of objects.
  for (const char* unread : {"animations", "skins", "cameras"})
    if (Status s = top_level_objects(ctx, doc, unread, kUnlimited, array); !s) return s;
  return read_lights(ctx, doc, model);
}

}  // namespace lintel::scene_read
