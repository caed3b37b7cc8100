// The ground truth's rim rule (ray_ground_truth.h): rays within the scene's float error of a
// portal edge are not judged, and only those. A hand-built world: cell 0 owns a 4 x 4 m wall at
// z = -5 with a 1 x 1 m hole, portal 0 fills the hole, cell 1 owns a wall at z = -10.
#include <lintel/reference/ray_ground_truth.h>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

namespace lintel {
namespace {

// `offset`: both cell frames sit this far from the geometry (the vertices compensate), as the
// random generator's frames do; the world-space geometry is the same for every offset.
World wall_with_portal(float offset) {
  World w;
  Mesh frame;
  auto quad = [&frame](float x0, float y0, float x1, float y1, float z) {
    const uint32_t b = static_cast<uint32_t>(frame.positions.size());
    frame.positions.insert(frame.positions.end(), {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}});
    frame.indices.insert(frame.indices.end(), {b, b + 1, b + 2, b, b + 2, b + 3});
  };
  quad(-2, -2, 2, -0.5f, -5);
  quad(-2, 0.5f, 2, 2, -5);
  quad(-2, -0.5f, -0.5f, 0.5f, -5);
  quad(0.5f, -0.5f, 2, 0.5f, -5);
  Mesh far_wall;
  std::swap(frame, far_wall);
  quad(-20, -20, 20, 20, -10);
  std::swap(frame, far_wall);
  for (Mesh* m : {&frame, &far_wall}) {
    for (glm::vec3& p : m->positions) p.x -= offset;
    for (const glm::vec3& p : m->positions) m->bounds_mesh.extend(p);
  }
  w.meshes = {frame, far_wall};
  w.cells.resize(2);
  for (uint32_t c = 0; c < 2; ++c) {
    w.cells[c].name = c ? "far" : "near";
    w.cells[c].shell_mesh = int(c);
    w.cells[c].cell_to_world = glm::translate(glm::mat4(1.0f), glm::vec3(offset, 0.0f, 0.0f));
  }
  Portal p;
  p.from = 0;
  p.to = 1;
  p.polygon_world = {{-0.5f, -0.5f, -5}, {0.5f, -0.5f, -5}, {0.5f, 0.5f, -5}, {-0.5f, 0.5f, -5}};
  p.normal_world = {0, 0, -1};
  p.plane_d_world = 5.0f;
  w.portals = {p};
  return w;
}

TEST(RimRule, FloatErrorGrowsWithTheFramesDistance) {
  std::vector<double> per_cell;
  const double near_origin = scene_float_error_m(wall_with_portal(0.0f), &per_cell);
  ASSERT_EQ(per_cell.size(), 2u);
  EXPECT_GT(near_origin, 0.0);
  EXPECT_LT(near_origin, 2e-5);  // 4 half-ulps of 50 m (sum_i |column_i| max |p_i|)
  const double far = scene_float_error_m(wall_with_portal(1e4f));
  EXPECT_GT(far, 1e-3);  // 4 half-ulps of 2e4 m (|t| + max |p_x|): 4.8 mm
  EXPECT_LT(far, 1e-2);
}

TEST(RimRule, OnlyRaysNearAnEdgeAreRimRays) {
  for (float offset : {0.0f, 1e4f}) {
    const World w = wall_with_portal(offset);
    RayGroundTruth rt;
    ASSERT_TRUE(rt.build(w).ok());
    const double r = rt.rim_radius_m(0);
    EXPECT_DOUBLE_EQ(r, scene_float_error_m(w));
    const glm::vec3 eye(0.0f, 0.1f, 0.0f);
    auto toward = [&](float x) { return glm::vec3(x, 0.0f, -5.0f) - eye; };
    // At the edge x = 0.5 and within r of it (inside or outside the hole): a rim ray.
    EXPECT_TRUE(rt.passes_portal_rim(eye, toward(0.5f), 0.0f, 100.0f)) << offset;
    EXPECT_TRUE(rt.passes_portal_rim(eye, toward(float(0.5 - 0.5 * r)), 0.0f, 100.0f)) << offset;
    EXPECT_TRUE(rt.passes_portal_rim(eye, toward(float(0.5 + 0.5 * r)), 0.0f, 100.0f)) << offset;
    // Farther than sqrt(2) r (the box's corner), through the hole or onto the wall: judged.
    EXPECT_FALSE(rt.passes_portal_rim(eye, toward(float(0.5 - 2.0 * r)), 0.0f, 100.0f)) << offset;
    EXPECT_FALSE(rt.passes_portal_rim(eye, toward(float(0.5 + 2.0 * r)), 0.0f, 100.0f)) << offset;
    // Only up to t_max: a ray stopped before the portal never reaches the rim.
    EXPECT_FALSE(rt.passes_portal_rim(eye, toward(0.5f), 0.0f, 0.5f)) << offset;
  }
}

TEST(RimRule, GridJudgesTheOpeningAndReportsWhatOnlyRimRaysSaw) {
  const World w = wall_with_portal(0.0f);
  RayGroundTruth rt;
  ASSERT_TRUE(rt.build(w).ok());
  GroundTruth gt;
  RayCamera cam;
  cam.eye_world = {0, 0, 0};
  cam.target_world = {0, 0, -1};
  cam.aspect = 1.0f;
  cam.fov_y_deg = 40.0f;
  rt.cast(cam, 64, gt);
  // The hole spans many pixels: the far cell is judged visible; a 12 um band around the rim
  // holds few if any pixel centres.
  EXPECT_TRUE(gt.cell_visible[1]);
  EXPECT_EQ(gt.past_rim_cell_visible[1], 0u);
  EXPECT_LT(gt.rim_pixels, 64u);
  // Looking straight at the edge x = 0.5 through a tiny field of view: every ray passes the rim,
  // none is judged, and the cells behind it are reported as seen only past a rim.
  cam.eye_world = {0.5f, 0.0f, 0.0f};
  cam.target_world = {0.5f, 0.0f, -5.0f};
  cam.fov_y_deg = 1e-4f;
  rt.cast(cam, 4, gt);
  EXPECT_EQ(gt.rim_pixels, 16u);
  EXPECT_FALSE(gt.cell_visible[0] || gt.cell_visible[1]);
  EXPECT_TRUE(gt.past_rim_cell_visible[0] || gt.past_rim_cell_visible[1]);
}

}  // namespace
}  // namespace lintel
