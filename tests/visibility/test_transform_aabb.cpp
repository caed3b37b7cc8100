// transform_aabb computes the box of a transformed box per row from the smaller and larger product
// of each column (world.cpp says why that is exact). The property: for any finite affine matrix and
// any box, the result equals, coordinate by coordinate, the box of the 8 corners transformed with
// glm's mat4 * vec4 -- the implementation it replaced -- so no culling decision can change.
#include <lintel/aabb.h>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <random>

namespace lintel {
namespace {

Aabb corners_reference(const glm::mat4& m, const Aabb& box) {
  Aabb out;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p{(corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                      (corner & 4) ? box.max.z : box.min.z};
    out.extend(glm::vec3(m * glm::vec4(p, 1.0f)));
  }
  return out;
}

// Matrices a game and a loader produce: rotations, mirrors, non-uniform scales, shears, exact
// zeros and translations from millimetres to 1e5 m; boxes from degenerate (a point) to large.
glm::mat4 random_affine(std::mt19937& rng) {
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::uniform_int_distribution<int> kind(0, 3), exponent(-3, 5);
  glm::mat4 m(1.0f);
  switch (kind(rng)) {
    case 0:  // rotation about a random axis, then a mirror on some axes
      m = glm::rotate(glm::mat4(1.0f), 3.2f * unit(rng),
                      glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)) + glm::vec3(1e-3f)));
      m = glm::scale(m, glm::vec3(unit(rng) < 0 ? -1.0f : 1.0f, 1.0f, unit(rng) < 0 ? -1.0f : 1.0f));
      break;
    case 1:  // general linear part (shear, non-uniform scale)
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) m[c][r] = 4.0f * unit(rng);
      break;
    case 2:  // axis-aligned with exact zeros
      m = glm::scale(glm::mat4(1.0f), glm::vec3(2.0f * unit(rng), 0.5f, -3.0f));
      break;
    default:  // identity linear part
      break;
  }
  const float t = std::pow(10.0f, float(exponent(rng)));
  m[3] = glm::vec4(t * unit(rng), t * unit(rng), t * unit(rng), 1.0f);
  return m;
}

TEST(TransformAabb, EqualsTheEightTransformedCornersOnEveryCoordinate) {
  std::mt19937 rng(20261125);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f), size(0.0f, 3.0f);
  for (int i = 0; i < 200000; ++i) {
    const glm::mat4 m = random_affine(rng);
    Aabb box;
    const glm::vec3 c(20.0f * unit(rng), 20.0f * unit(rng), 20.0f * unit(rng));
    const glm::vec3 half = (i % 10 == 0) ? glm::vec3(0.0f) : glm::vec3(size(rng), size(rng), size(rng));
    box.extend(c - half);
    box.extend(c + half);
    const Aabb fast = transform_aabb(m, box), ref = corners_reference(m, box);
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(fast.min[k], ref.min[k]) << "case " << i << " axis " << k;
      ASSERT_EQ(fast.max[k], ref.max[k]) << "case " << i << " axis " << k;
    }
  }
}

TEST(TransformAabb, EmptyStaysEmpty) {
  EXPECT_TRUE(transform_aabb(glm::mat4(1.0f), Aabb{}).empty());
  EXPECT_TRUE(transform_aabb(glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f)), Aabb{}).empty());
}

}  // namespace
}  // namespace lintel
