// View validation and the clip-space convention the GPU pass copies.
#include <lintel/view.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace lintel {
namespace {

View basic_view() {
  View v;
  v.eye_world = {1.0f, 2.0f, 3.0f};
  v.target_world = {1.0f, 2.0f, -7.0f};
  return v;
}

TEST(View, DefaultAndBasicViewsAreValid) {
  EXPECT_TRUE(validate_view(View{}).ok());
  EXPECT_TRUE(validate_view(basic_view()).ok());
}

TEST(View, BadCamerasAreErrorsNotCrashes) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  auto expect_error = [](View v, const char* what) {
    const Status s = validate_view(v);
    EXPECT_FALSE(s.ok()) << what;
    EXPECT_FALSE(s.message().empty()) << what;
  };
  View v = basic_view();
  v.eye_world.x = nan;
  expect_error(v, "NaN eye");
  v = basic_view();
  v.eye_world.z = inf;
  expect_error(v, "Inf eye");
  v = basic_view();
  v.target_world.y = nan;
  expect_error(v, "NaN target");
  v = basic_view();
  v.target_world = v.eye_world;
  expect_error(v, "eye == target");
  v = basic_view();
  v.up_world = {0.0f, 0.0f, 1.0f};
  expect_error(v, "up parallel to the view");
  v = basic_view();
  v.up_world = {0.0f, 0.0f, 0.0f};
  expect_error(v, "zero up");
  v = basic_view();
  v.fov_y_deg = 0.0f;
  expect_error(v, "zero fov");
  v = basic_view();
  v.fov_y_deg = 180.0f;
  expect_error(v, "180 fov");
  v = basic_view();
  v.aspect = -1.0f;
  expect_error(v, "negative aspect");
  v = basic_view();
  v.near_m = 0.0f;
  expect_error(v, "zero near");
  v = basic_view();
  v.far_m = v.near_m;
  expect_error(v, "far == near");
  v = basic_view();
  v.far_m = inf;
  expect_error(v, "infinite far");
}

// Convention: z_clip = 0 on the near plane, z_clip = w on the far plane, NDC y up, x right.
TEST(View, ClipConventionIsVulkanDepthWithYUp) {
  const View v = basic_view();
  const glm::dmat4 vp = view_projection_d(v);
  const glm::dvec3 eye(v.eye_world);
  const glm::dvec3 fwd = view_forward_d(v);
  const glm::dvec4 on_near = vp * glm::dvec4(eye + fwd * double(v.near_m), 1.0);
  EXPECT_NEAR(on_near.z / on_near.w, 0.0, 1e-9);
  EXPECT_NEAR(on_near.w, double(v.near_m), 1e-9);
  const glm::dvec4 on_far = vp * glm::dvec4(eye + fwd * double(v.far_m), 1.0);
  EXPECT_NEAR(on_far.z / on_far.w, 1.0, 1e-9);
  const glm::dvec4 above = vp * glm::dvec4(eye + fwd * 5.0 + glm::dvec3(0, 1, 0), 1.0);
  EXPECT_GT(above.y / above.w, 0.0);
  // Right of the view: forward x up.
  const glm::dvec3 right = glm::cross(fwd, glm::dvec3(0, 1, 0));
  const glm::dvec4 to_right = vp * glm::dvec4(eye + fwd * 5.0 + right, 1.0);
  EXPECT_GT(to_right.x / to_right.w, 0.0);
  // The float matrix is the double one rounded.
  const glm::mat4 vpf = view_projection(v);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_EQ(vpf[c][r], float(vp[c][r]));
}

TEST(View, NearHalfExtentIsHalfDiagonalOfNearRect) {
  View v = basic_view();
  v.fov_y_deg = 90.0f;
  v.aspect = 1.0f;
  v.near_m = 0.1f;
  EXPECT_NEAR(near_half_extent(v), double(v.near_m) * std::sqrt(2.0), 1e-7);
}

}  // namespace
}  // namespace lintel
