// The ground truth must itself be right before it can judge anything: rays hit the nearest
// surface, map back to the right cell and instance, start at the near plane, and see through
// openings exactly where there is no wall (or a cut-out's uncovered texels).
#include <lintel/reference/ray_ground_truth.h>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

namespace lintel {
namespace {

// Two triangles spanning the square [-h, h]^2 at z = z0 (mesh space).
Mesh square_mesh(float h, float z0) {
  Mesh m;
  m.positions = {{-h, -h, z0}, {h, -h, z0}, {h, h, z0}, {-h, h, z0}};
  m.indices = {0, 1, 2, 0, 2, 3};
  for (const glm::vec3& p : m.positions) m.bounds_mesh.extend(p);
  return m;
}

// Cell 0 "near" owns a wall at z = -5 with a 1 x 1 m hole (a frame of 4 quads); cell 1 "far"
// owns a wall at z = -10; an instance of a small square sits at z = -3 in cell 0.
World two_walls() {
  World w;
  Mesh frame;  // 4 quads around a 1 x 1 hole in a 4 x 4 wall at z = -5
  auto quad = [&frame](float x0, float y0, float x1, float y1) {
    const uint32_t b = static_cast<uint32_t>(frame.positions.size());
    frame.positions.insert(frame.positions.end(), {{x0, y0, -5}, {x1, y0, -5}, {x1, y1, -5}, {x0, y1, -5}});
    frame.indices.insert(frame.indices.end(), {b, b + 1, b + 2, b, b + 2, b + 3});
  };
  quad(-2, -2, 2, -0.5f);
  quad(-2, 0.5f, 2, 2);
  quad(-2, -0.5f, -0.5f, 0.5f);
  quad(0.5f, -0.5f, 2, 0.5f);
  for (const glm::vec3& p : frame.positions) frame.bounds_mesh.extend(p);
  w.meshes = {frame, square_mesh(20.0f, -10.0f), square_mesh(0.2f, 0.0f)};
  Cell near_cell, far_cell;
  near_cell.name = "near";
  near_cell.shell_mesh = 0;
  far_cell.name = "far";
  far_cell.shell_mesh = 1;
  // The far cell's frame is moved 1 m down; its mesh is lifted 1 m to compensate, so the wall
  // stays at z = -10 in world space and the hit must still map back to cell 1.
  far_cell.cell_to_world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -1.0f, 0.0f));
  for (glm::vec3& p : w.meshes[1].positions) p.y += 1.0f;
  w.cells = {near_cell, far_cell};
  Instance inst;
  inst.cell = 0;
  inst.mesh = 2;
  inst.mesh_to_world = glm::translate(glm::mat4(1.0f), glm::vec3(0.8f, 0.0f, -3.0f));
  w.instances = {inst};
  return w;
}

TEST(RayGroundTruth, PixelCentresAreSymmetricAndYUp) {
  EXPECT_FLOAT_EQ(pixel_center_ndc(0, 0, 2).x, -0.5f);
  EXPECT_FLOAT_EQ(pixel_center_ndc(0, 0, 2).y, 0.5f);  // row 0 is the top row
  EXPECT_FLOAT_EQ(pixel_center_ndc(1, 1, 2).x, 0.5f);
  EXPECT_FLOAT_EQ(pixel_center_ndc(1, 1, 2).y, -0.5f);
}

TEST(RayGroundTruth, SeesThroughTheHoleOnlyWhereThereIsNoWall) {
  const World w = two_walls();
  RayGroundTruth rt;
  ASSERT_TRUE(rt.build(w).ok());
  // Straight through the hole: the far wall.
  RayHitId through = rt.cast_ray({0, 0, 0}, {0, 0, -1}, 0.0f, 100.0f);
  EXPECT_EQ(through.cell, 1u);
  EXPECT_EQ(through.instance, RayHitId::kNone);
  // Beside the hole: the near wall.
  RayHitId blocked = rt.cast_ray({0, 1.0f, 0}, {0, 0, -1}, 0.0f, 100.0f);
  EXPECT_EQ(blocked.cell, 0u);
  // The instance in front of the wall wins over the wall behind it.
  RayHitId object = rt.cast_ray({0.8f, 0, 0}, {0, 0, -1}, 0.0f, 100.0f);
  EXPECT_EQ(object.cell, 0u);
  EXPECT_EQ(object.instance, 0u);
  // Nothing behind the eye.
  EXPECT_EQ(rt.cast_ray({0, 0, 0}, {0, 0, 1}, 0.0f, 100.0f).cell, RayHitId::kNone);
}

