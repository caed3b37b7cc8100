// Base colour as the scene format defines it (lintel/world.h, Texture): baseColorFactor times the
// baseColorTexture, texels decoded from sRGB to linear before bilinear filtering, REPEAT wrap.
// The CPU side of what the g-buffer samples on the GPU (GI surfels read it here), and the layer
// packing that puts every texture in one sampled 2D array.
#pragma once

#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lintel::render {

// Linear albedo of `mesh` at texture coordinate `uv` (the factor alone when it has no texture).
glm::vec3 base_color_at(const World& world, const Mesh& mesh, glm::vec2 uv);

// Every World texture resampled to one square size (the largest side among them, at most
// `max_size`, at least 1), sRGB bytes, layer after layer; one white texel layer when the world
// has no textures, so the sampler always has an image. Textures already of that size are copied
// unchanged.
struct TextureLayers {
  uint32_t size = 1, count = 1;
  std::vector<uint8_t> rgba8;  // size * size * 4 * count
};
TextureLayers pack_texture_layers(const World& world, uint32_t max_size = 1024);

// The next mip level of `count` square sRGB layers of side `size` (rgba8: size * size * 4 * count):
// side max(1, size / 2), each texel the mean in linear light of the 2x2 texels it covers (alpha
// averaged as is); for an odd side the last row and column fall out, as in a 2:1 linear blit.
// The CPU path of the mip chain where the device cannot blit the format.
std::vector<uint8_t> downsample_layers(const std::vector<uint8_t>& rgba8, uint32_t size, uint32_t count);

}  // namespace lintel::render
