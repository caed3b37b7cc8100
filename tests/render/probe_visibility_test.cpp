// The GI's visibility inside a cell (render/src/segment_occluders.h, gi_layout.cpp). No GPU.
//  * Segment queries: on random triangle soups, the BVH's answers are a brute-force loop's (a
//    different crossing test: the plane, then the point's side of each edge).
//  * A wall inside a room: a room split in two by a slab from floor to ceiling (an instance, not
//    a portal). No probe sees a surfel beyond the slab, and every probe sees surfels on its side.
//  * A buried probe: a grid point inside a solid block is moved out of it, within its own grid
//    cell, and then sees through the room like the others.
//  * Cut-outs (alphaMode MASK): a segment passes a cut-out triangle where its coverage is below
//    the cutoff and is blocked where it is not; a slab cut away entirely hides nothing.
#include "../scene/box_cells.h"
#include "gi_layout.h"
#include "render_scene.h"
#include "segment_occluders.h"

#include <lintel/scene_io.h>

#include <gtest/gtest.h>

#include <array>
#include <random>
#include <utility>

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

struct Agreement {
  int checked = 0, crossing = 0;
};

// Segments from `segment(rng)` against `tris`: the occluders' blocked() and first_hit() against a
// brute-force loop, grazing segments (a crossing near an end or an edge, where the two float tests
// may round apart) left out.
template <typename Segment>
Agreement check_against_brute_force(const std::vector<Tri>& tris, const SegmentOccluders& occluders, Segment segment,
                                    int segments, std::mt19937& rng, const char* what) {
  Agreement a;
  for (int s = 0; s < segments; ++s) {
    const auto [p, q] = segment(rng);
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
    ++a.checked;
    a.crossing += first != nullptr;
    EXPECT_EQ(occluders.blocked(p, q), first != nullptr) << what << " segment " << s;
    const SegmentOccluders::Hit expected =
        !first ? SegmentOccluders::Hit::None
               : (glm::dot(first->normal, q - p) < 0.0f ? SegmentOccluders::Hit::Front : SegmentOccluders::Hit::Back);
    EXPECT_EQ(occluders.first_hit(p, q), expected) << what << " segment " << s;
  }
  return a;
}

// Property: for any soup of triangles and any segment that does not graze one, the BVH says
// "blocked" exactly when some triangle crosses the segment, and its first hit is the nearest
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
    const Agreement a = check_against_brute_force(
        tris, bvh,
        [&](std::mt19937& r) {
          return std::pair{glm::vec3(coord(r), coord(r), coord(r)), glm::vec3(coord(r), coord(r), coord(r))};
        },
        300, rng, "soup");
    EXPECT_GT(a.checked, 200);
    if (soup > 5) {
      EXPECT_GT(a.crossing, 0) << "the soup should block some segments";
    }
  }
}

// The faces of the box [lo, hi], each split in two triangles, facing inward (a room's shell) or
// outward (a block of furniture).
void add_box(std::vector<Tri>& tris, const glm::vec3& lo, const glm::vec3& hi, bool inward) {
  const glm::vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z},
                          {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}};
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces)
    for (const auto& [i, j, k] : {std::array{f[0], f[1], f[2]}, std::array{f[0], f[2], f[3]}}) {
      const glm::vec3 a = c[i], b = inward ? c[k] : c[j], d = inward ? c[j] : c[k];
      tris.push_back({a, b, d, glm::normalize(glm::cross(b - a, d - a))});
    }
}

