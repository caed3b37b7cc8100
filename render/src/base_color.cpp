#include "base_color.h"

#include <algorithm>
#include <cmath>

namespace lintel::render {
namespace {

float srgb_to_linear(uint8_t v) {
  const float c = float(v) / 255.0f;
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

int wrap(int i, int n) { return ((i % n) + n) % n; }

// Bilinear with REPEAT on decoded texels; `decode` false filters the bytes themselves (resampling).
glm::vec4 bilinear(const Texture& t, glm::vec2 uv, bool decode) {
  const float x = uv.x * float(t.width) - 0.5f, y = uv.y * float(t.height) - 0.5f;
  const float fx = std::floor(x), fy = std::floor(y);
  const float ax = x - fx, ay = y - fy;
  glm::vec4 sum(0.0f);
  for (int k = 0; k < 4; ++k) {
    const int i = wrap(int(fx) + (k & 1), int(t.width)), j = wrap(int(fy) + (k >> 1), int(t.height));
    const uint8_t* p = &t.rgba8[(size_t(j) * t.width + size_t(i)) * 4];
    glm::vec4 texel = decode
                          ? glm::vec4(srgb_to_linear(p[0]), srgb_to_linear(p[1]), srgb_to_linear(p[2]), p[3] / 255.0f)
                          : glm::vec4(p[0], p[1], p[2], p[3]);
    const float w = ((k & 1) ? ax : 1.0f - ax) * ((k >> 1) ? ay : 1.0f - ay);
    sum += w * texel;
  }
  return sum;
}

}  // namespace

glm::vec3 base_color_at(const World& world, const Mesh& mesh, glm::vec2 uv) {
  const glm::vec3 factor(mesh.base_color);
  if (mesh.base_color_texture < 0 || size_t(mesh.base_color_texture) >= world.textures.size()) return factor;
  const Texture& t = world.textures[size_t(mesh.base_color_texture)];
  if (t.width == 0 || t.height == 0) return factor;
  return factor * glm::vec3(bilinear(t, uv, true));
}

TextureLayers pack_texture_layers(const World& world, uint32_t max_size) {
  TextureLayers out;
  if (world.textures.empty()) {
    out.rgba8 = {255, 255, 255, 255};
    return out;
  }
  uint32_t size = 1;
  for (const Texture& t : world.textures) size = std::max({size, t.width, t.height});
  out.size = std::min(size, std::max(max_size, 1u));
  out.count = uint32_t(world.textures.size());
  const size_t layer_bytes = size_t(out.size) * out.size * 4;
  out.rgba8.resize(layer_bytes * out.count);
  for (size_t l = 0; l < world.textures.size(); ++l) {
    const Texture& t = world.textures[l];
    uint8_t* dst = out.rgba8.data() + l * layer_bytes;
    if (t.width == out.size && t.height == out.size) {
      std::copy(t.rgba8.begin(), t.rgba8.end(), dst);
      continue;
    }
    for (uint32_t j = 0; j < out.size; ++j)
      for (uint32_t i = 0; i < out.size; ++i) {
        const glm::vec2 uv((float(i) + 0.5f) / float(out.size), (float(j) + 0.5f) / float(out.size));
        const glm::vec4 v = t.width && t.height ? bilinear(t, uv, false) : glm::vec4(255.0f);
        for (int c = 0; c < 4; ++c)
          dst[(size_t(j) * out.size + i) * 4 + size_t(c)] = uint8_t(std::lround(std::clamp(v[c], 0.0f, 255.0f)));
      }
  }
  return out;
}

std::vector<uint8_t> downsample_layers(const std::vector<uint8_t>& rgba8, uint32_t size, uint32_t count) {
  const uint32_t half = std::max(1u, size / 2);
  std::vector<uint8_t> out(size_t(half) * half * 4 * count);
  auto encode = [](float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    const float s = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return uint8_t(std::lround(s * 255.0f));
  };
  for (uint32_t l = 0; l < count; ++l) {
    const uint8_t* src = rgba8.data() + size_t(l) * size * size * 4;
    uint8_t* dst = out.data() + size_t(l) * half * half * 4;
    for (uint32_t j = 0; j < half; ++j)
      for (uint32_t i = 0; i < half; ++i) {
        glm::vec4 sum(0.0f);
        for (uint32_t k = 0; k < 4; ++k) {
          const uint32_t x = std::min(size - 1, 2 * i + (k & 1)), y = std::min(size - 1, 2 * j + (k >> 1));
          const uint8_t* p = src + (size_t(y) * size + x) * 4;
          sum += glm::vec4(srgb_to_linear(p[0]), srgb_to_linear(p[1]), srgb_to_linear(p[2]), float(p[3]) / 255.0f);
        }
        sum *= 0.25f;
        uint8_t* q = dst + (size_t(j) * half + i) * 4;
        for (int c = 0; c < 3; ++c) q[c] = encode(sum[c]);
        q[3] = uint8_t(std::lround(std::clamp(sum[3], 0.0f, 1.0f) * 255.0f));
      }
  }
  return out;
}

}  // namespace lintel::render
