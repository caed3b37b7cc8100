// The camera a visibility query is asked from, and the one clip-space convention every Lintel
// layer shares (the CPU traversal here, the GPU cull pass later copies view_projection()).
//
// Clip convention (Vulkan depth range, GL y):
//   * view space is right-handed, the camera looks down -Z, +Y is up;
//   * clip = view_projection(view) * (p_world, 1) with -w <= x <= w, -w <= y <= w, 0 <= z <= w
//     (z = 0 on the near plane, z = w on the far plane: glm::perspectiveRH_ZO);
//   * NDC = clip.xy / clip.w, x right, y UP, both in [-1, 1]. A Vulkan renderer draws with a
//     negative viewport height (core since 1.1) so that NDC y up lands on screen y up.
// Inside the visible region, z >= 0 implies w >= near > 0, so the divide after the near clip is safe.
#pragma once

#include <lintel/status.h>

#include <glm/glm.hpp>

namespace lintel {

struct View {
  glm::vec3 eye_world{0.0f, 0.0f, 0.0f};      // meters
  glm::vec3 target_world{0.0f, 0.0f, -1.0f};  // a point looked at; must differ from the eye
  glm::vec3 up_world{0.0f, 1.0f, 0.0f};       // need not be unit, must not be parallel to the view
  float fov_y_deg = 70.0f;                    // vertical field of view, (0, 179]
  float aspect = 16.0f / 9.0f;                // width / height, (0, 1e4]
  float near_m = 0.05f;                       // distance of the near plane, > 0
  float far_m = 1000.0f;                      // distance of the far plane, > near_m
};

// Bad cameras are data, not programming errors: NaN/Inf anywhere, eye == target (closer than
// 1e-6 m), up parallel to the view direction, fov/aspect/near/far out of range. Never asserts.
Status validate_view(const View& view);

// World -> clip matrix in the convention above. Precondition: validate_view(view).ok().
// The double version is what the CPU traversal and the CPU culling reference use; the float one
// is what a GPU pass uploads (the same matrix rounded to float).
glm::dmat4 view_projection_d(const View& view);
glm::mat4 view_projection(const View& view);
// Its two factors: view_projection_d(view) == view_to_clip_d(view) * world_to_view_d(view), bit for
// bit. The first depends on the lens alone (fov, aspect, near, far), so a caller whose lens stays
// the same from frame to frame can keep it and skip the trigonometry (VisibilityBuilder does).
glm::dmat4 view_to_clip_d(const View& view);
glm::dmat4 world_to_view_d(const View& view);

// Unit view direction (target - eye), in world space.
glm::dvec3 view_forward_d(const View& view);

// Half-diagonal of the near-plane rectangle in meters: near * tan(fov_y / 2) * sqrt(1 + aspect^2).
// The doorway rule expands portal polygons by this much (docs/visibility.md).
double near_half_extent(const View& view);

}  // namespace lintel
