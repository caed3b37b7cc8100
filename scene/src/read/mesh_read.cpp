// Primitive merging for lintel::Mesh. Indices are rebased as primitives are appended, so the
// result is a single triangle list over a single vertex array.
#include "read/mesh_read.h"

#include "read/load_limits.h"
#include "read/vertex_normals.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace lintel::scene_read {
namespace {

const char* mode_name(int mode) {
  switch (mode) {
    case TINYGLTF_MODE_POINTS:
      return "points";
    case TINYGLTF_MODE_LINE:
      return "lines";
    case TINYGLTF_MODE_LINE_LOOP:
      return "line loop";
    case TINYGLTF_MODE_LINE_STRIP:
      return "line strip";
    case TINYGLTF_MODE_TRIANGLE_STRIP:
      return "triangle strip";
    case TINYGLTF_MODE_TRIANGLE_FAN:
      return "triangle fan";
    default:
      return "unknown mode";
  }
}

// `where` names the primitive `first`.
Status read_base_color(const LoadContext& ctx, const tinygltf::Model& model, const tinygltf::Primitive& first,
                       const std::string& where, glm::vec4& out) {
  out = glm::vec4(1.0f);
  if (first.material < 0) return {};
  if (size_t(first.material) >= model.materials.size())
    return ctx.fail(where, "material " + std::to_string(first.material) + " does not exist");
  const std::vector<double>& f = model.materials[size_t(first.material)].pbrMetallicRoughness.baseColorFactor;
  const std::string material =
      describe("material", size_t(first.material), model.materials[size_t(first.material)].name);
  if (f.size() != 4) return ctx.fail(material, "baseColorFactor must have 4 numbers, has " + std::to_string(f.size()));
  for (int i = 0; i < 4; ++i) {
    if (!std::isfinite(f[size_t(i)]) || std::fabs(f[size_t(i)]) > 3.4e38)
      return ctx.fail(material, "baseColorFactor is not finite");
    out[i] = static_cast<float>(f[size_t(i)]);
  }
  return {};
}

// A triangle strip or fan (glTF 2.0, "Meshes": strip triangle i is v_i, v_{i+1+i%2}, v_{i+2-i%2};
// fan triangle i is v_{i+1}, v_{i+2}, v_0) appended as a list; triangles that repeat a vertex (the
// joins of concatenated strips) are left out.
Status strip_or_fan_to_list(const LoadContext& ctx, const std::string& where, bool strip,
                            const std::vector<uint32_t>& v, ReadBudget& budget, std::vector<uint32_t>& out) {
  if (v.size() < 3) return {};
  const size_t triangles = v.size() - 2;
  // The list holds up to 3 indices per triangle where the strip held about one: count the extra.
  const size_t extra = 3 * triangles - v.size();
  if (extra > kMaxTotalIndices - budget.indices)
    return ctx.fail(where, "more than " + std::to_string(kMaxTotalIndices) + " indices in the scene");
  budget.indices += extra;
  for (size_t i = 0; i < triangles; ++i) {
    const uint32_t a = strip ? v[i] : v[i + 1];
    const uint32_t b = strip ? v[i + 1 + i % 2] : v[i + 2];
    const uint32_t c = strip ? v[i + 2 - i % 2] : v[0];
    if (a == b || b == c || a == c) continue;
    out.insert(out.end(), {a, b, c});
  }
  return {};
}

// KHR_texture_transform of a texture (gltf_model_looks.cpp kept it), applied to the
// uvs as the extension defines it: uv' = translation(offset) * rotation(rotation) * scale(scale) * uv.
void apply_texture_transform(const tinygltf::TextureInfo& info, std::vector<glm::vec2>& uvs) {
  const auto found = info.extensions.find("KHR_texture_transform");
  if (found == info.extensions.end()) return;
  const tinygltf::Value& t = found->second;
  const double c = std::cos(t.Get("rotation").GetNumberAsDouble()), s = std::sin(t.Get("rotation").GetNumberAsDouble());
  const double su = t.Get("scale_u").GetNumberAsDouble(), sv = t.Get("scale_v").GetNumberAsDouble();
  const double ou = t.Get("offset_u").GetNumberAsDouble(), ov = t.Get("offset_v").GetNumberAsDouble();
  for (glm::vec2& uv : uvs) {
    const double u = su * double(uv.x), v = sv * double(uv.y);
    uv = glm::vec2(float(c * u + s * v + ou), float(-s * u + c * v + ov));
  }
}

bool is_triangles(const tinygltf::Primitive& prim) {
  // tinygltf stores an absent "mode" as 4 already; -1 is accepted for models built in memory.
  return prim.mode == TINYGLTF_MODE_TRIANGLES || prim.mode == -1 || prim.mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
         prim.mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

// Primitives `primitives` (indices into the mesh's, ascending) of mesh `index` merged into `out`,
// with the looks of the first triangle primitive's material.
Status read_primitives(const LoadContext& ctx, const tinygltf::Model& model, int index,
                       std::span<const size_t> primitives, ReadBudget& budget, TextureTable* textures, Mesh& out) {
  const tinygltf::Mesh& gm = model.meshes[size_t(index)];
  const std::string element = describe("mesh", size_t(index), gm.name);
  out = Mesh{};
  if (gm.name.find('\0') != std::string::npos) return ctx.fail(element, "name contains a NUL byte (\\u0000)");
  out.name = gm.name;
  out.gltf_index = index;
  // The looks are the first triangle primitive's (a skipped points or lines primitive draws nothing).
  size_t looks = primitives.empty() ? 0 : primitives.front();
  for (const size_t p : primitives)
    if (is_triangles(gm.primitives[p])) {
      looks = p;
      break;
    }
  const tinygltf::Primitive* first = primitives.empty() ? nullptr : &gm.primitives[looks];
  if (first) {
    const std::string where = element + " primitive " + std::to_string(looks);
    if (Status s = read_base_color(ctx, model, *first, where, out.base_color); !s) return s;
    if (const int material = first->material; material >= 0) {
      const tinygltf::Material& m = model.materials[size_t(material)];
      out.double_sided = m.doubleSided;
      // read_material accepted only glTF's three modes and a cutoff in [0, 1e9].
      out.alpha_mode = m.alphaMode == "MASK"    ? Mesh::AlphaMode::Mask
                       : m.alphaMode == "BLEND" ? Mesh::AlphaMode::Blend
                                                : Mesh::AlphaMode::Opaque;
      out.alpha_cutoff = float(m.alphaCutoff);
    }
    // read_base_color proved the material index valid.
    if (const int material = first->material; textures && material >= 0) {
      const tinygltf::Material& m = model.materials[size_t(material)];
      textures->note_drawn_material(material);
      if (Status s = textures->base_color_texture(material, out.base_color_texture, out.base_color_sampler); !s)
        return s;
      // read_emission checked the factor (strength folded in): finite, in [0, 1e9].
      out.emissive = glm::vec3(float(m.emissiveFactor[0]), float(m.emissiveFactor[1]), float(m.emissiveFactor[2]));
      // glTF multiplies the texture by the factor: with a zero factor it adds nothing (and needs no uvs).
      if (out.emissive != glm::vec3(0.0f))
        if (Status s = textures->emissive_texture(material, out.emissive_texture, out.emissive_sampler); !s) return s;
    }
  }
  bool every_primitive_has_uvs = true;
  // The one uv set Lintel reads: the base colour texture's (its texCoord: TEXCOORD_0 unless the
  // material says), else the emissive texture's; an emissive texture that reads another set or
  // transform than the base colour's is drawn with the base colour's (warned).
  const tinygltf::TextureInfo* uv_owner = nullptr;
  if (out.base_color_texture >= 0 || out.emissive_texture >= 0) {
    const tinygltf::Material& m = model.materials[size_t(first->material)];
    const tinygltf::TextureInfo& base = m.pbrMetallicRoughness.baseColorTexture;
    uv_owner = out.base_color_texture >= 0 ? &base : &m.emissiveTexture;
    if (out.base_color_texture >= 0 && out.emissive_texture >= 0 &&
        (base.texCoord != m.emissiveTexture.texCoord || !(base.extensions == m.emissiveTexture.extensions)))
      ctx.warn(describe("material", size_t(first->material), m.name),
               "emissiveTexture reads another uv set or KHR_texture_transform than baseColorTexture; Lintel reads "
               "one, the base colour's");
  }
  const std::string uv_set = "TEXCOORD_" + std::to_string(uv_owner ? uv_owner->texCoord : 0);
  const bool needs_uvs = out.base_color_texture >= 0 || out.emissive_texture >= 0;

  for (const size_t p : primitives) {
    const tinygltf::Primitive& prim = gm.primitives[p];
    const std::string where = element + " primitive " + std::to_string(p);
    const bool list = prim.mode == TINYGLTF_MODE_TRIANGLES || prim.mode == -1;
    if (!is_triangles(prim)) {
      ctx.warn(where, std::string("has mode ") + std::to_string(prim.mode) + " (" + mode_name(prim.mode) +
                          "); only triangles (lists, strips, fans) are read, skipped");
      continue;
    }
    const auto position = prim.attributes.find("POSITION");
    if (position == prim.attributes.end()) return ctx.fail(where, "has no POSITION attribute");

    const size_t first_vertex = out.positions.size();
    const size_t first_index = out.indices.size();
    if (Status s = read_vec3_accessor(ctx, model, position->second, "POSITION of " + where, budget, out.positions); !s)
      return s;
    const size_t vertex_count = out.positions.size() - first_vertex;
    const auto base = static_cast<uint32_t>(first_vertex);  // < kMaxTotalVertices, fits

    if (prim.indices >= 0) {
      if (Status s = read_index_accessor(ctx, model, prim.indices, "indices of " + where, vertex_count, base, budget,
                                         out.indices);
          !s)
        return s;
    } else {
      if (vertex_count > kMaxTotalIndices - budget.indices)
        return ctx.fail(where, "more than " + std::to_string(kMaxTotalIndices) + " indices in the scene");
      budget.indices += vertex_count;
      for (size_t v = 0; v < vertex_count; ++v) out.indices.push_back(base + static_cast<uint32_t>(v));
    }
    if (!list) {
      const std::vector<uint32_t> corners(out.indices.begin() + std::ptrdiff_t(first_index), out.indices.end());
      out.indices.resize(first_index);
      if (Status s =
              strip_or_fan_to_list(ctx, where, prim.mode == TINYGLTF_MODE_TRIANGLE_STRIP, corners, budget, out.indices);
          !s)
        return s;
    }
    const size_t index_count = out.indices.size() - first_index;
    if (index_count % 3 != 0)
      return ctx.fail(where, "triangle list has " + std::to_string(index_count) + " indices, not a multiple of 3");

    out.normals.resize(out.positions.size());
    const auto normal = prim.attributes.find("NORMAL");
    if (normal != prim.attributes.end()) {
      std::vector<glm::vec3> normals;
      if (Status s = read_vec3_accessor(ctx, model, normal->second, "NORMAL of " + where, budget, normals); !s)
        return s;
      if (normals.size() != vertex_count)
        return ctx.fail(where, "NORMAL has " + std::to_string(normals.size()) + " elements, POSITION has " +
                                   std::to_string(vertex_count));
      std::copy(normals.begin(), normals.end(), out.normals.begin() + static_cast<std::ptrdiff_t>(first_vertex));
    } else if (textures) {  // portal and volume meshes are never shaded: their normals stay zero
      compute_vertex_normals(out.positions, out.indices, first_index, first_vertex, vertex_count, out.normals);
    }

    if (!textures) continue;
    // COLOR_0 multiplies the base colour; a primitive without it is white (glTF 2.0).
    if (const auto color = prim.attributes.find("COLOR_0"); color != prim.attributes.end()) {
      out.colors.resize(first_vertex, glm::vec4(1.0f));  // pads earlier primitives without COLOR_0
      if (Status s = read_color_accessor(ctx, model, color->second, "COLOR_0 of " + where, budget, out.colors); !s)
        return s;
      if (out.colors.size() != out.positions.size())
        return ctx.fail(where, "COLOR_0 has " + std::to_string(out.colors.size() - first_vertex) +
                                   " elements, POSITION has " + std::to_string(vertex_count));
    } else if (!out.colors.empty()) {
      out.colors.resize(out.positions.size(), glm::vec4(1.0f));
    }
    const auto uv = prim.attributes.find(uv_set);
    if (uv == prim.attributes.end()) {
      if (needs_uvs)
        return ctx.fail(where, "has no " + uv_set + ", but the mesh has " +
                                   (out.base_color_texture >= 0 ? "a base colour" : "an emissive") +
                                   " texture (material " + std::to_string(first->material) + ")");
      every_primitive_has_uvs = false;
      continue;
    }
    out.uvs.resize(first_vertex);  // pads an earlier primitive without uvs (then all are dropped below)
    if (Status s = read_vec2_accessor(ctx, model, uv->second, uv_set + " of " + where, budget, out.uvs); !s) return s;
    if (out.uvs.size() != out.positions.size())
      return ctx.fail(where, uv_set + " has " + std::to_string(out.uvs.size() - first_vertex) +
                                 " elements, POSITION has " + std::to_string(vertex_count));
  }
  if (!every_primitive_has_uvs || !textures) out.uvs.clear();
  if (!out.uvs.empty() && uv_owner) apply_texture_transform(*uv_owner, out.uvs);
  for (const glm::vec3& p : out.positions) out.bounds_mesh.extend(p);
  return {};
}

}  // namespace

Status read_mesh(const LoadContext& ctx, const tinygltf::Model& model, int index, ReadBudget& budget,
                 TextureTable* textures, Mesh& out) {
  std::vector<size_t> all(model.meshes[size_t(index)].primitives.size());
  for (size_t p = 0; p < all.size(); ++p) all[p] = p;
  return read_primitives(ctx, model, index, all, budget, textures, out);
}

Status read_mesh_parts(const LoadContext& ctx, const tinygltf::Model& model, int index, ReadBudget& budget,
                       TextureTable& textures, std::vector<Mesh>& parts) {
  const std::vector<tinygltf::Primitive>& prims = model.meshes[size_t(index)].primitives;
  // Part k: the triangle primitives of the k-th material in order of first use. A primitive that is
  // not triangles goes with the first part (read_primitives warns about it and skips it).
  std::vector<int> materials;
  std::vector<std::vector<size_t>> members;
  for (size_t p = 0; p < prims.size(); ++p) {
    if (!is_triangles(prims[p])) continue;
    const size_t k = size_t(std::find(materials.begin(), materials.end(), prims[p].material) - materials.begin());
    if (k == materials.size()) {
      materials.push_back(prims[p].material);
      members.emplace_back();
    }
    members[k].push_back(p);
  }
  if (members.size() <= 1) {  // one material (or no triangles): the mesh as one part, as always
    parts.resize(1);
    return read_mesh(ctx, model, index, budget, &textures, parts[0]);
  }
  for (size_t p = 0; p < prims.size(); ++p)
    if (!is_triangles(prims[p])) members[0].push_back(p);
  std::sort(members[0].begin(), members[0].end());
  parts.resize(members.size());
  for (size_t k = 0; k < members.size(); ++k)
    if (Status s = read_primitives(ctx, model, index, members[k], budget, &textures, parts[k]); !s) return s;
  return {};
}

}  // namespace lintel::scene_read
