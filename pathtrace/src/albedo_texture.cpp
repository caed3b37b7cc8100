// sRGB decoding and bilinear REPEAT filtering, in the order the GPU does them for an _SRGB image:
// each of the four texels is decoded first, then they are blended (Vulkan spec, "Texel
// Filtering": sRGB conversion happens on texel fetch, before filtering).
#include "albedo_texture.h"

#include <array>
#include <cassert>
#include <cmath>

namespace lintel::pathtrace_detail {
namespace {

std::array<float, 256> make_srgb_table() {
  std::array<float, 256> table{};
  for (int i = 0; i < 256; ++i) {
    const double c = i / 255.0;
    table[size_t(i)] = float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
  }
  return table;
}

// The texel column (or row) pair around coordinate `t` (in texels, texel centres at k + 0.5) and
// the weight of the second, with t already wrapped into [0, size].
void wrap_pair(float t, uint32_t size, uint32_t& i0, uint32_t& i1, float& f) {
  const float x = t - 0.5f;
  const float x0 = std::floor(x);
  f = x - x0;
  const auto k = int64_t(x0);  // in [-1, size - 1]
  i0 = uint32_t(k < 0 ? k + int64_t(size) : k % int64_t(size));
  i1 = uint32_t((k + 1) % int64_t(size));
}

}  // namespace

float srgb_to_linear(uint8_t value) {
  static const std::array<float, 256> kTable = make_srgb_table();
  return kTable[value];
}

LinearTexture to_linear(const Texture& texture) {
  assert(texture.width >= 1 && texture.height >= 1);
  assert(texture.rgba8.size() == size_t(texture.width) * texture.height * 4);
  LinearTexture out;
  out.width = texture.width;
  out.height = texture.height;
  out.texels.resize(size_t(texture.width) * texture.height);
  for (size_t i = 0; i < out.texels.size(); ++i)
    out.texels[i] = {srgb_to_linear(texture.rgba8[4 * i]), srgb_to_linear(texture.rgba8[4 * i + 1]),
                     srgb_to_linear(texture.rgba8[4 * i + 2])};
  return out;
}

glm::vec3 sample_bilinear_repeat(const LinearTexture& texture, glm::vec2 uv) {
  if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return texture.texels[0];
  // Wrap first, so that huge uvs cannot overflow the texel index; u - floor(u) may round up to
  // exactly 1, which wrap_pair handles (it is the same place as 0).
  const float u = uv.x - std::floor(uv.x), v = uv.y - std::floor(uv.y);
  uint32_t x0, x1, y0, y1;
  float fx, fy;
  wrap_pair(u * float(texture.width), texture.width, x0, x1, fx);
  wrap_pair(v * float(texture.height), texture.height, y0, y1, fy);
  const auto at = [&texture](uint32_t x, uint32_t y) { return texture.texels[size_t(y) * texture.width + x]; };
  const glm::vec3 top = glm::mix(at(x0, y0), at(x1, y0), fx);
  const glm::vec3 bottom = glm::mix(at(x0, y1), at(x1, y1), fx);
  return glm::mix(top, bottom, fy);
}

}  // namespace lintel::pathtrace_detail