TEST(RayGroundTruth, ShellsSeenFromBehindBlockAndSeeNothingInstancesAreTwoSided) {
  const World w = two_walls();
  RayGroundTruth rt;
  ASSERT_TRUE(rt.build(w).ok());
  bool blocked = false;
  // From behind the near cell's wall (z = -7, looking back at it): blocked, nothing seen.
  EXPECT_EQ(rt.cast_ray({0, 1.0f, -7.0f}, {0, 0, 1}, 0.0f, 100.0f, &blocked).cell, RayHitId::kNone);
  EXPECT_TRUE(blocked);
  // From behind the far wall (z = -12): blocked too, even though the near wall lies beyond it.
  EXPECT_EQ(rt.cast_ray({0, 1.0f, -12.0f}, {0, 0, 1}, 0.0f, 100.0f, &blocked).cell, RayHitId::kNone);
  EXPECT_TRUE(blocked);
  // From the front the same wall is seen and nothing is blocked.
  EXPECT_EQ(rt.cast_ray({0, 1.0f, 0.0f}, {0, 0, -1}, 0.0f, 100.0f, &blocked).cell, 0u);
  EXPECT_FALSE(blocked);
  // An instance is hit from behind as well.
  RayHitId back = rt.cast_ray({0.8f, 0, -4.0f}, {0, 0, 1}, 0.0f, 100.0f);
  EXPECT_EQ(back.instance, 0u);
}

// Property: cut-outs (alphaMode MASK) are surface only where covered. The near wall gets a
// texture whose left texel is covered (alpha 255) and right one not (alpha 0), nearest, over
// uv = ((x + 2) / 4, (y + 2) / 4); the instance a base colour alpha below its cutoff. Rays beside
// the hole see the near wall on the left and the far wall on the right; the ray at the instance
// passes it and the wall's uncovered half. A ground truth that took them as solid would report
// the far cell unseen where a viewer sees it through the cut-out.
TEST(RayGroundTruth, SeesThroughCutOutsWhereTheyAreUncovered) {
  World w = two_walls();
  Texture half;
  half.name = "left covered";
  half.width = 2;
  half.height = 1;
  half.rgba8 = {200, 200, 200, 255, 200, 200, 200, 0};
  w.textures = {half};
  Mesh& wall = w.meshes[0];
  for (const glm::vec3& p : wall.positions) wall.uvs.emplace_back((p.x + 2.0f) / 4.0f, (p.y + 2.0f) / 4.0f);
  wall.base_color_texture = 0;
  wall.base_color_sampler.mag = wall.base_color_sampler.min = TextureSampler::Filter::Nearest;
  wall.base_color_sampler.wrap_s = wall.base_color_sampler.wrap_t = TextureSampler::Wrap::ClampToEdge;
  wall.alpha_mode = Mesh::AlphaMode::Mask;
  Mesh& square = w.meshes[2];
  square.alpha_mode = Mesh::AlphaMode::Mask;
  square.base_color.a = 0.3f;
  RayGroundTruth rt;
  ASSERT_TRUE(rt.build(w).ok());
  EXPECT_EQ(rt.cast_ray({-1.0f, 1.0f, 0}, {0, 0, -1}, 0.0f, 100.0f).cell, 0u) << "covered: the near wall";
  EXPECT_EQ(rt.cast_ray({1.0f, 1.0f, 0}, {0, 0, -1}, 0.0f, 100.0f).cell, 1u) << "uncovered: the far wall";
  const RayHitId past = rt.cast_ray({0.8f, 0, 0}, {0, 0, -1}, 0.0f, 100.0f);
  EXPECT_EQ(past.instance, RayHitId::kNone) << "base alpha 0.3 < cutoff 0.5: no instance there";
  EXPECT_EQ(past.cell, 1u);
  // Opaque again: the same rays stop at the near wall and the instance.
  w.meshes[0].alpha_mode = w.meshes[2].alpha_mode = Mesh::AlphaMode::Opaque;
  RayGroundTruth solid;
  ASSERT_TRUE(solid.build(w).ok());
  EXPECT_EQ(solid.cast_ray({1.0f, 1.0f, 0}, {0, 0, -1}, 0.0f, 100.0f).cell, 0u);
  EXPECT_EQ(solid.cast_ray({0.8f, 0, 0}, {0, 0, -1}, 0.0f, 100.0f).instance, 0u);
}

