// The doorway timelines walk like a person: the eye starts in a known cell, every segment either
// stays in its cell or crosses one of that cell's portals well inside the polygon, and no segment
// passes through a shell triangle (brute force over all shells).
#include "gen_test_support.h"
#include "generate/walk_timeline.h"

#include <lintel/scene_gen.h>
#include <lintel/timeline.h>

#include <gtest/gtest.h>

#include <cmath>

namespace lintel {
namespace {

struct Case {
  std::string label;
  SceneDesc scene;
  std::string start_cell;
  size_t min_crossings;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  out.push_back({"cottage", generate_cottage({1}), "outside", 6});
  out.push_back({"cottage seed 5", generate_cottage({5}), "outside", 6});
  out.push_back({"grid 1x1", generate_grid({1, 1, false, 1}), "room_0_0", 0});
  out.push_back({"grid 3x4", generate_grid({3, 4, false, 1}), "room_0_0", 5});
  out.push_back({"grid 8x8 jitter", generate_grid({8, 8, true, 4}), "room_0_0", 12});
  out.push_back({"grid 16x16", generate_grid({16, 16, false, 1}), "room_0_0", 12});
  for (uint32_t n : {2u, 3u, 4u, 5u, 64u})
    out.push_back({"ring " + std::to_string(n), generate_ring({n, 1}), "ring_0", std::min(n, 12u)});
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    RandomOptions o;
    o.seed = seed;
    o.cells = uint32_t(2 + seed * 5);
    o.storeys = uint32_t(1 + seed % 3);
    out.push_back({"random seed " + std::to_string(seed), generate_random(o), "cell_0", 1});
  }
  return out;
}

TEST(DoorwayTimeline, WalksThroughPortalsNeverThroughWalls) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.label);
    World world;
    ASSERT_TRUE(gen_test::load(c.scene, c.label, world, true));
    const int t = world.find_timeline("doorway");
    ASSERT_GE(t, 0);
    const Timeline& tl = world.timelines[size_t(t)];
    EXPECT_GE(tl.fps, 30.0);
    EXPECT_LE(tl.fps, 60.0);
    EXPECT_DOUBLE_EQ(tl.fov_y_deg, 70.0);
    EXPECT_NEAR(tl.aspect, 16.0 / 9.0, 1e-6);
    const std::vector<gen_test::OwnedTriangle> shells = gen_test::world_triangles(world, false);

    int cell = world.find_cell(c.start_cell);
    ASSERT_GE(cell, 0);
    size_t crossings = 0;
    for (size_t k = 0; k < tl.keys.size(); ++k) {
      const glm::dvec3 eye(tl.keys[k].eye_world);
      if (k == 0) {
        EXPECT_TRUE(gen_test::in_volume_box(world.cells[size_t(cell)], eye))
            << "the first key is not in " << c.start_cell;
        continue;
      }
      const glm::dvec3 from(tl.keys[k - 1].eye_world);
      for (const gen_test::OwnedTriangle& tri : shells) {
        const double hit = gen_test::ray_triangle(from, eye - from, tri);
        EXPECT_FALSE(hit >= 0.0 && hit <= 1.0)
            << "segment " << k << " passes through a shell triangle of " << world.cells[tri.cell].name;
        if (hit >= 0.0 && hit <= 1.0) break;
      }
      // At most one portal of the current cell, crossed well inside; no other portal at all.
      int next = cell;
      for (const PortalLink& link : world.cells[size_t(cell)].links) {
        const double margin = gen_test::portal_crossing_margin(world.portals[link.portal], from, eye);
        if (margin < 0.0) continue;
        EXPECT_EQ(next, cell) << "segment " << k << " crosses two portals";
        EXPECT_GT(margin, 0.3) << "segment " << k << " crosses " << world.portals[link.portal].name << " near its edge";
        next = int(link.neighbour);
        ++crossings;
      }
      for (uint32_t p = 0; p < world.portals.size(); ++p) {
        const Portal& portal = world.portals[p];
        const bool own = portal.from == uint32_t(cell) || portal.to == uint32_t(cell);
        if (own) continue;
        EXPECT_LT(gen_test::portal_crossing_margin(portal, from, eye), 0.0)
            << "segment " << k << " crosses " << portal.name << " of other cells";
      }
      cell = next;
      EXPECT_TRUE(gen_test::in_volume_box(world.cells[size_t(cell)], eye))
          << "key " << k << " is outside the volume box of " << world.cells[size_t(cell)].name;
    }
    EXPECT_GE(crossings, c.min_crossings);
  }
}

