// The carry walk on a generated building (issue 11): a crate carried 1.2 m ahead of the camera of
// the generated cottage's "doorway" timeline, through its rooms. On every frame the crate is listed
// whenever the ray from the eye to its centre reaches the centre's cell through open doors (the
// ray-walk oracle: a miss would be a false negative), and every cell its reach lists it from
// overlaps its box (it is never listed from a cell it is not in).
#include "ray_walk.h"

#include <lintel/dynamic_instances.h>
#include <lintel/scene_gen.h>
#include <lintel/scene_io.h>
#include <lintel/timeline.h>
#include <lintel/viewer_tracker.h>
#include <lintel/visibility_builder.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace lintel {
namespace {

TEST(CarryWalk, ACrateCarriedThroughTheCottageIsNeverLost) {
  World world;
  ASSERT_TRUE(build_world(generate_cottage({1}), "cottage", world).ok());
  const Timeline timeline = world.timelines[size_t(std::max(0, world.find_timeline("doorway")))];
  Mesh box;
  box.name = "crate";
  box.bounds_mesh.extend(glm::vec3(-0.2f));
  box.bounds_mesh.extend(glm::vec3(0.2f));
  world.meshes.push_back(box);
  world.groups.push_back({uint32_t(world.meshes.size() - 1), {}});
  auto carried_at = [&](const View& v) {
    const glm::vec3 ahead = glm::normalize(v.target_world - v.eye_world);
    return v.eye_world + 1.2f * ahead - glm::vec3(0.0f, 0.3f, 0.0f);
  };
  const View first = timeline_view(timeline, timeline.keys.front().t);
  ViewerTracker tracker;
  ASSERT_TRUE(tracker.reset(world, first.eye_world).ok());
  Instance crate;
  crate.name = "crate";
  crate.mesh = uint32_t(world.meshes.size() - 1);
  crate.group = uint32_t(world.groups.size() - 1);
  crate.cell = tracker.cell();
  crate.mesh_to_world = glm::translate(glm::mat4(1.0f), carried_at(first));
  const uint32_t id = uint32_t(world.instances.size());
  world.instances.push_back(crate);
  const Status finalized = finalize_world(world);
  ASSERT_TRUE(finalized.ok()) << finalized.message();

  DynamicInstances movers;
  ASSERT_TRUE(movers.reset(world).ok());
  VisibilityBuilder builder;
  VisibleSet visible;
  std::set<uint32_t> cells_carried_through;
  size_t judged = 0;
  const size_t frames = timeline_frame_count(timeline);
  for (size_t f = 0; f < frames; ++f) {
    const View view = timeline_view(timeline, timeline.keys.front().t + double(f) / timeline.fps);
    ASSERT_TRUE(movers.move(world, id, glm::translate(glm::mat4(1.0f), carried_at(view))).ok());
    movers.take_moved();
    builder.instances_moved(world, movers);
    ASSERT_TRUE((f == 0 ? tracker.reset(world, view.eye_world) : tracker.update(world, view.eye_world)).ok());
    ASSERT_TRUE(builder.build(world, view, tracker.cell(), {}, visible).ok());
    const Instance& inst = world.instances[id];
    cells_carried_through.insert(inst.cell);
    const glm::dvec4 clip = view_projection_d(view) * glm::dvec4(glm::dvec3(inst.bounds_world.center()), 1.0);
    const testing::RayWalk walk = testing::walk_view_ray(world, view, tracker.cell(), glm::dvec2(clip) / clip.w);
    const bool centre_seen = !walk.ambiguous && std::find(walk.seen_cells.begin(), walk.seen_cells.end(), inst.cell) !=
                                                    walk.seen_cells.end();
    if (centre_seen) {
      ++judged;
      EXPECT_TRUE(std::binary_search(visible.instances.begin(), visible.instances.end(), id)) << "frame " << f;
    }
    for (const uint32_t* c = movers.reach().begin(id); c != movers.reach().end(id); ++c) {
      const Cell& cell = world.cells[*c];
      EXPECT_TRUE(boxes_overlap(inst.bounds_world, transform_aabb(cell.cell_to_world, cell.volume_box_cell)))
          << "frame " << f << " cell " << cell.name;
    }
  }
  EXPECT_GE(cells_carried_through.size(), 3u) << "carried through at least three rooms";
  EXPECT_GE(judged * 10, frames * 8) << "the oracle judged most frames (" << judged << " of " << frames << ")";
}

}  // namespace
}  // namespace lintel