// Property: a see-through surface (alphaMode BLEND: glass) hides nothing from the ground truth,
// whatever its alpha: the renderer shows what lies behind it on part of its pixels, so a cell or
// instance behind glass counts as seen. The near wall and the instance as glass of alpha 0.9:
// the rays that stopped at them reach the far wall.
TEST(RayGroundTruth, SeesThroughGlassEverywhere) {
  World w = two_walls();
  w.meshes[0].alpha_mode = w.meshes[2].alpha_mode = Mesh::AlphaMode::Blend;
  w.meshes[0].base_color.a = w.meshes[2].base_color.a = 0.9f;
  RayGroundTruth rt;
  ASSERT_TRUE(rt.build(w).ok());
  for (float x : {-1.5f, -1.0f, 1.0f, 1.5f})
    EXPECT_EQ(rt.cast_ray({x, 1.0f, 0}, {0, 0, -1}, 0.0f, 100.0f).cell, 1u) << "beside the hole at x " << x;
  const RayHitId past = rt.cast_ray({0.8f, 0, 0}, {0, 0, -1}, 0.0f, 100.0f);
  EXPECT_EQ(past.instance, RayHitId::kNone);
  EXPECT_EQ(past.cell, 1u);
}

TEST(RayGroundTruth, GridMarksExactlyTheCellsAndInstancesItHits) {
  const World w = two_walls();
  RayGroundTruth rt;
  ASSERT_TRUE(rt.build(w).ok());
  GroundTruth gt;
  RayCamera cam;
  cam.eye_world = {0, 0, 0};
  cam.target_world = {0, 0, -1};
  cam.aspect = 1.0f;
  cam.fov_y_deg = 40.0f;
  rt.cast(cam, 64, gt);
  ASSERT_EQ(gt.pixels.size(), 64u * 64u);
  EXPECT_TRUE(gt.cell_visible[0]);
  EXPECT_TRUE(gt.cell_visible[1]);
  EXPECT_TRUE(gt.instance_visible[0]);
  // The centre pixel looks through the hole, a corner pixel at the frame.
  EXPECT_EQ(gt.pixels[32 * 64 + 32].cell, 1u);
  EXPECT_EQ(gt.pixels[0].cell, 0u);
  // Turning away from everything sees nothing.
  cam.target_world = {0, 0, 1};
  rt.cast(cam, 16, gt);
  EXPECT_FALSE(gt.cell_visible[0]);
  EXPECT_FALSE(gt.cell_visible[1]);
  EXPECT_FALSE(gt.instance_visible[0]);
}

TEST(RayGroundTruth, RaysStartAtTheNearPlane) {
  const World w = two_walls();
  RayGroundTruth rt;
  ASSERT_TRUE(rt.build(w).ok());
  RayCamera cam;
  cam.eye_world = {0.8f, 0.0f, 0.02f};  // the instance is 3.02 m ahead
  cam.target_world = {0.8f, 0.0f, -1.0f};
  cam.aspect = 1.0f;
  cam.near_m = 3.5f;  // the instance at depth ~3.02 is nearer than the near plane: clipped away
  GroundTruth gt;
  rt.cast(cam, 16, gt);
  EXPECT_FALSE(gt.instance_visible[0]);
  cam.near_m = 0.05f;
  rt.cast(cam, 16, gt);
  EXPECT_TRUE(gt.instance_visible[0]);
}

}  // namespace
}  // namespace lintel
