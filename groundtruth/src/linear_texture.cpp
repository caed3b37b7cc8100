// sRGB decoding, the mip chain and the glTF sampler, in the order the GPU does them for an _SRGB
// image: each texel is decoded first, then texels are blended (Vulkan spec, "Texel Filtering":
// sRGB conversion happens on texel fetch, before filtering). Written from the Vulkan spec's
// wrapping and filtering rules, independently of the renderer's CPU copy (render/src/base_color.cpp).
#include <lintel/reference/linear_texture.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

namespace lintel::reference {
namespace {

using Wrap = TextureSampler::Wrap;

std::array<float, 256> make_srgb_table() {
  std::array<float, 256> table{};
  for (int i = 0; i < 256; ++i) {
    const double c = i / 255.0;
    table[size_t(i)] = float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
  }
  return table;
}

// Vulkan's wrap of an integer texel coordinate i into [0, n).
int64_t wrap_texel(int64_t i, int64_t n, Wrap mode) {
  if (mode == Wrap::ClampToEdge) return std::clamp<int64_t>(i, 0, n - 1);
  if (mode == Wrap::MirroredRepeat) {
    const int64_t m = ((i % (2 * n)) + 2 * n) % (2 * n);  // the mirrored pair of periods
    return m < n ? m : 2 * n - 1 - m;
  }
  return ((i % n) + n) % n;
}

// The same place in the texture, nearer 0: whole periods (two for a mirror) taken off, and a
// clamped coordinate kept just outside [0, 1]. Huge uvs then cannot overflow the texel index.
float near_zero(float u, Wrap mode) {
  if (!std::isfinite(u)) return 0.0f;
  if (mode == Wrap::Repeat) return u - std::floor(u);
  if (mode == Wrap::MirroredRepeat) return u - 2.0f * std::floor(u * 0.5f);
  return std::clamp(u, -1.0f, 2.0f);
}

// One channel (`texels`: colour or alpha) of a level.
template <class T>
T sample_level(const LinearTexture::Level& level, const std::vector<T>& texels, const TextureSampler& s, glm::vec2 uv,
               bool nearest) {
  const int64_t w = level.width, h = level.height;
  const auto at = [&](int64_t i, int64_t j) {
    return texels[size_t(wrap_texel(j, h, s.wrap_t)) * size_t(w) + size_t(wrap_texel(i, w, s.wrap_s))];
  };
  const float x = near_zero(uv.x, s.wrap_s) * float(w), y = near_zero(uv.y, s.wrap_t) * float(h);
  if (nearest) return at(int64_t(std::floor(x)), int64_t(std::floor(y)));
  // Texel centres at k + 0.5: the pair around x - 0.5 and the weight of the second.
  const float x0 = std::floor(x - 0.5f), y0 = std::floor(y - 0.5f);
  const float fx = x - 0.5f - x0, fy = y - 0.5f - y0;
  const auto i = int64_t(x0), j = int64_t(y0);
  const T top = glm::mix(at(i, j), at(i + 1, j), fx);
  const T bottom = glm::mix(at(i, j + 1), at(i + 1, j + 1), fx);
  return glm::mix(top, bottom, fy);
}

// The sampler's levels and filters at `lod` (sample_texture's rule in linear_texture.h), for the
// channel `member` of each level.
template <class T>
T sample_channel(const LinearTexture& texture, std::vector<T> LinearTexture::Level::*member,
                 const TextureSampler& sampler, glm::vec2 uv, float lod) {
  using Filter = TextureSampler::Filter;
  using MipMode = TextureSampler::MipMode;
  const auto level = [&](size_t k, bool nearest) {
    const LinearTexture::Level& l = texture.levels[k];
    return sample_level(l, l.*member, sampler, uv, nearest);
  };
  if (!(lod > 0.0f)) return level(0, sampler.mag == Filter::Nearest);
  const bool nearest = sampler.min == Filter::Nearest;
  if (sampler.mip == MipMode::None) return level(0, nearest);
  const size_t last = texture.levels.size() - 1;
  lod = std::min(lod, float(last));
  if (sampler.mip == MipMode::Nearest) return level(size_t(std::floor(lod + 0.5f)), nearest);
  const float below = std::floor(lod);
  const auto k = size_t(below);
  return glm::mix(level(k, nearest), level(std::min(k + 1, last), nearest), lod - below);
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
  LinearTexture::Level base;
  base.width = texture.width;
  base.height = texture.height;
  base.texels.resize(size_t(texture.width) * texture.height);
  base.alpha.resize(base.texels.size());
  for (size_t i = 0; i < base.texels.size(); ++i) {
    base.texels[i] = {srgb_to_linear(texture.rgba8[4 * i]), srgb_to_linear(texture.rgba8[4 * i + 1]),
                      srgb_to_linear(texture.rgba8[4 * i + 2])};
    base.alpha[i] = float(texture.rgba8[4 * i + 3]) / 255.0f;
  }
  out.levels.push_back(std::move(base));
  while (out.levels.back().width > 1 || out.levels.back().height > 1) {
    const LinearTexture::Level& above = out.levels.back();
    LinearTexture::Level next;
    next.width = std::max(1u, above.width / 2);
    next.height = std::max(1u, above.height / 2);
    next.texels.resize(size_t(next.width) * next.height);
    next.alpha.resize(next.texels.size());
    for (uint32_t j = 0; j < next.height; ++j)
      for (uint32_t i = 0; i < next.width; ++i) {
        glm::vec3 sum(0.0f);
        float alpha = 0.0f;
        for (uint32_t k = 0; k < 4; ++k) {
          const uint32_t x = std::min(above.width - 1, 2 * i + (k & 1)),
                         y = std::min(above.height - 1, 2 * j + (k >> 1));
          sum += above.texels[size_t(y) * above.width + x];
          alpha += above.alpha[size_t(y) * above.width + x];
        }
        next.texels[size_t(j) * next.width + i] = 0.25f * sum;
        next.alpha[size_t(j) * next.width + i] = 0.25f * alpha;
      }
    out.levels.push_back(std::move(next));
  }
  return out;
}

glm::vec3 sample_texture(const LinearTexture& texture, const TextureSampler& sampler, glm::vec2 uv, float lod) {
  return sample_channel(texture, &LinearTexture::Level::texels, sampler, uv, lod);
}

float sample_alpha(const LinearTexture& texture, const TextureSampler& sampler, glm::vec2 uv, float lod) {
  return sample_channel(texture, &LinearTexture::Level::alpha, sampler, uv, lod);
}

}  // namespace lintel::reference
