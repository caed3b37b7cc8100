// The generated geometry is physically consistent with its portals, as a ray caster that ignores
// portals needs: from points inside a cell (the doorway timeline's keys and points between them), rays in
// random directions first hit the cell's own shell or instances, or pass one of its portals and
// continue in the neighbour under the same rule. A ray hitting another cell's surface would mean
// a crack, a wall without its portal or an opening the portal does not cover; a ray escaping
// means a shell that is not closed (only the exterior may see the sky).
#include "gen_test_support.h"

#include <lintel/scene_gen.h>

#include <gtest/gtest.h>
#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtx/string_cast.hpp>

#include <random>

namespace lintel {
namespace {

struct Walker {
  const World& world;
  std::vector<gen_test::OwnedTriangle> triangles;
  double tolerance;  // rays passing this close to a portal outline are ambiguous and skipped
  int exterior = -1;
  size_t rays = 0, ambiguous = 0, failures = 0;

  void walk(uint32_t cell, glm::dvec3 origin, const glm::dvec3& dir) {
    ++rays;
    for (int depth = 0; depth < 64; ++depth) {
      double t_hit = INFINITY;
      const gen_test::OwnedTriangle* hit = nullptr;
      for (const auto& tri : triangles) {
        const double t = gen_test::ray_triangle(origin, dir, tri);
        if (t > 1e-9 && t < t_hit) t_hit = t, hit = &tri;
      }
      double t_portal = INFINITY, margin_at = 0.0;
      uint32_t next = cell;
      bool near_edge = false;
      for (const PortalLink& link : world.cells[cell].links) {
        double margin = -1.0;
        const double t = gen_test::ray_portal(world.portals[link.portal], origin, dir, margin);
        if (t > 1e-7 && t < t_portal) t_portal = t, next = link.neighbour, margin_at = margin;
        // Also a miss just outside the outline is ambiguous.
        const Portal& p = world.portals[link.portal];
        const double denom = glm::dot(glm::dvec3(p.normal_world), dir);
        if (std::fabs(denom) > 1e-12) {
          const double tp = (double(p.plane_d_world) - glm::dot(glm::dvec3(p.normal_world), origin)) / denom;
          if (tp > 0.0 && tp <= t_hit + tolerance) {
            double m = 0.0;
            gen_test::ray_portal(p, origin, dir, m);
            near_edge |= std::fabs(m) < tolerance;
          }
        }
      }
      if (t_portal < INFINITY &&
          t_portal <= t_hit + tolerance) {  // through the portal (a one-way plug sits on its plane)
        if (margin_at < tolerance) return void(++ambiguous);
        origin += t_portal * dir;
        cell = next;
        continue;
      }
      if (!hit) {
        if (int(cell) != exterior) {
          ++failures;
          ADD_FAILURE() << "ray escapes from " << world.cells[cell].name;
        }
        return;
      }
      if (hit->cell == cell) return;
      if (near_edge) return void(++ambiguous);
      ++failures;
      if (failures <= 5)
        ADD_FAILURE() << "ray in " << world.cells[cell].name << " from " << glm::to_string(origin) << " along "
                      << glm::to_string(dir) << " hits " << world.cells[hit->cell].name
                      << (hit->instance >= 0 ? " (instance)" : " (shell)") << " at "
                      << glm::to_string(origin + t_hit * dir) << " triangle " << glm::to_string(hit->a)
                      << glm::to_string(hit->b) << glm::to_string(hit->c);
      return;
    }
  }
};

void check_scene(const SceneDesc& scene, const std::string& label, const std::string& start, double tolerance) {
  SCOPED_TRACE(label);
  World world;
  ASSERT_TRUE(gen_test::load(scene, label, world));
  Walker w{world, gen_test::world_triangles(world, true), tolerance, world.find_cell("outside")};
  const Timeline& tl = world.timelines[size_t(world.find_timeline("doorway"))];
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  // Track the eye's cell along the walk (the timeline test checks the walk itself).
  int cell = world.find_cell(start);
  ASSERT_GE(cell, 0);
  for (size_t k = 0; k < tl.keys.size(); ++k) {
    const glm::dvec3 eye(tl.keys[k].eye_world);
    if (k > 0) {
      const glm::dvec3 from(tl.keys[k - 1].eye_world);
      // Not the midpoint: a walk through a door puts that exactly on the portal's plane.
      const glm::dvec3 mid = from + 0.37 * (eye - from);
      int mid_cell = cell;
      for (const PortalLink& link : world.cells[size_t(cell)].links) {
        if (gen_test::portal_crossing_margin(world.portals[link.portal], from, mid) > 0.0)
          mid_cell = int(link.neighbour);
        if (gen_test::portal_crossing_margin(world.portals[link.portal], from, eye) > 0.0) cell = int(link.neighbour);
      }
      for (int r = 0; r < 48; ++r) {
        glm::dvec3 d;
        do d = {u(rng), u(rng), u(rng)};
        while (glm::dot(d, d) > 1.0 || glm::dot(d, d) < 1e-3);
        w.walk(uint32_t(mid_cell), mid, glm::normalize(d));
      }
    }
    for (int r = 0; r < 48; ++r) {
      glm::dvec3 d;
      do d = {u(rng), u(rng), u(rng)};
      while (glm::dot(d, d) > 1.0 || glm::dot(d, d) < 1e-3);
      w.walk(uint32_t(cell), eye, glm::normalize(d));
    }
  }
  EXPECT_EQ(w.failures, 0u) << w.rays << " rays";
  EXPECT_LT(w.ambiguous * 50, w.rays) << "too many ambiguous rays";
}

// World::Portal's contract: the normal points from `from` into `to`. Just behind the polygon's
// centroid lies `from`'s volume, just in front `to`'s (cells with volume meshes only).
void check_portal_sides(const SceneDesc& scene, const std::string& label) {
  SCOPED_TRACE(label);
  World world;
  ASSERT_TRUE(gen_test::load(scene, label, world));
  size_t checked = 0;
  for (const Portal& p : world.portals) {
    const Cell &from = world.cells[p.from], &to = world.cells[p.to];
    if (from.volume_triangles_cell.empty() || to.volume_triangles_cell.empty()) continue;
    const glm::dvec3 c(p.centroid_world), n(p.normal_world);
    EXPECT_TRUE(gen_test::in_volume(from, c - 0.05 * n) && gen_test::in_volume(to, c + 0.05 * n))
        << p.name << " (" << from.name << " -> " << to.name << ") has its normal the wrong way round";
    ++checked;
  }
  EXPECT_GT(checked, 0u);
}

TEST(GeometryConsistency, PortalNormalsPointIntoTo) {
  check_portal_sides(generate_cottage({1}), "cottage");
  check_portal_sides(generate_grid({3, 3, true, 1}), "grid 3x3 jitter");
  check_portal_sides(generate_ring({2, 1}), "ring 2");
  check_portal_sides(generate_ring({6, 1}), "ring 6");
  RandomOptions o;
  o.cells = 30;
  o.storeys = 3;
  o.volume_fraction = 1.0;
  o.one_way_fraction = 0.5;
  check_portal_sides(generate_random(o), "random");
}

TEST(GeometryConsistency, Cottage) { check_scene(generate_cottage({1}), "cottage", "outside", 1e-4); }
TEST(GeometryConsistency, Grid) {
  check_scene(generate_grid({4, 3, false, 1}), "grid 4x3", "room_0_0", 1e-4);
  check_scene(generate_grid({5, 5, true, 9}), "grid 5x5 jitter", "room_0_0", 1e-4);
}
TEST(GeometryConsistency, Ring) {
  for (uint32_t n : {2u, 3u, 4u, 7u, 16u})
    check_scene(generate_ring({n, 1}), "ring " + std::to_string(n), "ring_0", 1e-4);
}
TEST(GeometryConsistency, Random) {
  for (uint64_t seed = 1; seed <= 8; ++seed) {
    RandomOptions o;
    o.seed = seed;
    o.cells = uint32_t(10 + seed * 4);
    o.storeys = 3;
    o.one_way_fraction = 0.5;
    // Frames 1e4 m away at scale 0.1 leave ~1 mm of float error in the world: a matching tolerance.
    check_scene(generate_random(o), "random seed " + std::to_string(seed), "cell_0", 5e-3);
  }
}

}  // namespace
}  // namespace lintel
