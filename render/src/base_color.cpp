// The CPU side of the base colour (base_color.h): the g-buffer's texture lookup for the GI
// surfels, written from Vulkan's wrapping and filtering rules, and the packing and mip levels the
// upload puts on the GPU.
#include "base_color.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>

namespace lintel::render {
namespace {

using Wrap = TextureSampler::Wrap;

float srgb_to_linear(uint8_t v) {
  static const std::array<float, 256> kTable = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) {
      const float c = float(i) / 255.0f;
      t[size_t(i)] = c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
    }
    return t;
  }();
  return kTable[v];
}

int wrap(int i, int n) { return ((i % n) + n) % n; }

// Bilinear with REPEAT on the bytes themselves (resampling to the layer size).
glm::vec4 bilinear_bytes(const Texture& t, glm::vec2 uv) {
  const float x = uv.x * float(t.width) - 0.5f, y = uv.y * float(t.height) - 0.5f;
  const float fx = std::floor(x), fy = std::floor(y);
  const float ax = x - fx, ay = y - fy;
  glm::vec4 sum(0.0f);
  for (int k = 0; k < 4; ++k) {
    const int i = wrap(int(fx) + (k & 1), int(t.width)), j = wrap(int(fy) + (k >> 1), int(t.height));
    const uint8_t* p = &t.rgba8[(size_t(j) * t.width + size_t(i)) * 4];
    const float w = ((k & 1) ? ax : 1.0f - ax) * ((k >> 1) ? ay : 1.0f - ay);
    sum += w * glm::vec4(p[0], p[1], p[2], p[3]);
  }
  return sum;
}

// Texel index i of a row (or column) of n texels under `mode`, as Vulkan wraps integer texel
// coordinates: REPEAT i mod n; CLAMP_TO_EDGE clamp(i, 0, n - 1); MIRRORED_REPEAT the period of
// 2n read forwards, then backwards.
int64_t wrap_index(int64_t i, int64_t n, Wrap mode) {
  switch (mode) {
    case Wrap::ClampToEdge:
      return std::clamp<int64_t>(i, 0, n - 1);
    case Wrap::MirroredRepeat: {
      const int64_t t = ((i % (2 * n)) + 2 * n) % (2 * n);
      return t < n ? t : 2 * n - 1 - t;
    }
    case Wrap::Repeat:
      break;
  }
  return ((i % n) + n) % n;
}

// u moved by whole periods (clamped far outside for CLAMP_TO_EDGE) so that u * size fits an
// index; what it samples does not change. A non-finite u reads as 0.
float reduce_coordinate(float u, Wrap mode) {
  if (!std::isfinite(u)) return 0.0f;
  if (mode == Wrap::Repeat) return u - std::floor(u);
  if (mode == Wrap::MirroredRepeat) return u - 2.0f * std::floor(0.5f * u);
  return std::clamp(u, -1.0f, 2.0f);
}

// Linear rgb and alpha (alpha is stored linear) of level k.
glm::vec4 sample_level(const TextureMips& mips, size_t k, const TextureSampler& s, glm::vec2 uv, bool nearest) {
  const int64_t w = mips.sizes[k].x, h = mips.sizes[k].y;
  const uint8_t* pixels = mips.level(k);
  const auto texel = [&](int64_t i, int64_t j) {
    const uint8_t* p =
        pixels + (size_t(wrap_index(j, h, s.wrap_t)) * size_t(w) + size_t(wrap_index(i, w, s.wrap_s))) * 4;
    return glm::vec4(srgb_to_linear(p[0]), srgb_to_linear(p[1]), srgb_to_linear(p[2]), float(p[3]) / 255.0f);
  };
  const float x = reduce_coordinate(uv.x, s.wrap_s) * float(w), y = reduce_coordinate(uv.y, s.wrap_t) * float(h);
  if (nearest) return texel(int64_t(std::floor(x)), int64_t(std::floor(y)));
  const float fx = std::floor(x - 0.5f), fy = std::floor(y - 0.5f);
  const float ax = x - 0.5f - fx, ay = y - 0.5f - fy;
  const int64_t i = int64_t(fx), j = int64_t(fy);
  return glm::mix(glm::mix(texel(i, j), texel(i + 1, j), ax), glm::mix(texel(i, j + 1), texel(i + 1, j + 1), ax), ay);
}

}  // namespace

