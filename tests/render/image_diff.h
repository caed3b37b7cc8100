// How far a rendered frame is from its golden image: the mean absolute difference per channel
// and the share of pixels where some channel differs by more than a threshold (both in 8-bit
// steps, alpha ignored). The golden test's tolerance is stated in these two numbers.
#pragma once

#include <lintel/render/image_io.h>

#include <cstdint>

namespace lintel::render::test {

struct ImageDiff {
  bool same_size = false;
  double mean_abs = 0.0;    // mean |a - b| over the rgb channels of every pixel, in 1/255 steps
  double share_over = 0.0;  // share of pixels (0..1) with some rgb |a - b| > threshold
  uint32_t pixels_over = 0;
  uint32_t max_abs = 0;  // largest rgb |a - b|
};

ImageDiff diff_images(const Rgba8Image& a, const Rgba8Image& b, uint32_t threshold);

}  // namespace lintel::render::test
