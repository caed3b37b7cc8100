// FLIP (pathtrace/src/image_flip.cpp) on image pairs whose ordering follows from the metric's
// definition: identical images score 0, larger differences score more, a shifted edge scores
// more the further it moved, and detail finer than the eye resolves at the viewing distance
// counts less than the same contrast at a coarse scale (the contrast sensitivity filters).
#include <lintel/reference/image_flip.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace lintel {
namespace {

constexpr uint32_t kW = 96, kH = 64;

std::vector<glm::vec3> flat(glm::vec3 c) { return std::vector<glm::vec3>(size_t(kW) * kH, c); }

std::vector<glm::vec3> random_image(uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<glm::vec3> img(size_t(kW) * kH);
  for (glm::vec3& c : img) c = glm::vec3(u(rng), u(rng), u(rng));
  return img;
}

// A bright square on a dark ground, its left edge at column `left`.
std::vector<glm::vec3> square(int left) {
  std::vector<glm::vec3> img = flat(glm::vec3(0.1f));
  for (int y = 16; y < 48; ++y)
    for (int x = left; x < left + 32; ++x) img[size_t(y) * kW + size_t(x)] = glm::vec3(0.9f, 0.8f, 0.7f);
  return img;
}

// Black/white checker of `cell`-pixel squares, and the flat grey of the same mean linear radiance.
std::vector<glm::vec3> checker(uint32_t cell) {
  std::vector<glm::vec3> img(size_t(kW) * kH);
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x) img[size_t(y) * kW + x] = glm::vec3(float((x / cell + y / cell) % 2));
  return img;
}
const glm::vec3 kMeanGreySrgb(0.7354f);  // linear 0.5 encoded

TEST(ImageFlip, IdenticalImagesScoreZero) {
  for (uint32_t seed : {1u, 2u, 3u}) {
    const std::vector<glm::vec3> img = random_image(seed);
    std::vector<float> map;
    EXPECT_EQ(flip_ldr(img, img, kW, kH, {}, &map), 0.0);
    for (float e : map) ASSERT_EQ(e, 0.0f);
  }
}

// Property: every per-pixel error lies in [0, 1], and the metric is symmetric (both of its
// differences, HyAB and the feature magnitudes, are symmetric in the two images).
TEST(ImageFlip, BoundedAndSymmetric) {
  for (uint32_t seed : {4u, 5u}) {
    const std::vector<glm::vec3> a = random_image(seed), b = random_image(seed + 100);
    std::vector<float> map;
    const double ab = flip_ldr(a, b, kW, kH, {}, &map), ba = flip_ldr(b, a, kW, kH);
    EXPECT_NEAR(ab, ba, 1e-12);
    EXPECT_GT(ab, 0.0);
    for (float e : map) {
      ASSERT_GE(e, 0.0f);
      ASSERT_LE(e, 1.0f);
    }
  }
}

TEST(ImageFlip, LargerColourShiftScoresMore) {
  const std::vector<glm::vec3> ref = flat(glm::vec3(0.5f, 0.4f, 0.3f));
  double previous = 0.0;
  for (float d : {0.01f, 0.03f, 0.1f, 0.3f}) {
    const double e = flip_ldr(ref, flat(glm::vec3(0.5f + d, 0.4f, 0.3f - d)), kW, kH);
    EXPECT_GT(e, previous) << "shift " << d;
    previous = e;
  }
  // Black against white: a lightness difference of 100 lands in the compressed top of the range.
  EXPECT_GT(flip_ldr(flat(glm::vec3(0.0f)), flat(glm::vec3(1.0f)), kW, kH), 0.95);
}

TEST(ImageFlip, FurtherMovedEdgeScoresMore) {
  const std::vector<glm::vec3> ref = square(30);
  const double one = flip_ldr(ref, square(31), kW, kH), three = flip_ldr(ref, square(33), kW, kH);
  EXPECT_GT(one, 0.0);
  EXPECT_GT(three, one);
  // The error sits where the edge moved: the square's interior and the far ground are untouched.
  std::vector<float> map;
  flip_ldr(ref, square(33), kW, kH, {}, &map);
  EXPECT_GT(map[size_t(32) * kW + 31], 0.5f);
  EXPECT_LT(map[size_t(32) * kW + 50], 0.01f);
  EXPECT_LT(map[size_t(32) * kW + 90], 0.01f);
}

TEST(ImageFlip, DetailBelowTheEyesResolutionCountsLess) {
  // At the default 67 pixels per degree a 1-pixel checker is near the limit of vision; an
  // 8-pixel one is not. Against the flat grey of the same mean, the fine one must score far less.
  const double fine = flip_ldr(flat(kMeanGreySrgb), checker(1), kW, kH);
  const double coarse = flip_ldr(flat(kMeanGreySrgb), checker(8), kW, kH);
  EXPECT_LT(fine, 0.5 * coarse) << "fine " << fine << " coarse " << coarse;
  // Seen from much closer (fewer pixels per degree), the fine checker becomes visible.
  FlipOptions close;
  close.pixels_per_degree = 8.0f;
  EXPECT_GT(flip_ldr(flat(kMeanGreySrgb), checker(1), kW, kH, close), fine);
}

TEST(ImageFlip, TonemapMatchesTheRenderersCurve) {
  // Linear 0 stays black, large radiance saturates to white, and the middle is monotonic.
  const std::vector<glm::vec3> out =
      tonemap_for_flip({glm::vec3(0.0f), glm::vec3(0.18f), glm::vec3(0.5f), glm::vec3(100.0f)}, 1.0f);
  EXPECT_EQ(out[0].r, 0.0f);
  EXPECT_LT(out[1].r, out[2].r);
  EXPECT_NEAR(out[3].r, 1.0f, 1e-3f);
  // key_exposure maps the log-average of the non-black pixels to 0.18.
  EXPECT_NEAR(key_exposure({glm::vec3(0.0f), glm::vec3(0.09f), glm::vec3(0.36f)}), 0.18f / 0.18f, 1e-4f);
}

}  // namespace
}  // namespace lintel
