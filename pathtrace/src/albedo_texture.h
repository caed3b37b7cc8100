// Base colour textures as the path tracer samples them: texels decoded from sRGB to linear once,
// at build time, then bilinear filtering with REPEAT wrapping, the convention of lintel::Texture
// (world.h) that the realtime renderer's VK_FORMAT_R8G8B8A8_SRGB image and linear sampler follow.
#pragma once

#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lintel::pathtrace_detail {

struct LinearTexture {
  uint32_t width = 0, height = 0;
  std::vector<glm::vec3> texels;  // linear rgb, row-major, row 0 = the image's top row (v = 0)
};

// IEC 61966-2-1: c / 12.92 below 0.04045, else ((c + 0.055) / 1.055)^2.4, c = value / 255.
float srgb_to_linear(uint8_t value);

// The texture's rgb decoded to linear (alpha is dropped: the albedo has none). Precondition:
// rgba8.size() == width * height * 4, width and height >= 1.
LinearTexture to_linear(const Texture& texture);

// Bilinear lookup at glTF uv (u right, v down, (0, 0) the top-left corner of the image; texel
// (i, j) centred at ((i + 0.5) / width, (j + 0.5) / height)), REPEAT on both axes. Any finite uv
// is fine; a non-finite one reads texel (0, 0).
glm::vec3 sample_bilinear_repeat(const LinearTexture& texture, glm::vec2 uv);

}  // namespace lintel::pathtrace_detail
