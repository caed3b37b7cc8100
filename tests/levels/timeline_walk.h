// Shared by the level tests that walk a map's doorway timeline: frame by frame, as a game would,
// with a ViewerTracker and a VisibilityBuilder.
#pragma once

#include <lintel/timeline.h>
#include <lintel/viewer_tracker.h>
#include <lintel/visibility_builder.h>

#include <gtest/gtest.h>

#include <vector>

namespace lintel::test {

struct WalkCounts {
  size_t flaps = 0;      // A -> B -> A within 3 frames
  size_t crossings = 0;  // portal crossings
};

// Walks the world's first timeline; every frame's own cell must be in its visible set (a fatal
// failure otherwise: callers check HasFatalFailure()).
inline void walk_first_timeline(const World& world, WalkCounts& out) {
  ASSERT_FALSE(world.timelines.empty());
  const Timeline& timeline = world.timelines[0];
  ViewerTracker tracker;
  VisibilityBuilder builder;
  VisibleSet visible;
  std::vector<CellTransition> history;
  std::vector<size_t> frame_of;
  for (size_t f = 0; f < timeline_frame_count(timeline); ++f) {
    const View view = timeline_view(timeline, timeline.keys.front().t + double(f) / timeline.fps);
    ASSERT_TRUE((f == 0 ? tracker.reset(world, view.eye_world) : tracker.update(world, view.eye_world)).ok());
    for (const CellTransition& tr : tracker.transitions()) {
      if (f == 0) continue;
      if (!history.empty() && history.back().to == tr.from && history.back().from == tr.to && f - frame_of.back() <= 3)
        ++out.flaps;
      out.crossings += tr.reason == TransitionReason::PortalCrossing;
      history.push_back(tr);
      frame_of.push_back(f);
    }
    ASSERT_TRUE(builder.build(world, view, tracker.cell(), {}, visible).ok());
    ASSERT_NE(visible.find(tracker.cell()), nullptr);
  }
}

}  // namespace lintel::test
