// Base colour as the scene format defines it (lintel/world.h, Texture): baseColorFactor times the
// baseColorTexture, texels decoded from sRGB to linear before filtering, read through the glTF
// sampler. The CPU side of what the g-buffer samples on the GPU (the GI surfels read it here,
// with the same mip chain, wrap and filter rules), and the layer packing that puts every
// texture in one sampled 2D array.
#pragma once

#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace lintel::render {

// One texture's mip chain as the renderer builds it: level 0 is the image itself, each next level
// max(1, w / 2) x max(1, h / 2) (down to 1 x 1), each texel the mean in linear light of the 2x2
// texels it covers (downsample_rgba8), stored as sRGB bytes like the GPU's levels.
struct TextureMips {
  const Texture* texture = nullptr;  // level 0; must outlive this
  std::vector<glm::uvec2> sizes;     // per level, width and height
  std::vector<size_t> offsets;       // per level >= 1: where it starts in `smaller`
  std::vector<uint8_t> smaller;      // levels 1.., rgba8, one after another
  const uint8_t* level(size_t k) const { return k == 0 ? texture->rgba8.data() : smaller.data() + offsets[k]; }
};
// Precondition: texture.width, height >= 1 and rgba8 holds width * height * 4 bytes.
TextureMips texture_mips(const Texture& texture);

// The g-buffer's texture lookup (gbuffer.frag, sample_base_color) on the CPU, in linear rgb.
// `lod` is the level of detail: log2 of the footprint's side in texels of level 0. lod <= 0
// magnifies: level 0 with sampler.mag. Otherwise sampler.min at the level(s) sampler.mip names:
// None level 0, Nearest level round(lod), Linear a blend of floor(lod) and the next; lod is
// clamped to the last level. Wrapping is per texel index, as Vulkan defines REPEAT,
// CLAMP_TO_EDGE and MIRRORED_REPEAT; a linear filter blends the 2x2 texels around uv (texel
// centres at (i + 0.5) / width), a nearest one takes the texel uv lies in. A non-finite uv reads
// as (0, 0), a NaN lod as magnification.
glm::vec3 sample_texture(const TextureMips& mips, const TextureSampler& sampler, glm::vec2 uv, float lod);
// The same lookup with alpha (linear in the file; for cut-outs, Mesh::AlphaMode::Mask).
glm::vec4 sample_texture_rgba(const TextureMips& mips, const TextureSampler& sampler, glm::vec2 uv, float lod);

// The level of detail of a square footprint of `area_m2` on a surface with `texels_per_m2`
// level-0 texels per square metre: log2 of its side in texels, 0.5 * log2(area * density).
// -infinity (magnification) when the product is not positive.
float footprint_lod(float area_m2, float texels_per_m2);

// Every World texture resampled to one square size (the largest side among them, at most
// `max_size`, at least 1), sRGB bytes, layer after layer; one white texel layer when the world
// has no textures, so the sampler always has an image. Textures already of that size are copied
// unchanged.
struct TextureLayers {
  uint32_t size = 1, count = 1;
  std::vector<uint8_t> rgba8;  // size * size * 4 * count
};
TextureLayers pack_texture_layers(const World& world, uint32_t max_size = 1024);

// The next mip level of one width x height sRGB image: max(1, width / 2) x max(1, height / 2),
// each texel the mean in linear light of the 2x2 texels it covers (alpha averaged as is); for an
// odd side the last row or column falls out, as in a 2:1 linear blit.
std::vector<uint8_t> downsample_rgba8(const uint8_t* rgba8, uint32_t width, uint32_t height);

// downsample_rgba8 of each of `count` square sRGB layers of side `size` (rgba8: size * size * 4 *
// count), layer after layer. The CPU path of the mip chain where the device cannot blit the format.
std::vector<uint8_t> downsample_layers(const std::vector<uint8_t>& rgba8, uint32_t size, uint32_t count);

}  // namespace lintel::render
