// The CPU mip path (downsample_layers, used where the device cannot blit the texture format):
// a level averages its 2x2 texels in linear light, layer by layer. No GPU.
#include "base_color.h"

#include <gtest/gtest.h>

namespace lintel::render {
namespace {

std::vector<uint8_t> layer_of(uint32_t size, uint8_t (*texel)(uint32_t, uint32_t)) {
  std::vector<uint8_t> out(size_t(size) * size * 4);
  for (uint32_t j = 0; j < size; ++j)
    for (uint32_t i = 0; i < size; ++i) {
      uint8_t* p = &out[(size_t(j) * size + i) * 4];
      p[0] = p[1] = p[2] = texel(i, j);
      p[3] = 255;
    }
  return out;
}

TEST(TextureMips, CheckerAveragesInLinearLight) {
  // Black and white texels average to linear 0.5, sRGB 188 (not 128, the mean of the bytes).
  const std::vector<uint8_t> checker =
      layer_of(8, [](uint32_t i, uint32_t j) -> uint8_t { return (i + j) % 2 ? 255 : 0; });
  const std::vector<uint8_t> next = downsample_layers(checker, 8, 1);
  ASSERT_EQ(next.size(), size_t(4 * 4 * 4));
  for (size_t p = 0; p < next.size(); p += 4) {
    EXPECT_EQ(next[p], 188);
    EXPECT_EQ(next[p + 3], 255);
  }
}

TEST(TextureMips, LayersStaySeparateAndFlatLayersKeepTheirValue) {
  std::vector<uint8_t> two = layer_of(5, [](uint32_t, uint32_t) -> uint8_t { return 77; });
  const std::vector<uint8_t> white = layer_of(5, [](uint32_t, uint32_t) -> uint8_t { return 255; });
  two.insert(two.end(), white.begin(), white.end());
  const std::vector<uint8_t> next = downsample_layers(two, 5, 2);  // odd side: 5 -> 2
  ASSERT_EQ(next.size(), size_t(2 * 2 * 4 * 2));
  for (size_t p = 0; p < 16; p += 4) EXPECT_EQ(next[p], 77);
  for (size_t p = 16; p < 32; p += 4) EXPECT_EQ(next[p], 255);
  EXPECT_EQ(downsample_layers(layer_of(1, [](uint32_t, uint32_t) -> uint8_t { return 9; }), 1, 1).size(), 4u);
}

}  // namespace
}  // namespace lintel::render