// gen::walk_timeline with runs: 40 jumps after runs of every length from 0.01 m to 4 m, so
// that their ends fall at every phase of the 60 fps frame grid. Each jump's keys are 1 ms apart
// and no frame time i / fps comes within kJumpMarginMs of them; sampled at every frame, an eye
// is in one run's stretch or the other's, never between (the runs lie 100 m apart); a last run of
// one waypoint is held for a frame. One run gives walk_timeline's keys exactly.
TEST(WalkTimeline, JumpsFallBetweenFramesAndNoFrameSamplesBetweenThePlaces) {
  std::vector<std::vector<glm::dvec3>> runs;
  for (int r = 0; r < 41; ++r) {
    const double length = 0.01 + 0.0997 * r;  // metres walked in this run
    const glm::dvec3 start(100.0 * r, 1.6, 0.0);
    runs.push_back({start, start + glm::dvec3(0.0, 0.0, -length)});
  }
  runs.push_back({glm::dvec3(5000.0, 1.6, 0.0)});  // a last run of one waypoint
  const Timeline t = gen::walk_timeline("jumps", 60.0, runs);
  size_t jumps = 0;
  for (size_t i = 0; i + 1 < t.keys.size(); ++i) {
    const TimelineKey &a = t.keys[i], &b = t.keys[i + 1];
    ASSERT_GT(b.t, a.t);
    if (glm::length(b.eye_world - a.eye_world) < 50.0f) continue;
    ++jumps;
    EXPECT_NEAR(b.t - a.t, 0.001, 1e-12) << i;
    for (size_t f = 0; f < timeline_frame_count(t); ++f) {
      const double ft = t.keys.front().t + double(f) / t.fps;
      EXPECT_FALSE(ft > a.t - gen::kJumpMarginMs * 1e-3 + 1e-9 && ft < b.t + gen::kJumpMarginMs * 1e-3 - 1e-9)
          << "frame " << f << " at " << ft << " s, jump " << a.t << " .. " << b.t;
    }
  }
  EXPECT_EQ(jumps, runs.size() - 1);
  for (size_t f = 0; f < timeline_frame_count(t); ++f) {
    const glm::vec3 eye = sample_timeline(t, double(f) / t.fps).eye_world;
    const double along = eye.x / 100.0;  // every run stands at x = 100 r
    EXPECT_NEAR(along, std::round(along), 1e-6) << "frame " << f << " eye x " << eye.x;
  }
  EXPECT_FLOAT_EQ(sample_timeline(t, double(timeline_frame_count(t) - 1) / t.fps).eye_world.x, 5000.0f);
  // One run: the keys of the plain overload, bit for bit.
  const Timeline one = gen::walk_timeline("one", 60.0, std::vector<std::vector<glm::dvec3>>{runs[7]});
  const Timeline plain = gen::walk_timeline("one", 60.0, runs[7]);
  ASSERT_EQ(one.keys.size(), plain.keys.size());
  for (size_t i = 0; i < one.keys.size(); ++i) {
    EXPECT_EQ(one.keys[i].t, plain.keys[i].t);
    EXPECT_EQ(one.keys[i].eye_world, plain.keys[i].eye_world);
    EXPECT_EQ(one.keys[i].target_world, plain.keys[i].target_world);
  }
}

}  // namespace
}  // namespace lintel
