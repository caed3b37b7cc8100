// Disocclusion under two-phase occlusion culling (portal+hiz, hiz_method.cpp): frames in sequence,
// each with the visibility the previous frame left, every frame checked against the Embree ray
// cast. The danger the two-phase scheme exists for: an object hidden last frame is not drawn
// first, and if the second phase did not test it against this frame's pyramid it would be missing
// for a frame when it comes out from behind a wall. (Checked by hand: drawing only what passed
// last frame's test fails the few-steps slide and back-away paths and the cottage walk.)
#include <lintel/reference/cull_method.h>
#include <lintel/reference/ray_ground_truth.h>
#include <lintel/reference/bench_views.h>
#include <lintel/ndc_snap.h>
#include <lintel/scene_io.h>
#include <lintel/timeline.h>
#include <lintel/viewer_tracker.h>

#include "box_cells.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace lintel {
namespace {

// One room (12 x 3 x 12 m, shell facing in) with a free-standing wall across its middle and a
// crate 2 m behind the wall's centre, a second crate off to the side.
World room_with_wall() {
  SceneDesc scene;
  const int room = test::add_box_cell(scene, "room", {-6, 0, -6}, {6, 3, 6},
                                      test::inward_box_mesh("room shell", {-6, 0, -6}, {6, 3, 6}));
  auto add_instance = [&](const std::string& name, glm::vec3 lo, glm::vec3 hi) {
    test::add_box_instance(scene, room, name, lo, hi);
  };
  add_instance("wall", {-2, 0, -0.1f}, {2, 2.5f, 0.1f});
  add_instance("crate", {-0.4f, 0, -2.4f}, {0.4f, 0.8f, -1.6f});
  add_instance("side crate", {-5, 0, -3}, {-4.2f, 0.8f, -2.2f});
  World world;
  EXPECT_TRUE(build_world(scene, "room with wall", world).ok());
  return world;
}

struct WalkCounts {
  uint32_t frames = 0;
  uint32_t seen = 0;           // (frame, instance) pairs the rays see
  uint32_t appeared = 0;       // ... that the rays did not see the frame before (frame 0 excepted)
  uint32_t hidden_culled = 0;  // (frame, instance) pairs the portal set has and occlusion removes
};

// Runs `views` in order through one portal+hiz method (history carried from frame to frame) and
// the ray cast; returns the counts, failing the test on any instance the rays see that is not
// drawn. The start cell comes from a viewer tracker, as in a game.
WalkCounts walk(const World& world, const std::vector<View>& views, const std::string& what) {
  RayGroundTruth rays;
  EXPECT_TRUE(rays.build(world).ok());
  auto hiz = make_portal_hiz_method(64, HizHistory::Cut);  // Cut: history is whatever run() saw last
  auto polygon = make_polygon_method(kDefaultSnapLatticeCells, 16);
  ViewerTracker tracker;
  GroundTruth gt;
  MethodResult r, p;
  std::vector<uint8_t> seen_before(world.instances.size(), 0);
  WalkCounts n;
  for (size_t f = 0; f < views.size(); ++f) {
    const View& view = views[f];
    EXPECT_TRUE((f == 0 ? tracker.reset(world, view.eye_world) : tracker.update(world, view.eye_world)).ok());
    EXPECT_TRUE(hiz->run(world, view, tracker.cell(), r).ok());
    EXPECT_TRUE(polygon->run(world, view, tracker.cell(), p).ok());
    rays.cast(ray_camera_of(view), 96, gt);
    ++n.frames;
    for (size_t i = 0; i < world.instances.size(); ++i) {
      if (gt.instance_visible[i]) {
        ++n.seen;
        n.appeared += f > 0 && !seen_before[i];
        // The property: what a ray sees is drawn, in every frame, also the first frame it is seen.
        EXPECT_TRUE(r.instance_visible[i])
            << what << ": frame " << f << ": instance " << world.instances[i].name << " seen by the rays but not drawn"
            << (seen_before[i] ? "" : " (it just appeared)");
      }
      n.hidden_culled += p.instance_visible[i] && !r.instance_visible[i];
      seen_before[i] = gt.instance_visible[i];
    }
  }
  std::printf("%s: %u frames, %u seen, %u appeared, %u hidden and culled\n", what.c_str(), n.frames, n.seen, n.appeared,
              n.hidden_culled);
  return n;
}

View look(glm::vec3 eye, glm::vec3 dir) {
  View v;
  v.eye_world = eye;
  v.target_world = eye + dir;
  v.fov_y_deg = 60.0f;
  v.aspect = 16.0f / 9.0f;
  return v;
}

// Property: a crate behind a wall that comes into sight as the camera slides sideways, as it turns
// towards it, or as it backs away, is drawn on the first frame any ray sees it and on every frame
// after; while the wall hides it, occlusion culls it.
TEST(HizDisocclusion, CrateComingOutFromBehindAWallIsNeverMissing) {
  const World world = room_with_wall();
  // Each path slowly (the box starts passing the test a frame or two before a ray sees the crate)
  // and in a few big steps (hidden in one frame, plainly visible in the next: a renderer that drew
  // only last frame's survivors would miss it there).
  for (const int frames : {90, 6}) {
    std::vector<View> slide, turn, back;
    for (int f = 0; f <= frames; ++f) {
      const float s = float(f) / float(frames);
      slide.push_back(look({-3.0f + 8.0f * s, 1.2f, 2.0f}, {0, -0.15f, -1}));
      const float a = glm::radians(-100.0f + 110.0f * s);  // from facing away (+x, +z) to the crate
      turn.push_back(look({3.5f, 1.0f, 1.0f}, {std::sin(a), -0.1f, -std::cos(a)}));
      back.push_back(look({0.3f, 0.9f, 0.4f + 5.0f * s}, {0, -0.05f, -1}));
    }
    for (const auto& [name, views] : {std::pair{"slide", slide}, {"turn", turn}, {"back away", back}}) {
      const std::string what = std::string(name) + " in " + std::to_string(frames) + " steps";
      const WalkCounts n = walk(world, views, what);
      EXPECT_GT(n.appeared, 0u) << what << ": nothing came into sight";
      EXPECT_GT(n.hidden_culled, 0u) << what << ": occlusion never culled anything";
    }
  }
}

// Property: along the committed scenes' camera timelines, frame by frame (portal crossings, turns,
// objects of the next room appearing through doors), every instance a ray sees is drawn.
TEST(HizDisocclusion, TimelineWalksThroughPortalsMissNothing) {
  for (const char* name : {"cottage", "grid16"}) {
    World world;
    ASSERT_TRUE(load_world(std::string(LINTEL_SOURCE_DIR) + "/scenes/" + name + ".gltf", world).ok());
    ASSERT_FALSE(world.timelines.empty());
    const Timeline& tl = world.timelines[0];
    std::vector<View> views;
    const size_t frames = timeline_frame_count(tl), step = std::string(name) == "cottage" ? 2 : 4;
    for (size_t f = 0; f < frames; f += step)
      views.push_back(timeline_view(tl, tl.keys.front().t + double(f) / tl.fps));
    const WalkCounts n = walk(world, views, name);
    EXPECT_GT(n.appeared, 5u) << name;
    EXPECT_GT(n.hidden_culled, 0u) << name;
  }
}

}  // namespace
}  // namespace lintel
