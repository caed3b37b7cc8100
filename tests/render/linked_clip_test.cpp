// Property (no GPU): the pyramids a linked view is clipped with (linked_pyramid, linked_draws.h)
// keep everything the eye sees through the portal and give up nothing it does not. Over random
// convex portals (3..8 corners, 0.3..2 m, any orientation, up to 50 m from the origin, and again up
// to 10 km away) and eyes 0.05..20 m off the portal's plane, evaluated in float as gbuffer.frag
// does, with m = linked_pyramid's margin (1 mm + 1e-6 x the coordinates' size):
//  * every point on a ray from the eye through the polygon's interior, 2m + 1 mm or more beyond
//    the plane, is inside the keep pyramid (nothing seen through the portal is clipped away);
//  * no point m + 1 cm or more outside the true pyramid (beside it, or before the plane) is inside
//    the cut pyramid (the view it is seen from gives up only what the portal shows);
//  * every point of the cut pyramid 3m or more beyond the plane is inside the keep pyramid (no
//    crack between the two);
//  * an eye within the margin of the plane gets no pyramid (the portal is seen edge-on).
// And ndc_rect_to_pixels covers every pixel centre whose NDC lies in the rect.
#include "linked_draws.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace lintel::render {
namespace {

constexpr float kPi = 3.14159265358979f;

bool inside(const std::vector<glm::vec4>& run, const glm::vec3& p) {
  const uint32_t n = pyramid_planes(run[0]);
  for (uint32_t i = 1; i <= n; ++i)
    if (glm::dot(glm::vec3(run[i]), p) + run[i].w < 0.0f) return false;
  return true;
}

struct Case {
  std::vector<glm::dvec3> polygon;
  glm::dvec3 centre, normal, eye;
};

// `reach`: the portal's centre lies up to this far from the origin along each axis.
Case random_case(std::mt19937_64& rng, double reach = 50.0) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Case c;
  c.centre = (glm::dvec3(u(rng), u(rng), u(rng)) * 2.0 - 1.0) * reach;
  c.normal = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)) * 2.0 - 1.0);
  const glm::dvec3 a =
      glm::normalize(glm::cross(c.normal, std::abs(c.normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
  const glm::dvec3 b = glm::cross(c.normal, a);
  const int n = 3 + int(u(rng) * 6.0);
  const double radius = 0.3 + 1.7 * u(rng), turn = 2.0 * kPi * u(rng);
  for (int k = 0; k < n; ++k) {
    const double angle = turn + 2.0 * kPi * k / n;
    c.polygon.push_back(c.centre + radius * (std::cos(angle) * a + std::sin(angle) * b));
  }
  const double off = (u(rng) < 0.5 ? -1.0 : 1.0) * (0.05 + 19.95 * u(rng) * u(rng));
  c.eye = c.centre + off * c.normal + (u(rng) * 2.0 - 1.0) * 3.0 * a + (u(rng) * 2.0 - 1.0) * 3.0 * b;
  return c;
}

// A random point inside the polygon (a fan triangle, barycentric), `inset` of the way to the centre.
glm::dvec3 interior_point(const Case& c, std::mt19937_64& rng, double inset) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const size_t k = size_t(u(rng) * double(c.polygon.size())) % c.polygon.size();
  double s = u(rng), t = u(rng);
  if (s + t > 1.0) {
    s = 1.0 - s;
    t = 1.0 - t;
  }
  const glm::dvec3 p =
      c.centre + s * (c.polygon[k] - c.centre) + t * (c.polygon[(k + 1) % c.polygon.size()] - c.centre);
  return glm::mix(p, c.centre, inset);
}

void check_pyramids(uint64_t seed, double reach) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int cases = 0, kept = 0, outside_checked = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Case c = random_case(rng, reach);
    // linked_pyramid's margin (linked_draws.h): 1 mm plus what float loses at these coordinates.
    const double m = 1e-3 + 1e-6 * (glm::length(c.centre) + glm::length(c.eye));
    std::vector<glm::vec4> keep, cut;
    ASSERT_TRUE(linked_pyramid(c.polygon, c.eye, keep, cut)) << "trial " << trial;
    ++cases;
    const double plane_d = -glm::dot(c.normal, c.centre);
    const double eye_side = glm::dot(c.normal, c.eye) + plane_d;
    const glm::dvec3 away = eye_side > 0.0 ? -c.normal : c.normal;  // the far side
    for (int k = 0; k < 50; ++k) {
      // Seen through the portal: from the eye through an interior point, 2m + 1 mm to 10 m beyond.
      const glm::dvec3 q = interior_point(c, rng, 0.0);
      const glm::dvec3 ray = glm::normalize(q - c.eye);
      const double beyond = 2.0 * m + 0.001 + 10.0 * u(rng) * u(rng);
      const glm::dvec3 p = q + ray * (beyond / std::abs(glm::dot(ray, away)));
      ASSERT_TRUE(inside(keep, glm::vec3(p))) << "trial " << trial << ": a point seen through the portal is clipped";
      ++kept;
      // Before the plane by m + 1 cm or more: never cut.
      const glm::dvec3 before = q - ray * ((m + 0.01 + 5.0 * u(rng)) / std::abs(glm::dot(ray, away)));
      ASSERT_FALSE(inside(cut, glm::vec3(before))) << "trial " << trial << ": a point before the portal is cut";
      // Beside the pyramid: through a point in the plane m + 1 cm or more outside the polygon's
      // circumcircle, pushed beyond the plane along the ray from the eye.
      const glm::dvec3 a = glm::normalize(c.polygon[0] - c.centre), b = glm::cross(c.normal, a);
      const double angle = 2.0 * kPi * u(rng);
      const glm::dvec3 dir_out = std::cos(angle) * a + std::sin(angle) * b;
      const double circum = glm::length(c.polygon[0] - c.centre);
      const glm::dvec3 far_in_plane = c.centre + dir_out * (circum + m + 0.01 + u(rng));
      const glm::dvec3 ray_out = glm::normalize(far_in_plane - c.eye);
      const glm::dvec3 beside = far_in_plane + ray_out * ((0.01 + 5.0 * u(rng)) / std::abs(glm::dot(ray_out, away)));
      ASSERT_FALSE(inside(cut, glm::vec3(beside))) << "trial " << trial << ": a point beside the portal is cut";
      ++outside_checked;
    }
    // Beyond the plane, the cut pyramid lies inside the keep pyramid: random points near the
    // portal. (Within the margin of the plane they differ on purpose: the wall face on the plane
    // is cut from the view it hangs in, and not drawn again, reflected, by the linked view.)
    for (int k = 0; k < 50; ++k) {
      const glm::dvec3 p = c.centre + (glm::dvec3(u(rng), u(rng), u(rng)) * 2.0 - 1.0) * 4.0;
      if (glm::dot(p - c.centre, away) < 3.0 * m || !inside(cut, glm::vec3(p))) continue;
      ASSERT_TRUE(inside(keep, glm::vec3(p))) << "trial " << trial << ": a crack between the pyramids";
    }
  }
  std::printf("%d portals up to %.0f m out: %d points seen through them kept, %d beside or before them not cut\n",
              cases, reach, kept, outside_checked);
}

