// The portal flood: what it sees, that it never misses what a view ray sees, its pop bound,
// determinism, and independence from cell frames.
#include "ray_walk.h"
#include "test_worlds.h"

#include <lintel/cell_locate.h>
#include <lintel/visibility_builder.h>

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace lintel {
namespace {

using testing::make_chain;
using testing::make_cycle_stack;
using testing::make_grid;
using testing::make_ring;
using testing::TestWorld;
using testing::WorldOptions;

std::vector<uint32_t> visible_cells(const VisibleSet& v) {
  std::vector<uint32_t> out;
  for (const VisibleCell& c : v.cells) out.push_back(c.cell);
  return out;
}

VisibleSet build_or_fail(VisibilityBuilder& builder, const World& world, const View& view, uint32_t start,
                         const VisibilityOptions& options = {}) {
  VisibleSet out;
  const Status s = builder.build(world, view, start, options, out);
  EXPECT_TRUE(s.ok()) << s.message();
  return out;
}

TEST(PortalTraversal, ChainSeenDownItsLength) {
  const TestWorld t = make_chain(6);
  VisibilityBuilder builder;
  const VisibleSet v = build_or_fail(builder, t.world, t.view({1.0f, 1.2f, 0.0f}, {23.0f, 1.2f, 0.0f}), 0);
  EXPECT_EQ(visible_cells(v), (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
  // Regions shrink with distance and stay inside the screen.
  for (size_t i = 1; i < v.cells.size(); ++i) {
    EXPECT_TRUE(full_screen_rect().contains(v.cells[i].rect_ndc));
    EXPECT_TRUE(v.cells[i - 1].rect_ndc.contains(v.cells[i].rect_ndc)) << "room " << i;
    EXPECT_EQ(v.cells[i].reached_from, v.cells[i - 1].cell);
  }
  EXPECT_EQ(v.cells[0].rect_ndc, full_screen_rect());
  uint64_t pops = 0;
  for (const VisibleCell& c : v.cells) pops += c.pops;
  EXPECT_EQ(pops, v.stats.pops);
  EXPECT_EQ(v.stats.pop_bound, pop_bound(6, VisibilityOptions{}));
}

TEST(PortalTraversal, LookingAtAWallSeesOnlyTheViewerCell) {
  const TestWorld t = make_chain(5);
  VisibilityBuilder builder;
  const VisibleSet v = build_or_fail(builder, t.world, t.view({10.0f, 1.2f, 0.0f}, {10.0f, 1.2f, -5.0f}), 2);
  EXPECT_EQ(visible_cells(v), (std::vector<uint32_t>{2}));
  EXPECT_EQ(v.stats.pops, 1u);
}

TEST(PortalTraversal, OneWayPortalsAreSeenFromTheirFromSideOnly) {
  WorldOptions o;
  o.one_way = true;
  const TestWorld t = make_chain(4, o);
  VisibilityBuilder builder;
  const VisibleSet forward = build_or_fail(builder, t.world, t.view({1.0f, 1.2f, 0.0f}, {15.0f, 1.2f, 0.0f}), 0);
  EXPECT_EQ(visible_cells(forward), (std::vector<uint32_t>{0, 1, 2, 3}));
  const VisibleSet back = build_or_fail(builder, t.world, t.view({15.0f, 1.2f, 0.0f}, {1.0f, 1.2f, 0.0f}), 3);
  EXPECT_EQ(visible_cells(back), (std::vector<uint32_t>{3}));
  // The same looking back through two-way portals sees everything: the test can tell.
  const TestWorld two_way = make_chain(4);
  const VisibleSet back2 =
      build_or_fail(builder, two_way.world, two_way.view({15.0f, 1.2f, 0.0f}, {1.0f, 1.2f, 0.0f}), 3);
  EXPECT_EQ(visible_cells(back2), (std::vector<uint32_t>{0, 1, 2, 3}));
}

// Property (no false negatives): for random eyes inside random cells and random view directions,
// every cell a view ray reaches through portals between the near and far planes is visible and
// the ray's pixel lies inside that cell's region (up to 1e-6 NDC).
void check_against_ray_walks(const TestWorld& t, uint32_t seed, int views, int rays_per_view,
                             const VisibilityOptions& options = {}) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  VisibilityBuilder builder;
  int checked = 0, beyond_start = 0;
  for (int view_index = 0; view_index < views; ++view_index) {
    // A random point inside a random cell: sample the cell's world box until contained.
    const uint32_t cell = uint32_t(rng() % t.world.cells.size());
    const Aabb box = transform_aabb(t.world.cells[cell].cell_to_world, t.world.cells[cell].volume_box_cell);
    glm::dvec3 eye;
    bool found = false;
    for (int k = 0; k < 1000 && !found; ++k) {
      eye = glm::dvec3(box.min) + glm::dvec3(u(rng), u(rng), u(rng)) * glm::dvec3(box.extent());
      found = cell_volume_contains(t.world, cell, eye) && cell_volume_distance_m(t.world, cell, eye) == 0.0;
    }
    ASSERT_TRUE(found);
    const double yaw = 6.283185307 * u(rng), pitch = 0.6 * (u(rng) - 0.5);
    const glm::vec3 dir_layout(std::cos(yaw) * std::cos(pitch), std::sin(pitch), std::sin(yaw) * std::cos(pitch));
    View view;
    view.eye_world = glm::vec3(eye);
    view.target_world = view.eye_world + t.dir_to_world(dir_layout);
    view.up_world = t.dir_to_world({0.0f, 1.0f, 0.0f});
    view.fov_y_deg = float(50.0 + 60.0 * u(rng));
    const VisibleSet v = build_or_fail(builder, t.world, view, cell, options);
    for (int r = 0; r < rays_per_view; ++r) {
      const glm::dvec2 ndc(1.98 * u(rng) - 0.99, 1.98 * u(rng) - 0.99);
      const testing::RayWalk walk = testing::walk_view_ray(t.world, view, cell, ndc);
      if (walk.ambiguous) continue;
      for (uint32_t c : walk.seen_cells) {
        ++checked;
        if (c != cell) ++beyond_start;
        const VisibleCell* vc = v.find(c);
        ASSERT_NE(vc, nullptr) << "cell " << c << " seen by a ray is not visible (view " << view_index << ")";
        EXPECT_TRUE(v.region(*vc).contains(ndc, 1e-6))
            << "pixel " << ndc.x << ", " << ndc.y << " outside the region of cell " << c;
      }
    }
  }
  EXPECT_GT(beyond_start, checked / 20) << "too few rays went through portals to test anything";
}

TEST(PortalTraversal, NeverMissesWhatARaySeesInChains) { check_against_ray_walks(make_chain(7), 1, 60, 150); }
TEST(PortalTraversal, NeverMissesWhatARaySeesInGrids) {
  check_against_ray_walks(make_grid(5, 4), 2, 60, 150);
  WorldOptions wide;
  wide.door_half_width = 1.7f;
  check_against_ray_walks(make_grid(5, 5, wide), 12, 60, 150);
}
TEST(PortalTraversal, NeverMissesWhatARaySeesInRings) {
  for (uint32_t n : {3u, 5u, 12u, 40u}) check_against_ray_walks(make_ring(n), 3 + n, 25, 120);
}
TEST(PortalTraversal, NeverMissesWhatARaySeesWithTinyCapAndCoarseLattice) {
  VisibilityOptions o;
  o.reprocess_cap = 0;
  o.max_region_polygons = 1;
  o.snap_lattice_cells = 16;
  WorldOptions wide;
  wide.door_half_width = 1.7f;
  check_against_ray_walks(make_grid(5, 5, wide), 4, 60, 150, o);
}

// Property (no false negatives near doors): eyes just beyond the doorway rule's reach — 0.051 to
// 0.3 m from a door's plane (near = 0.05), over the door or beside it — looking anywhere, grazing
// the wall included: every cell a ray sees is visible with the pixel inside its region. Corner
// rays of such views cross the door closer than the near plane and still see the room behind it.
TEST(PortalTraversal, NeverMissesWhatARaySeesJustOutsideTheDoorway) {
  WorldOptions o;
  o.layout_to_world = testing::layout_to_world_centred_at({8.0f, 1.1f, 0.0f});
  const TestWorld t = make_chain(4, o);
  VisibilityBuilder builder;
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int beyond = 0;
  for (int k = 0; k < 150; ++k) {
    const double side = u(rng) < 0.5 ? -1.0 : 1.0;
    const double distance = 0.051 + 0.25 * u(rng) * u(rng);
    const glm::vec3 eye(8.0f + float(side * distance), float(0.3 + 1.6 * u(rng)), float(-1.2 + 2.4 * u(rng)));
    const uint32_t start = side < 0 ? 1 : 2;
    const double yaw = 6.283185307 * u(rng);
    const double pitch = u(rng) < 0.3 ? 0.0 : 0.8 * (u(rng) - 0.5);
    const glm::vec3 dir(float(std::cos(yaw) * std::cos(pitch)), float(std::sin(pitch)),
                        float(std::sin(yaw) * std::cos(pitch)));
    View view = t.view(eye, eye + dir, float(40.0 + 80.0 * u(rng)));
    view.aspect = float(0.5 + 2.0 * u(rng));
    const VisibleSet v = build_or_fail(builder, t.world, view, start);
    for (int j = 0; j < 24; ++j)
      for (int i = 0; i < 24; ++i) {
        const glm::dvec2 ndc((i + 0.5) / 12.0 - 1.0, (j + 0.5) / 12.0 - 1.0);
        const testing::RayWalk walk = testing::walk_view_ray(t.world, view, start, ndc);
        if (walk.ambiguous) continue;
        for (uint32_t c : walk.seen_cells) {
          beyond += c != start;
          const VisibleCell* vc = v.find(c);
          ASSERT_NE(vc, nullptr) << "view " << k << ": cell " << c << " seen by a ray is not visible";
          ASSERT_TRUE(v.region(*vc).contains(ndc, 1e-6))
              << "view " << k << ": pixel " << ndc.x << ", " << ndc.y << " outside the region of cell " << c;
        }
      }
  }
  EXPECT_GT(beyond, 500);
}

// Property (termination bound): on rings of 2..256 cells (annular rings, and cyclic stacks whose
// flood really goes round), from many eyes and directions, the number of pops never exceeds
// cells * (K + 2N) — with the defaults and with a coarse lattice and tiny cap, where the rect
// fallback does the work.
TEST(PortalTraversal, PopBoundHoldsOnRings) {
  VisibilityOptions tight;
  tight.snap_lattice_cells = 8;
  tight.reprocess_cap = 1;
  tight.max_region_polygons = 2;
  VisibilityBuilder builder;
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (uint32_t n : {2u, 3u, 4u, 7u, 16u, 33u, 64u, 128u, 256u}) {
    const TestWorld ring = make_ring(n);
    const TestWorld stack = make_cycle_stack(n);
    const float r = testing::ring_inner_radius(n) + 2.0f;
    for (int k = 0; k < 6; ++k) {
      const float a = 6.2831853f * u(rng) / float(n);  // inside sector 0
      const glm::vec3 eye(r * std::cos(a), 1.5f, r * std::sin(a));
      const float yaw = 6.2831853f * u(rng);
      const View view = ring.view(eye, eye + glm::vec3(std::cos(yaw), 0.1f * (u(rng) - 0.5f), std::sin(yaw)));
      for (const VisibilityOptions& o : {VisibilityOptions{}, tight}) {
        const VisibleSet v = build_or_fail(builder, ring.world, view, 0, o);
        EXPECT_LE(v.stats.pops, pop_bound(n, o)) << "ring " << n;
        EXPECT_FALSE(v.stats.bound_exceeded);
      }
      const View into = stack.view({0.3f * (u(rng) - 0.5f), 0.3f * (u(rng) - 0.5f), 0.5f},
                                   {0.5f * (u(rng) - 0.5f), 0.5f * (u(rng) - 0.5f), -5.0f});
      for (const VisibilityOptions& o : {VisibilityOptions{}, tight}) {
        const VisibleSet v = build_or_fail(builder, stack.world, into, 0, o);
        EXPECT_LE(v.stats.pops, pop_bound(n + 1, o)) << "stack " << n;
        EXPECT_EQ(v.cells.size(), n + 1) << "the whole cycle is visible through the windows";
      }
    }
  }
}

// Property (cap keeps a superset): with the cap at 0 and one polygon per region, every cell
// visible with the defaults is still visible and its region covers the default region (checked
// on the default region's vertices pulled 1e-4 NDC toward their polygon's centroid). Tolerance:
// snapping is conservative but not monotone (the snap of a sub-polygon may overhang the snap of
// its super-polygon by up to a lattice cell where the latter has a slanted edge), so the default
// region may overhang the capped one by that much; both contain the exact region.
TEST(PortalTraversal, CapAndPolygonLimitOnlyEverAdd) {
  WorldOptions wide;
  wide.door_half_width = 1.7f;  // wide doors: cells are reached along several paths
  const TestWorld t = make_grid(6, 6, wide);
  VisibilityOptions capped;
  capped.reprocess_cap = 0;
  capped.max_region_polygons = 1;
  VisibilityBuilder builder;
  std::mt19937 rng(23);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  uint64_t cap_hits = 0;
  const double kOverhang = 2.0 * 2.0 / double(VisibilityOptions{}.snap_lattice_cells);
  for (int k = 0; k < 40; ++k) {
    const glm::vec3 eye(0.5f + 23.0f * u(rng), 1.0f + u(rng), 0.5f + 23.0f * u(rng));
    const uint32_t start =
        uint32_t(std::min(5.0f, std::floor(eye.z / 4.0f)) * 6 + std::min(5.0f, std::floor(eye.x / 4.0f)));
    const float yaw = 6.2831853f * u(rng);
    const View view = t.view(eye, eye + glm::vec3(std::cos(yaw), 0.0f, std::sin(yaw)));
    const VisibleSet exact = build_or_fail(builder, t.world, view, start);
    const VisibleSet loose = build_or_fail(builder, t.world, view, start, capped);
    cap_hits += loose.stats.cap_hits + loose.stats.polygon_overflows;
    for (const VisibleCell& c : exact.cells) {
      const VisibleCell* lc = loose.find(c.cell);
      ASSERT_NE(lc, nullptr) << "the cap dropped cell " << c.cell;
      const ClipRegionView re = exact.region(c), rl = loose.region(*lc);
      EXPECT_TRUE(rl.rect_ndc.contains(re.rect_ndc));
      for (size_t i = 0; i < re.polygons.size(); ++i) {
        const auto poly = re.polygon(i);
        glm::dvec2 centroid(0.0);
        for (const glm::vec2& p : poly) centroid += glm::dvec2(p);
        centroid /= double(poly.size());
        for (const glm::vec2& p : poly) {
          const glm::dvec2 q = glm::dvec2(p) + 1e-4 * glm::normalize(centroid - glm::dvec2(p));
          EXPECT_TRUE(rl.contains(q, kOverhang)) << "cell " << c.cell;
        }
      }
    }
  }
  EXPECT_GT(cap_hits, 0u) << "the scenario should exercise the fallbacks";
}

// Property (determinism): the same input gives a bit-identical VisibleSet, whether the builder is
// reused (after other frames) or fresh.
TEST(PortalTraversal, BuildsAreBitIdentical) {
  const TestWorld t = make_grid(5, 5);
  const View a = t.view({2.0f, 1.5f, 2.0f}, {19.0f, 1.2f, 17.0f});
  const View b = t.view({13.0f, 1.0f, 9.0f}, {3.0f, 1.4f, 18.0f});
  VisibilityBuilder builder, fresh;
  VisibleSet first, second, other, third;
  ASSERT_TRUE(builder.build(t.world, a, 0, {}, first).ok());
  ASSERT_TRUE(builder.build(t.world, b, 8, {}, other).ok());
  ASSERT_TRUE(builder.build(t.world, a, 0, {}, second).ok());
  ASSERT_TRUE(fresh.build(t.world, a, 0, {}, third).ok());
  EXPECT_GT(first.cells.size(), 3u);
  EXPECT_TRUE(first == second);
  EXPECT_TRUE(first == third);
  EXPECT_FALSE(first == other);
}

// Property (frames do not matter): visibility depends on world-space geometry only, so worlds that
// differ only in their cell frames (random, other random, identity) give identical results.
TEST(PortalTraversal, CellFramesDoNotChangeTheResult) {
  WorldOptions o1, o2, o3;
  o1.frame_seed = 1;
  o2.frame_seed = 99;
  o3.identity_frames = true;
  const TestWorld t1 = make_grid(4, 4, o1), t2 = make_grid(4, 4, o2), t3 = make_grid(4, 4, o3);
  ASSERT_NE(t1.world.cells[3].cell_to_world, t2.world.cells[3].cell_to_world);
  VisibilityBuilder builder;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int k = 0; k < 20; ++k) {
    const glm::vec3 eye(0.5f + 15.0f * u(rng), 1.5f, 0.5f + 15.0f * u(rng));
    const uint32_t start = uint32_t(std::floor(eye.z / 4.0f) * 4 + std::floor(eye.x / 4.0f));
    const View view = t1.view(eye, eye + glm::vec3(u(rng) - 0.5f, 0.0f, u(rng) - 0.5f));
    const VisibleSet v1 = build_or_fail(builder, t1.world, view, start);
    EXPECT_TRUE(v1 == build_or_fail(builder, t2.world, view, start));
    EXPECT_TRUE(v1 == build_or_fail(builder, t3.world, view, start));
  }
}

// Either stored winding of the portal polygons gives the same visible cells.
TEST(PortalTraversal, PortalWindingDoesNotMatter) {
  WorldOptions reversed;
  reversed.reverse_portal_winding = true;
  const TestWorld a = make_grid(4, 3), b = make_grid(4, 3, reversed);
  ASSERT_NE(a.world.portals[0].polygon_world, b.world.portals[0].polygon_world);
  VisibilityBuilder builder;
  const View view = a.view({1.0f, 1.5f, 1.0f}, {15.0f, 1.0f, 11.0f});
  const VisibleSet va = build_or_fail(builder, a.world, view, 0);
  const VisibleSet vb = build_or_fail(builder, b.world, view, 0);
  EXPECT_GT(va.cells.size(), 2u);
  EXPECT_EQ(visible_cells(va), visible_cells(vb));
}

TEST(PortalTraversal, BadInputsAreStatusErrors) {
  const TestWorld t = make_chain(3);
  VisibilityBuilder builder;
  VisibleSet out;
  View nan_view = t.view({1.0f, 1.0f, 0.0f}, {5.0f, 1.0f, 0.0f});
  nan_view.eye_world.y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(builder.build(t.world, nan_view, 0, {}, out).ok());
  EXPECT_TRUE(out.cells.empty());
  View same = t.view({1.0f, 1.0f, 0.0f}, {1.0f, 1.0f, 0.0f});
  EXPECT_FALSE(builder.build(t.world, same, 0, {}, out).ok());
  const View good = t.view({1.0f, 1.0f, 0.0f}, {5.0f, 1.0f, 0.0f});
  EXPECT_FALSE(builder.build(t.world, good, 3, {}, out).ok());
  VisibilityOptions bad;
  bad.snap_lattice_cells = 1000;
  EXPECT_FALSE(builder.build(t.world, good, 0, bad, out).ok());
  bad = {};
  bad.max_region_polygons = 0;
  EXPECT_FALSE(builder.build(t.world, good, 0, bad, out).ok());
  EXPECT_TRUE(builder.build(t.world, good, 0, {}, out).ok());
}

}  // namespace
}  // namespace lintel