TextureMips texture_mips(const Texture& texture) {
  assert(texture.width >= 1 && texture.height >= 1);
  assert(texture.rgba8.size() == size_t(texture.width) * texture.height * 4);
  TextureMips out;
  out.texture = &texture;
  glm::uvec2 size(texture.width, texture.height);
  out.sizes.push_back(size);
  out.offsets.push_back(0);
  std::vector<uint8_t> level;
  while (size.x > 1 || size.y > 1) {
    const uint8_t* above = out.sizes.size() == 1 ? texture.rgba8.data() : out.smaller.data() + out.offsets.back();
    level = downsample_rgba8(above, size.x, size.y);
    size = glm::max(size / 2u, glm::uvec2(1));
    out.offsets.push_back(out.smaller.size());
    out.sizes.push_back(size);
    out.smaller.insert(out.smaller.end(), level.begin(), level.end());
  }
  return out;
}

glm::vec4 sample_texture_rgba(const TextureMips& mips, const TextureSampler& sampler, glm::vec2 uv, float lod) {
  using Filter = TextureSampler::Filter;
  using MipMode = TextureSampler::MipMode;
  if (!(lod > 0.0f)) return sample_level(mips, 0, sampler, uv, sampler.mag == Filter::Nearest);
  const bool nearest = sampler.min == Filter::Nearest;
  if (sampler.mip == MipMode::None) return sample_level(mips, 0, sampler, uv, nearest);
  const size_t top = mips.sizes.size() - 1;
  lod = std::min(lod, float(top));
  if (sampler.mip == MipMode::Nearest) return sample_level(mips, size_t(std::floor(lod + 0.5f)), sampler, uv, nearest);
  const float low = std::floor(lod);
  const size_t k = size_t(low);
  return glm::mix(sample_level(mips, k, sampler, uv, nearest),
                  sample_level(mips, std::min(k + 1, top), sampler, uv, nearest), lod - low);
}

glm::vec3 sample_texture(const TextureMips& mips, const TextureSampler& sampler, glm::vec2 uv, float lod) {
  return glm::vec3(sample_texture_rgba(mips, sampler, uv, lod));
}

float footprint_lod(float area_m2, float texels_per_m2) {
  const float texels = area_m2 * texels_per_m2;
  if (!(texels > 0.0f)) return -std::numeric_limits<float>::infinity();
  return 0.5f * std::log2(texels);
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
        const glm::vec4 v = t.width && t.height ? bilinear_bytes(t, uv) : glm::vec4(255.0f);
        for (int c = 0; c < 4; ++c)
          dst[(size_t(j) * out.size + i) * 4 + size_t(c)] = uint8_t(std::lround(std::clamp(v[c], 0.0f, 255.0f)));
      }
  }
  return out;
}

std::vector<uint8_t> downsample_rgba8(const uint8_t* src, uint32_t width, uint32_t height) {
  const uint32_t half_w = std::max(1u, width / 2), half_h = std::max(1u, height / 2);
  std::vector<uint8_t> out(size_t(half_w) * half_h * 4);
  auto encode = [](float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    const float e = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return uint8_t(std::lround(e * 255.0f));
  };
  for (uint32_t j = 0; j < half_h; ++j)
    for (uint32_t i = 0; i < half_w; ++i) {
      glm::vec4 sum(0.0f);
      for (uint32_t k = 0; k < 4; ++k) {
        const uint32_t x = std::min(width - 1, 2 * i + (k & 1)), y = std::min(height - 1, 2 * j + (k >> 1));
        const uint8_t* p = src + (size_t(y) * width + x) * 4;
        sum += glm::vec4(srgb_to_linear(p[0]), srgb_to_linear(p[1]), srgb_to_linear(p[2]), float(p[3]) / 255.0f);
      }
      sum *= 0.25f;
      uint8_t* q = out.data() + (size_t(j) * half_w + i) * 4;
      for (int c = 0; c < 3; ++c) q[c] = encode(sum[c]);
      q[3] = uint8_t(std::lround(std::clamp(sum[3], 0.0f, 1.0f) * 255.0f));
    }
  return out;
}

std::vector<uint8_t> downsample_layers(const std::vector<uint8_t>& rgba8, uint32_t size, uint32_t count) {
  const uint32_t half = std::max(1u, size / 2);
  std::vector<uint8_t> out;
  out.reserve(size_t(half) * half * 4 * count);
  for (uint32_t l = 0; l < count; ++l) {
    const std::vector<uint8_t> level = downsample_rgba8(rgba8.data() + size_t(l) * size * size * 4, size, size);
    out.insert(out.end(), level.begin(), level.end());
  }
  return out;
}

}  // namespace lintel::render
