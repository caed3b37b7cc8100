// Base colour and emissive textures: a material's pbrMetallicRoughness.baseColorTexture (or
// emissiveTexture) -> textures[i] ->
// images[j] -> one lintel::Texture (RGBA8, as in the file), each glTF image decoded at most once.
// Image bytes come from a bufferView, a data: URI (decoded by read_gltf_model) or a
// file beside the scene; PNG and JPEG are decoded with stb_image.
#pragma once

#include "read/load_context.h"

#include <lintel/world.h>

#include <cstddef>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
struct TextureInfo;
}  // namespace tinygltf

namespace lintel::scene_read {

class TextureTable {
 public:
  // `base_dir` resolves external image URIs (empty: only embedded images are allowed); decoded
  // images are appended to `textures` (World::textures), which must outlive the table.
  TextureTable(const LoadContext& ctx, const tinygltf::Model& model, std::string base_dir,
               std::vector<Texture>& textures);

  // The base colour texture of material `material` (an existing material index) as an index into
  // `textures`, or -1 when the material has none, and its glTF sampler (defaults without one).
  // Decodes the image the first time it is used.
  Status base_color_texture(int material, int& out, TextureSampler& sampler);
  // The same for the material's emissiveTexture.
  Status emissive_texture(int material, int& out, TextureSampler& sampler);
  // Material `material` (an existing index) gives a drawn mesh its looks: warns, once per
  // material, when its alphaMode is BLEND, which Lintel draws with screen-door transparency, not
  // blended (glass would otherwise look unlike the file silently; MASK cut-outs are drawn as such). Volumes and portals, which
  // Lintel's own writer marks BLEND to hide them in other viewers, are not drawn: no warning.
  void note_drawn_material(int material);

 private:
  Status texture_of(const tinygltf::TextureInfo& info, const std::string& element, int& out, TextureSampler& sampler);
  Status decode_image(size_t image, int& out);
  Status read_sampler(int sampler, TextureSampler& out) const;

  const LoadContext& ctx_;
  const tinygltf::Model& model_;
  std::string base_dir_;
  std::vector<Texture>& textures_;
  std::vector<int> slot_of_image_;  // glTF image -> index into textures_, -1 while not decoded
  std::vector<bool> alpha_warned_;  // per glTF material
  size_t texel_bytes_ = 0;          // all decoded images together, against kMaxTotalTexelBytes
};

}  // namespace lintel::scene_read
