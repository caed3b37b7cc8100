// Drawing through the cull's indirect buffer: every group with visible instances -- including the
// ones at a non-zero firstInstance, which a device without drawIndirectFirstInstance would drop
// silently -- produces fragments, and gl_InstanceIndex reaches the right instance (the vertex
// shader reads the id buffer at gl_InstanceIndex; the fragment writes id + 1 into R32_UINT).
// Both draw paths: vkCmdDrawIndexedIndirect (checked by GPU-assisted validation) and the
// compacted list with vkCmdDrawIndexedIndirectCount (which GPU-AV 1.3.239 does not check, so this
// readback is its only guard).
#include "gpu_test_support.h"
#include "id_raster.h"

#include <lintel/gpu/cull_pass.h>

#include <glm/ext/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

namespace lintel::gpu {
namespace {

constexpr uint32_t kSlots = 16;  // 16 x 16 instance slots on the 256 px target
constexpr uint32_t kMeshes = 6;
constexpr float kSlotNdc = 2.0f / kSlots;

glm::vec2 slot_center(uint32_t i) {
  return {-1.0f + (float(i % kSlots) + 0.5f) * kSlotNdc, -1.0f + (float(i / kSlots) + 0.5f) * kSlotNdc};
}

// Meshes: regular (3 + m)-gons at z = 0.5, so each group has its own index count, first index
// and vertex offset. Instances: one per slot, groups interleaved so most bases are non-zero.
World make_world() {
  World w;
  w.source = "raster test";
  w.cells.resize(3);
  for (uint32_t m = 0; m < kMeshes; ++m) {
    Mesh mesh;
    const uint32_t n = 3 + m;
    mesh.positions.push_back({0.0f, 0.0f, 0.5f});
    for (uint32_t k = 0; k < n; ++k) {
      const double a = 2.0 * std::numbers::pi * k / n;
      mesh.positions.push_back({float(0.045 * std::cos(a)), float(0.045 * std::sin(a)), 0.5f});
      mesh.indices.insert(mesh.indices.end(), {0, 1 + k, 1 + (k + 1) % n});
    }
    for (const glm::vec3& p : mesh.positions) mesh.bounds_mesh.extend(p);
    w.meshes.push_back(mesh);
    w.groups.push_back({m, {}});
  }
  for (uint32_t i = 0; i < kSlots * kSlots; ++i) {
    Instance inst;
    inst.group = inst.mesh = (i * 5 + i / 7) % kMeshes;
    inst.cell = (i / kSlots) % 3;
    const glm::vec2 c = slot_center(i);
    inst.mesh_to_world = glm::translate(glm::mat4(1.0f), glm::vec3(c, 0.0f));
    inst.bounds_world = transform_aabb(inst.mesh_to_world, w.meshes[inst.mesh].bounds_mesh);
    w.groups[inst.group].instances.push_back(i);
    w.instances.push_back(inst);
  }
  return w;
}

class RasterTest : public test::ValidatedGpu {};

TEST_F(RasterTest, IndirectDrawsReachEveryGroupAndInstance) {
  const World world = make_world();
  CullScene scene;
  ASSERT_TRUE(pack_scene(world, {}, scene).ok());
  // Identity camera (clip = world, w = 1), eye far outside every box. Cell 0 sees the whole
  // screen, cell 1 only its left half, cell 2 nothing.
  CullFrame frame;
  frame.clear(3, glm::dmat4(1.0), glm::vec3(10.0f));
  const std::vector<std::vector<glm::vec2>> full = {{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};
  const std::vector<std::vector<glm::vec2>> left = {{{-1, -1}, {0, -1}, {0, 1}, {-1, 1}}};
  frame.add_region(0, {-1, -1, 1, 1}, full);
  frame.add_region(1, {-1, -1, 0, 1}, left);

  std::vector<glm::vec3> vertices;
  std::vector<uint32_t> indices;
  for (const Mesh& m : world.meshes) {
    vertices.insert(vertices.end(), m.positions.begin(), m.positions.end());
    indices.insert(indices.end(), m.indices.begin(), m.indices.end());
  }
  std::vector<glm::vec2> offsets;
  for (uint32_t i = 0; i < world.instances.size(); ++i) offsets.push_back(slot_center(i));

  std::unique_ptr<CullPass> pass;
  ASSERT_TRUE(CullPass::create(ctx(), {}, pass).ok());
  ASSERT_TRUE(pass->set_scene(scene).ok());
  ASSERT_TRUE(pass->set_frame(frame).ok());
  CullReadback rb;
  ASSERT_TRUE(pass->run(&rb).ok());
  std::set<uint32_t> drawn;
  uint32_t groups_with_nonzero_base = 0;
  for (uint32_t g = 0; g < rb.commands.size(); ++g) {
    for (uint32_t id : rb.group_ids(g)) drawn.insert(id);
    if (rb.commands[g].instance_count && rb.commands[g].first_instance) ++groups_with_nonzero_base;
  }
  // Cell 0 rows: all 16 slots; cell 1 rows: the 8 left slots (the boxes at x = 0 +- 0.045 do not
  // reach the left half's edge x = 0 except ... none do: slot centers are 0.0625 from it).
  ASSERT_EQ(drawn.size(), 6u * 16 + 5u * 8) << "rows 0,3,..,15 (cell 0) and 1,4,..,13 (cell 1)";
  ASSERT_GE(groups_with_nonzero_base, 4u);

  test::IdRaster raster;
  ASSERT_TRUE(raster.init(ctx(), vertices, indices, offsets).ok());
  for (bool use_count : {false, true}) {
    if (use_count && !ctx().info().draw_indirect_count) continue;
    SCOPED_TRACE(use_count ? "vkCmdDrawIndexedIndirectCount" : "vkCmdDrawIndexedIndirect");
    std::vector<uint32_t> pixels;
    Status s = raster.cull_and_draw(*pass, use_count, pixels);
    ASSERT_TRUE(s.ok()) << s.message();
    std::set<uint32_t> seen;
    for (uint32_t p : pixels)
      if (p) seen.insert(p - 1);
    EXPECT_EQ(seen, drawn) << "the image holds exactly the drawn instances";
    for (uint32_t i = 0; i < world.instances.size(); ++i) {
      const uint32_t expected = drawn.count(i) ? i + 1 : 0;
      EXPECT_EQ(pixels[test::IdRaster::pixel_index(slot_center(i))], expected)
          << "slot of instance " << i << " (group " << world.instances[i].group << ")";
    }
    for (uint32_t g = 0; g < rb.commands.size(); ++g) {
      if (!rb.commands[g].instance_count) continue;
      bool fragments = false;
      for (uint32_t id : seen) fragments = fragments || world.instances[id].group == g;
      EXPECT_TRUE(fragments) << "group " << g << " (firstInstance " << rb.commands[g].first_instance
                             << ") produced no fragments";
    }
  }
}

}  // namespace
}  // namespace lintel::gpu
