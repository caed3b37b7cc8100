// The GI's visibility inside a cell (render/src/segment_occluders.h, gi_layout.cpp). No GPU.
//  * Segment queries: on random triangle soups, the BVH's answers are a brute-force loop's (a
//    different crossing test: the plane, then the point's side of each edge).
//  * A wall inside a room: a room split in two by a slab from floor to ceiling (an instance, not
//    a portal). No probe sees a surfel beyond the slab, and every probe sees surfels on its side.
//  * A buried probe: a grid point inside a solid block is moved out of it, within its own grid
//    cell, and then sees through the room like the others.
#include "../scene/box_cells.h"
#include "gi_layout.h"
#include "render_scene.h"
#include "segment_occluders.h"

#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <random>

namespace lintel::render {
namespace {

using Tri = SegmentOccluders::Triangle;

// Where the segment crosses the triangle's plane, if more than `margin` from its ends and inside it.
bool brute_cross(const glm::vec3& p, const glm::vec3& q, const Tri& t, float margin, float& at) {
  const glm::vec3 n = glm::cross(t.b - t.a, t.c - t.a);
  const float dp = glm::dot(n, p - t.a), dq = glm::dot(n, q - t.a);
  if ((dp > 0.0f) == (dq > 0.0f) || dp == dq) return false;
  at = dp / (dp - dq);
  if (at <= margin || at >= 1.0f - margin) return false;
  const glm::vec3 x = p + at * (q - p);
  const float s0 = glm::dot(n, glm::cross(t.b - t.a, x - t.a)), s1 = glm::dot(n, glm::cross(t.c - t.b, x - t.b)),
              s2 = glm::dot(n, glm::cross(t.a - t.c, x - t.c));
  return (s0 >= 0.0f && s1 >= 0.0f && s2 >= 0.0f) || (s0 <= 0.0f && s1 <= 0.0f && s2 <= 0.0f);
}

// Property: for any soup of triangles and any segment that does not graze one (crossings near an
// end or an edge are left out: there the two float tests may round apart), the BVH
// says "blocked" exactly when some triangle crosses the segment, and its first hit is the nearest
// crossing, front or back as that triangle faces the segment's start.
TEST(SegmentOccluders, AgreesWithBruteForce) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> coord(-5.0f, 5.0f), size(0.1f, 2.0f);
  for (int soup = 0; soup < 20; ++soup) {
    std::vector<Tri> tris;
    const int count = 1 + soup * 15;
    for (int i = 0; i < count; ++i) {
      const glm::vec3 a(coord(rng), coord(rng), coord(rng));
      const glm::vec3 b = a + size(rng) * glm::normalize(glm::vec3(coord(rng), coord(rng), coord(rng)) + 1e-3f);
      const glm::vec3 c = a + size(rng) * glm::normalize(glm::vec3(coord(rng), coord(rng), coord(rng)) + 1e-3f);
      const glm::vec3 n = glm::cross(b - a, c - a);
      if (glm::length(n) < 1e-3f) continue;
      tris.push_back({a, b, c, glm::normalize(n)});
    }
    const SegmentOccluders bvh(tris);
    int checked = 0, crossing = 0;
    for (int s = 0; s < 300; ++s) {
      const glm::vec3 p(coord(rng), coord(rng), coord(rng)), q(coord(rng), coord(rng), coord(rng));
      float nearest = 2.0f;
      const Tri* first = nullptr;
      bool grazing = false;
      for (const Tri& t : tris) {
        float at;
        // Grazing: a crossing of a slightly grown or shrunk triangle that this one does not share.
        const glm::vec3 m = (t.a + t.b + t.c) / 3.0f;
        const Tri grown{m + 1.01f * (t.a - m), m + 1.01f * (t.b - m), m + 1.01f * (t.c - m), t.normal};
        const Tri shrunk{m + 0.99f * (t.a - m), m + 0.99f * (t.b - m), m + 0.99f * (t.c - m), t.normal};
        float g;
        if (brute_cross(p, q, grown, 0.0f, g) != brute_cross(p, q, shrunk, 2e-3f, g)) grazing = true;
        if (brute_cross(p, q, t, 1e-3f, at) && at < nearest) {
          nearest = at;
          first = &t;
        }
      }
      if (grazing) continue;
      ++checked;
      crossing += first != nullptr;
      EXPECT_EQ(bvh.blocked(p, q), first != nullptr) << "soup " << soup << " segment " << s;
      const SegmentOccluders::Hit expected =
          !first ? SegmentOccluders::Hit::None
                 : (glm::dot(first->normal, q - p) < 0.0f ? SegmentOccluders::Hit::Front : SegmentOccluders::Hit::Back);
      EXPECT_EQ(bvh.first_hit(p, q), expected) << "soup " << soup << " segment " << s;
    }
    EXPECT_GT(checked, 200);
    if (soup > 5) {
      EXPECT_GT(crossing, 0) << "the soup should block some segments";
    }
  }
}

bool sees(const GiLayout& layout, const GpuProbe& probe, uint32_t first_surfel, uint32_t surfel) {
  const uint32_t k = surfel - first_surfel;
  return (layout.probe_visibility[probe.visibility.x + k / 128][(k / 32) % 4] >> (k % 32)) & 1u;
}

TEST(ProbeVisibility, WallInsideARoomHidesTheOtherHalf) {
  SceneDesc scene;
  const int room =
      test::add_box_cell(scene, "room", {-5, 0, -5}, {5, 3, 5}, test::inward_box_mesh("shell", {-5, 0, -5}, {5, 3, 5}));
  test::add_box_instance(scene, room, "slab", {-0.05f, 0.0f, -5.0f}, {0.05f, 3.0f, 5.0f});
  // A solid block around the grid point (2.5, 0.75, 2.5) (probes 10 / 6 m apart across, 1.5 m up).
  test::add_box_instance(scene, room, "block", {2.0f, 0.0f, 2.0f}, {3.0f, 1.2f, 3.0f});
  World world;
  ASSERT_TRUE(build_world(scene, "room with a slab", world).ok());
  RenderScene rs;
  ASSERT_TRUE(build_render_scene(world, rs).ok());
  const GiLayout layout = build_gi_layout(rs, GiOptions{});
  ASSERT_EQ(layout.cells.size(), 1u);
  const GpuCellProbes& cp = layout.cells[0];
  const uint32_t first = cp.surfels.x, last = cp.surfels.z + cp.surfels.w;
  const glm::vec3 step(cp.step_grid);
  int moved = 0;
  for (uint32_t p = cp.dims.w; p < cp.dims.w + cp.dims.x * cp.dims.y * cp.dims.z; ++p) {
    const GpuProbe& probe = layout.probes[p];
    const glm::vec3 x(probe.position_world);
    const uint32_t i = p - cp.dims.w;
    const glm::vec3 grid = glm::vec3(cp.origin_grid) +
                           glm::vec3(i % cp.dims.x, i / cp.dims.x % cp.dims.y, i / (cp.dims.x * cp.dims.y)) * step;
    // Relocation stays within the probe's own grid cell, and never onto the slab's other side.
    EXPECT_TRUE(glm::all(glm::lessThanEqual(glm::abs(x - grid), 0.5f * step))) << "probe " << p;
    ASSERT_NE(x.x > 0.0f, grid.x < 0.0f) << "probe " << p;
    moved += x != grid;
    EXPECT_FALSE(x.x > 2.0f && x.x < 3.0f && x.y < 1.2f && x.z > 2.0f && x.z < 3.0f)
        << "probe " << p << " in the block";
    int own_side = 0;
    for (uint32_t s = first; s < last; ++s) {
      if (!sees(layout, probe, first, s)) continue;
      const float sx = layout.surfels[s].position_cell.x;
      EXPECT_TRUE(x.x < 0.0f ? sx <= 0.05f : sx >= -0.05f)
          << "probe " << p << " at x " << x.x << " sees surfel " << s << " at x " << sx << " beyond the slab";
      own_side += (x.x < 0.0f) == (sx < 0.0f);
    }
    EXPECT_GT(own_side, 20) << "probe " << p << " sees almost nothing of its own half";
  }
  EXPECT_EQ(moved, 1) << "exactly the probe inside the block moves";
}

}  // namespace
}  // namespace lintel::render
