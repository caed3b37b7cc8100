// The viewer tracker's hysteresis band and its agreement with containment: a resting eye in a
// doorway does not flap, a walk through switches once, and an eye placed on a portal plane (a
// player start on a two-sided line) is followed into either cell without a stale frame.
#include "ray_walk.h"
#include "test_worlds.h"

#include <lintel/cell_locate.h>
#include <lintel/doorway_rule.h>
#include <lintel/viewer_tracker.h>
#include <lintel/visibility_builder.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace lintel {
namespace {

using testing::TestWorld;
using testing::WorldBuilder;

// The eye moved `offset_m` along the portal normal from its plane, at a point of its polygon.
glm::vec3 off_plane(const Portal& p, const glm::dvec3& on_plane, double offset_m) {
  return glm::vec3(on_plane + glm::dvec3(p.normal_world) * offset_m);
}

glm::dvec3 project_to_plane(const Portal& p, const glm::dvec3& x) {
  const glm::dvec3 n(p.normal_world);
  return x - n * (glm::dot(n, x) - double(p.plane_d_world));
}

TEST(TrackerHysteresis, BandIsScaleAwareAndBounded) {
  const TestWorld near_origin =
      testing::make_chain(2, {.layout_to_world = testing::layout_to_world_centred_at({4, 1, 0})});
  EXPECT_DOUBLE_EQ(hysteresis_band_m(near_origin.world.portals[0]), kMinHysteresisBand_m);
  // 1 km away the float ulp term takes over (8 ulps of ~1000 m ~ 0.95 mm), still under the cap.
  glm::mat4 far = glm::translate(glm::mat4(1.0f), glm::vec3(1000.0f, 0.0f, 0.0f));
  const TestWorld far_away = testing::make_chain(2, {.layout_to_world = far});
  const double band = hysteresis_band_m(far_away.world.portals[0]);
  EXPECT_GT(band, 5e-4);
  EXPECT_LE(band, kMaxHysteresisBand_m);
  // A tiny portal caps the band at 1 % of its inradius.
  const TestWorld slit = testing::make_chain(2, {.layout_to_world = far, .door_half_width = 0.02f});
  EXPECT_LE(hysteresis_band_m(slit.world.portals[0]), 0.01 * 0.02 + 1e-9);
}

// A person at rest in a doorway (the lesson's case: +-1..3 um of jitter every frame for 3 s at
// 60 fps, on the plane and along it) never switches cell, whichever side it was placed on.
TEST(TrackerHysteresis, MicrometreJitterInADoorwayNeverSwitches) {
  const TestWorld t = testing::make_chain(3, {.layout_to_world = testing::layout_to_world_centred_at({8, 1.3f, 0})});
  const Portal& door = t.world.portals[1];
  const glm::dvec3 centre = project_to_plane(door, glm::dvec3(t.to_world({8.0f, 1.3f, 0.0f})));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-3e-6, 3e-6);
  for (double start : {-2e-6, 0.0, 2e-6}) {
    ViewerTracker tracker;
    ASSERT_TRUE(tracker.reset(t.world, off_plane(door, centre, start)).ok());
    const uint32_t placed = tracker.cell();
    int switches = 0;
    for (int frame = 0; frame < 180; ++frame) {
      const glm::dvec3 lateral =
          glm::dvec3(t.dir_to_world({0, 1, 0})) * jitter(rng) + glm::dvec3(t.dir_to_world({0, 0, 1})) * jitter(rng);
      ASSERT_TRUE(tracker.update(t.world, off_plane(door, centre + lateral, jitter(rng))).ok());
      switches += int(tracker.transitions().size());
    }
    EXPECT_EQ(switches, 0) << "start offset " << start;
    EXPECT_EQ(tracker.cell(), placed);
  }
}

