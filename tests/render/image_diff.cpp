// Per-channel image differences for the golden test.
#include "image_diff.h"

#include <algorithm>
#include <cstdlib>

namespace lintel::render::test {

ImageDiff diff_images(const Rgba8Image& a, const Rgba8Image& b, uint32_t threshold) {
  ImageDiff d;
  d.same_size = a.width == b.width && a.height == b.height && a.pixels.size() == b.pixels.size() &&
                a.pixels.size() == size_t(a.width) * a.height * 4;
  if (!d.same_size || a.pixels.empty()) return d;
  const size_t pixels = size_t(a.width) * a.height;
  uint64_t sum = 0;
  for (size_t p = 0; p < pixels; ++p) {
    uint32_t worst = 0;
    for (size_t c = 0; c < 3; ++c) {
      const uint32_t e = uint32_t(std::abs(int(a.pixels[4 * p + c]) - int(b.pixels[4 * p + c])));
      sum += e;
      worst = std::max(worst, e);
    }
    d.max_abs = std::max(d.max_abs, worst);
    d.pixels_over += worst > threshold;
  }
  d.mean_abs = double(sum) / double(3 * pixels);
  d.share_over = double(d.pixels_over) / double(pixels);
  return d;
}

}  // namespace lintel::render::test