TEST(LinkedClip, PyramidsKeepWhatThePortalShowsAndCutNothingElse) { check_pyramids(7, 50.0); }

// The same far from the origin, where float rounding of the planes is millimetres.
TEST(LinkedClip, PyramidsHoldTenKilometresOut) { check_pyramids(8, 1e4); }

TEST(LinkedClip, AnEyeOnThePlaneGetsNoPyramid) {
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 200; ++trial) {
    Case c = random_case(rng);
    c.eye -= c.normal * (glm::dot(c.normal, c.eye - c.centre) - 0.0005);  // 0.5 mm off the plane
    std::vector<glm::vec4> keep, cut;
    EXPECT_FALSE(linked_pyramid(c.polygon, c.eye, keep, cut)) << "trial " << trial;
    EXPECT_TRUE(keep.empty() && cut.empty());
  }
}

TEST(LinkedClip, PixelRectCoversEveryPixelCentreInTheNdcRect) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  const uint32_t w = 160, h = 90;
  for (int trial = 0; trial < 500; ++trial) {
    NdcRect r;
    r.extend({u(rng), u(rng)});
    r.extend({u(rng), u(rng)});
    const glm::vec4 px = ndc_rect_to_pixels(r, w, h);
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x) {
        // Pixel centre (x + 0.5, y + 0.5) in framebuffer space, row 0 at the top (flipped viewport).
        const float nx = (float(x) + 0.5f) / float(w) * 2.0f - 1.0f, ny = 1.0f - (float(y) + 0.5f) / float(h) * 2.0f;
        if (nx < r.min.x || nx > r.max.x || ny < r.min.y || ny > r.max.y) continue;
        const float fx = float(x) + 0.5f, fy = float(y) + 0.5f;
        ASSERT_TRUE(fx >= px.x && fx <= px.z && fy >= px.y && fy <= px.w) << "trial " << trial;
      }
  }
}

}  // namespace
}  // namespace lintel::render