// Property: in rooms -- an inward box shell, an L-shaped one (an inner corner: two planes with
// geometry on both sides), blocks of furniture, a room far from the origin -- the boundary planes
// (segment_occluders.h) change no answer: blocked() and first_hit() equal the brute-force loop's
// for segments between points inside the room (the fast path) and for segments that leave it.
TEST(SegmentOccluders, BoundaryPlanesChangeNoAnswer) {
  std::mt19937 rng(11);
  for (int room = 0; room < 12; ++room) {
    const glm::vec3 offset = room % 4 == 3 ? glm::vec3(1.2e4f, -3.0e3f, 7.0e3f) : glm::vec3(0.0f);
    const glm::vec3 lo = offset + glm::vec3(-4.0f, 0.0f, -3.0f), hi = offset + glm::vec3(4.0f, 3.0f, 3.0f);
    std::vector<Tri> tris;
    add_box(tris, lo, hi, true);
    // An L: a corner filled by a block (a hair off the walls: coincident faces would make "the
    // first hit" a tie between front and back).
    if (room % 2 == 1) add_box(tris, lo + 0.01f, lo + glm::vec3(3.0f, 2.99f, 2.5f), false);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int block = 0; block < room; ++block) {
      // Inside the room, a hair above the floor (no coincident faces).
      const glm::vec3 a = lo + glm::vec3(0.7f * u(rng), 0.0f, 0.7f * u(rng)) * (hi - lo) + glm::vec3(0.0f, 0.01f, 0.0f);
      add_box(tris, a, a + glm::vec3(0.3f + u(rng), 0.2f + 2.0f * u(rng), 0.3f + u(rng)), false);
    }
    const SegmentOccluders occluders(tris);
    EXPECT_EQ(occluders.boundary_plane_count(), 6u)
        << "room " << room << ": the shell's six planes; no block's plane (geometry on both sides)";
    // Points inside the room's box, a fifth of them beyond it (outside every wall).
    const auto point = [&](std::mt19937& r) {
      const glm::vec3 t(u(r), u(r), u(r));
      return lo - 0.25f * (hi - lo) * float(u(r) < 0.2f) + t * (hi - lo) * (1.0f + 0.5f * float(u(r) < 0.2f));
    };
    int inside_both = 0;
    const Agreement a = check_against_brute_force(
        tris, occluders,
        [&](std::mt19937& r) {
          const glm::vec3 p = point(r), q = point(r);
          inside_both += occluders.inside_boundary(p) && occluders.inside_boundary(q);
          return std::pair{p, q};
        },
        400, rng, "room");
    EXPECT_GT(a.checked, 300);
    EXPECT_GT(inside_both, 100) << "most segments should take the boundary planes' fast path";
    if (room > 2) {
      EXPECT_GT(a.crossing, 0) << "the furniture should block some segments";
    }
  }
}

// A 10 x 3 x 10 m room split at x = 0 by a 10 cm slab from floor to ceiling (an instance named
// "slab", not a portal); the room's node index.
int add_room_split_by_slab(SceneDesc& scene) {
  const int room =
      test::add_box_cell(scene, "room", {-5, 0, -5}, {5, 3, 5}, test::inward_box_mesh("shell", {-5, 0, -5}, {5, 3, 5}));
  test::add_box_instance(scene, room, "slab", {-0.05f, 0.0f, -5.0f}, {0.05f, 3.0f, 5.0f});
  return room;
}

// The GI layout of `scene` as the renderer builds it (probe visibility on).
GiLayout gi_layout_of(const SceneDesc& scene) {
  World world;
  const Status s = build_world(scene, "room", world);
  EXPECT_TRUE(s.ok()) << s.message();
  RenderScene rs;
  EXPECT_TRUE(build_render_scene(world, rs).ok());
  return build_gi_layout(rs, GiOptions{});
}

bool sees(const GiLayout& layout, const GpuProbe& probe, uint32_t first_surfel, uint32_t surfel) {
  const uint32_t k = surfel - first_surfel;
  return (layout.probe_visibility[probe.visibility.x + k / 128][(k / 32) % 4] >> (k % 32)) & 1u;
}