// Two rooms of different size, so that containment of a point on the shared plane picks the
// smaller one, which is `to` in one layout and `from` in the other (the reduced field case).
// Axis-aligned (identity frames): a start at x = 4 is then exactly on the plane, as in the field.
World two_rooms(bool small_is_to, bool axis_aligned, uint32_t& small, uint32_t& big) {
  testing::WorldOptions options;
  options.identity_frames = axis_aligned;
  WorldBuilder b(axis_aligned ? glm::mat4(1.0f) : testing::default_layout_to_world(), options);
  const uint32_t a = b.add_box_cell("a", {0, 0, -2}, {4, 3, 2});
  const uint32_t c = b.add_box_cell("c", {4, 0, -1.5f}, {6, 3, 1.5f});  // smaller
  const std::vector<glm::vec3> door{{4, 0, -0.6f}, {4, 0, 0.6f}, {4, 2.2f, 0.6f}, {4, 2.2f, -0.6f}};
  if (small_is_to)
    b.add_portal(a, c, door, {3, 1, 0}, true);
  else
    b.add_portal(c, a, door, {5, 1, 0}, true);
  small = c;
  big = a;
  return b.finish();
}

// Regression (blank screen): a start exactly on a portal plane, then a walk into either room.
// Containment and the side rule agree (the plane belongs to whichever cell is tracked), so the
// walk into the other room is one portal crossing once the eye is a band past the plane; on no
// frame is the eye farther than the band outside the tracked cell, and the visible set holds
// every cell a ray from the eye sees (ray walks from the cell that really contains the eye).
TEST(TrackerHysteresis, StartOnAPortalPlaneFollowsTheWalkIntoEitherRoom) {
  for (int variant = 0; variant < 4; ++variant) {
    const bool small_is_to = variant & 1, axis_aligned = variant & 2;
    uint32_t small = 0, big = 0;
    const World w = two_rooms(small_is_to, axis_aligned, small, big);
    const testing::TestWorld t{w, axis_aligned ? glm::mat4(1.0f) : testing::default_layout_to_world()};
    const Portal& door = w.portals[0];
    const double band = hysteresis_band_m(door);
    const glm::dvec3 start =
        axis_aligned ? glm::dvec3(4.0, 1.5, 0.1f) : project_to_plane(door, glm::dvec3(t.to_world({4.0f, 1.5f, 0.1f})));
    for (float into_x : {2.0f, 5.5f}) {  // walk into the big room, then into the small one
      ViewerTracker tracker;
      ASSERT_TRUE(tracker.reset(w, glm::vec3(start)).ok());
      const uint32_t placed = tracker.cell();  // either room: the eye is on the plane of both
      const uint32_t destination = into_x < 4.0f ? big : small;
      VisibilityBuilder builder;
      int switches = 0;
      for (int frame = 1; frame <= 12; ++frame) {
        const float x = 4.0f + (into_x - 4.0f) * float(frame) / 12.0f;
        const glm::vec3 eye_layout(x, 1.5f, 0.1f);
        const glm::vec3 eye = t.to_world(eye_layout);
        ASSERT_TRUE(tracker.update(w, eye).ok());
        for (const CellTransition& tr : tracker.transitions()) {
          ++switches;
          EXPECT_EQ(tr.reason, TransitionReason::PortalCrossing);
        }
        EXPECT_LE(cell_volume_distance_m(w, tracker.cell(), glm::dvec3(eye)), band)
            << "variant " << variant << " frame " << frame;
        const View view = t.view(eye_layout, eye_layout + glm::vec3(into_x < 4.0f ? 1.0f : -1.0f, 0.0f, 0.2f));
        VisibleSet visible;
        ASSERT_TRUE(builder.build(w, view, tracker.cell(), {}, visible).ok());
        const uint32_t truth_cell = locate_cell(w, glm::dvec3(eye)).cell;
        for (int k = 0; k < 64; ++k) {
          const glm::dvec2 ndc(-0.95 + 1.9 * (k % 8) / 7.0, -0.95 + 1.9 * (k / 8) / 7.0);
          const testing::RayWalk walk = testing::walk_view_ray(w, view, truth_cell, ndc);
          if (walk.ambiguous) continue;
          for (uint32_t c : walk.seen_cells) {
            const VisibleCell* vc = visible.find(c);
            ASSERT_NE(vc, nullptr) << "frame " << frame << ": cell " << c << " seen by a ray is not visible";
            EXPECT_TRUE(visible.region(*vc).contains(ndc, 1e-6)) << "frame " << frame << " cell " << c;
          }
        }
      }
      EXPECT_EQ(tracker.cell(), destination);
      EXPECT_EQ(switches, placed == destination ? 0 : 1) << "variant " << variant << " into " << into_x;
    }
  }
}

