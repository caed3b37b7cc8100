// Base colour textures as the reference ray casters sample them (the path tracer's albedo, and
// the cut-outs' coverage there and in the ray-cast ground truth): texels decoded from sRGB to
// linear once, at build time, into a mip chain, then read through the glTF sampler (wrap modes,
// filters, mip mode) as the realtime renderer's g-buffer reads its VK_FORMAT_R8G8B8A8_SRGB array
// (render/shaders/base_color.glsl; the convention of lintel::Texture in world.h). Tests and
// benchmarks only.
#pragma once

#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lintel::reference {

struct LinearTexture {
  struct Level {
    uint32_t width = 0, height = 0;
    std::vector<glm::vec3> texels;  // linear rgb, row-major, row 0 = the image's top row (v = 0)
    std::vector<float> alpha;       // the same texels' alpha in [0, 1] (linear in the file)
  };
  // Level 0 is the image; each next level is max(1, w / 2) x max(1, h / 2), down to 1 x 1, each
  // texel the mean of the 2x2 texels of the level above it covers (an odd side's last row or
  // column falls out): the renderer's chain, without its rounding to 8 bits per level.
  std::vector<Level> levels;
};

// IEC 61966-2-1: c / 12.92 below 0.04045, else ((c + 0.055) / 1.055)^2.4, c = value / 255.
float srgb_to_linear(uint8_t value);

// The texture's rgb decoded to linear, and its alpha (for Mesh::AlphaMode::Mask coverage), with
// their mip chains. Precondition: rgba8.size() == width * height * 4, width and height >= 1.
LinearTexture to_linear(const Texture& texture);

// The lookup at glTF uv (u right, v down, (0, 0) the top-left corner of the image; texel (i, j)
// centred at ((i + 0.5) / width, (j + 0.5) / height)) through `sampler`, at level of detail `lod`
// (log2 of the footprint's side in level-0 texels), by the g-buffer's rule: lod <= 0 magnifies
// (level 0, sampler.mag); otherwise sampler.min at level 0 (mip None), at level round(lod) (mip
// Nearest) or blended between floor(lod) and the next (mip Linear), lod clamped to the last
// level. Texel indices wrap as Vulkan wraps them (REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT). Any
// finite uv is fine; a non-finite one reads as (0, 0), a NaN lod as magnification.
glm::vec3 sample_texture(const LinearTexture& texture, const TextureSampler& sampler, glm::vec2 uv, float lod);
// The alpha channel, read by the same rule.
float sample_alpha(const LinearTexture& texture, const TextureSampler& sampler, glm::vec2 uv, float lod);

}  // namespace lintel::reference