// Property: a cut-out blocks a segment exactly where it has surface: a 2 x 2 m quad whose texture
// is two texels, alpha 0 on its left half and 255 on its right, read nearest, blocks every
// segment through its right half and none through its left (crossings within 5 cm of the texel
// edge left out); with every corner's alpha 0.3 under a cutoff of 0.5, it blocks none.
TEST(SegmentOccluders, CutOutBlocksOnlyWhereItHasSurface) {
  Texture halves;
  halves.width = 2;
  halves.height = 1;
  halves.rgba8 = {200, 200, 200, 0, 200, 200, 200, 255};
  const TextureMips mips = texture_mips(halves);
  const glm::vec3 a(-1, -1, 0), b(1, -1, 0), c(1, 1, 0), d(-1, 1, 0);
  auto uv = [](const glm::vec3& p) { return glm::vec2((p.x + 1.0f) / 2.0f, (1.0f - p.y) / 2.0f); };
  SegmentOccluders::CutOut cut;
  cut.texture = &mips;
  cut.sampler.mag = cut.sampler.min = TextureSampler::Filter::Nearest;
  cut.sampler.wrap_s = cut.sampler.wrap_t = TextureSampler::Wrap::ClampToEdge;
  for (const float corner_alpha : {1.0f, 0.3f}) {
    SCOPED_TRACE(corner_alpha);
    std::vector<SegmentOccluders::CutOut> cuts;
    for (const auto& [p, q, r] : {std::array{a, b, c}, std::array{a, c, d}}) {
      cut.uv_a = uv(p), cut.uv_b = uv(q), cut.uv_c = uv(r);
      cut.alpha_a = cut.alpha_b = cut.alpha_c = corner_alpha;
      cuts.push_back(cut);
    }
    const std::vector<Tri> quad = {{a, b, c, {0, 0, 1}, 0}, {a, c, d, {0, 0, 1}, 1}};
    const SegmentOccluders occluders(quad, cuts);
    int blocked = 0, passed = 0;
    for (float x = -0.95f; x <= 0.95f; x += 0.1f)
      for (float y = -0.95f; y <= 0.95f; y += 0.1f) {
        if (std::abs(x) < 0.05f) continue;
        const bool hit = occluders.blocked({x, y, -1.0f}, {x, y, 1.0f});
        EXPECT_EQ(hit, corner_alpha == 1.0f && x > 0.0f) << x << ", " << y;
        (hit ? blocked : passed)++;
      }
    EXPECT_GT(passed, 100);
    EXPECT_EQ(blocked > 100, corner_alpha == 1.0f) << blocked << " blocked";
  }
}

// Property: a slab that is a cut-out with no surface anywhere (factor alpha 0) hides nothing: the
// probes on each side of it see surfels on the other (the same room with the slab solid is
// WallInsideARoomHidesTheOtherHalf).
TEST(ProbeVisibility, UncoveredCutOutHidesNothing) {
  SceneDesc scene;
  add_room_split_by_slab(scene);
  for (MeshDesc& m : scene.meshes)
    if (m.name == "slab") m.alpha_mode = Mesh::AlphaMode::Mask, m.base_color.a = 0.0f;
  const GiLayout layout = gi_layout_of(scene);
  ASSERT_EQ(layout.cells.size(), 1u);
  const GpuCellProbes& cp = layout.cells[0];
  const uint32_t first = cp.surfels.x, last = cp.surfels.z + cp.surfels.w;
  for (uint32_t p = cp.dims.w; p < cp.dims.w + cp.dims.x * cp.dims.y * cp.dims.z; ++p) {
    const GpuProbe& probe = layout.probes[p];
    const float x = probe.position_world.x;
    int other_side = 0;
    for (uint32_t s = first; s < last; ++s)
      if (sees(layout, probe, first, s) && (x < 0.0f) != (layout.surfels[s].position_cell.x < 0.0f)) ++other_side;
    EXPECT_GT(other_side, 20) << "probe " << p << " at x " << x << " sees almost nothing beyond the slab";
  }
}

TEST(ProbeVisibility, WallInsideARoomHidesTheOtherHalf) {
  SceneDesc scene;
  const int room = add_room_split_by_slab(scene);
  // A solid block around the grid point (2.5, 0.75, 2.5) (probes 10 / 6 m apart across, 1.5 m up).
  test::add_box_instance(scene, room, "block", {2.0f, 0.0f, 2.0f}, {3.0f, 1.2f, 3.0f});
  const GiLayout layout = gi_layout_of(scene);
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