// Property (placement on portal planes): for random eyes on random portal planes of grids and
// rings (non-identity frames, cyclic graphs), each followed by a short walk in a random direction
// looking anywhere, (a) the tracked cell never lies farther than the largest hysteresis band from
// the eye, and (b) every cell that a ray from the eye sees (walked from each cell whose volume
// contains the eye) is visible with the ray's pixel in its region.
TEST(TrackerHysteresis, PlacementsOnPortalPlanesNeverLeaveAStaleCell) {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const std::vector<TestWorld> worlds = {testing::make_grid(3, 3, {.frame_seed = 3}),
                                         testing::make_ring(5, {.frame_seed = 9})};
  int frames_checked = 0, rays_checked = 0;
  for (const TestWorld& t : worlds) {
    double max_band = 0.0;
    for (const Portal& p : t.world.portals) max_band = std::max(max_band, hysteresis_band_m(p));
    VisibilityBuilder builder;
    for (int placement = 0; placement < 40; ++placement) {
      const Portal& portal = t.world.portals[size_t(u(rng) * float(t.world.portals.size())) % t.world.portals.size()];
      // A point of the polygon (convex combination of three vertices), exactly on its plane.
      const auto& poly = portal.polygon_world;
      float a = u(rng), b = u(rng) * (1.0f - a);
      const glm::dvec3 p0 = glm::dvec3(poly[0]) * double(1.0f - a - b) + glm::dvec3(poly[1]) * double(a) +
                            glm::dvec3(poly[2]) * double(b);
      glm::dvec3 eye = project_to_plane(portal, glm::mix(p0, glm::dvec3(portal.centroid_world), 0.5));
      // Mostly across the plane (either way), a little along it: the eye stays in the opening
      // rather than walking inside a zero-thickness wall, which no portal method models.
      const glm::dvec3 n(portal.normal_world);
      const glm::dvec3 drift = glm::dvec3(u(rng) - 0.5f, 0.3f * (u(rng) - 0.5f), u(rng) - 0.5f) * 0.02;
      const glm::dvec3 step = n * (u(rng) < 0.5f ? -0.025 : 0.025) + (drift - n * glm::dot(drift, n));
      const glm::dvec3 look = glm::normalize(glm::dvec3(u(rng) - 0.5f, 0.4f * (u(rng) - 0.5f), u(rng) - 0.5f));
      ViewerTracker tracker;
      ASSERT_TRUE(tracker.reset(t.world, glm::vec3(eye)).ok());
      for (int frame = 0; frame < 10; ++frame) {
        if (frame > 0) {
          eye += step;
          ASSERT_TRUE(tracker.update(t.world, glm::vec3(eye)).ok());
        }
        const glm::dvec3 e = glm::dvec3(glm::vec3(eye));  // what the tracker was given
        ASSERT_LE(cell_volume_distance_m(t.world, tracker.cell(), e), max_band)
            << "placement " << placement << " frame " << frame;
        View view;
        view.eye_world = glm::vec3(eye);
        view.target_world = glm::vec3(eye + look);
        view.up_world = t.dir_to_world({0, 1, 0});
        VisibleSet visible;
        ASSERT_TRUE(builder.build(t.world, view, tracker.cell(), {}, visible).ok());
        ++frames_checked;
        for (uint32_t c = 0; c < t.world.cells.size(); ++c) {
          if (!cell_volume_contains(t.world, c, e)) continue;
          for (int k = 0; k < 36; ++k) {
            const glm::dvec2 ndc(-0.95 + 1.9 * (k % 6) / 5.0, -0.95 + 1.9 * (k / 6) / 5.0);
            const testing::RayWalk walk = testing::walk_view_ray(t.world, view, c, ndc);
            if (walk.ambiguous) continue;
            for (uint32_t seen : walk.seen_cells) {
              ++rays_checked;
              const VisibleCell* vc = visible.find(seen);
              ASSERT_NE(vc, nullptr) << "placement " << placement << " frame " << frame << ": cell " << seen
                                     << " seen by a ray is not visible (tracked " << tracker.cell() << ")";
              ASSERT_TRUE(visible.region(*vc).contains(ndc, 1e-6))
                  << "placement " << placement << " frame " << frame << " cell " << seen;
            }
          }
        }
      }
    }
  }
  EXPECT_GT(frames_checked, 500);
  EXPECT_GT(rays_checked, 10000);
}

}  // namespace
}  // namespace lintel
