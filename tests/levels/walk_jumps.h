// Shared by the level tests of teleporter walks: a timeline's jumps (the eye moves from one place
// to another between two keys) walked frame by frame, as `lintel walk` samples it.
#pragma once

#include <lintel/cell_locate.h>
#include <lintel/timeline.h>
#include <lintel/viewer_tracker.h>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

namespace lintel::test {

inline constexpr double kWalkSpeedMps = 1.4;  // gen::kWalkSpeed

// Keys i whose move to key i + 1 is far faster than a walk: the jumps.
inline std::vector<size_t> jump_keys(const Timeline& timeline) {
  std::vector<size_t> out;
  const auto& k = timeline.keys;
  for (size_t i = 0; i + 1 < k.size(); ++i)
    if (glm::length(glm::dvec3(k[i + 1].eye_world - k[i].eye_world)) >
        2.0 * kWalkSpeedMps * (k[i + 1].t - k[i].t) + 1e-3)
      out.push_back(i);
  return out;
}

// An eye crossing a portal stands on its plane, at times a few mm outside both volumes (float
// rounding of the sectors' outlines); the tracker only re-locates beyond 1 cm
// (TrackerOptions::found_elsewhere_m). An eye sampled between a jump's two places would
// typically stand in a wall or the void, metres from any cell.
inline constexpr double kOutsideM = 0.01;

struct JumpWalk {
  size_t frames = 0;
  size_t jumps = 0;               // jump_keys
  size_t jumps_not_1ms = 0;       // jumps whose two keys are not 1 ms apart
  size_t frames_in_a_jump = 0;    // frame times within [a.t, b.t] of a jump's keys
  size_t jump_frames = 0;         // frames whose eye moved farther than the tracker's jump distance
  size_t eyes_outside_cells = 0;  // frames whose eye lies more than kOutsideM outside every cell volume
  size_t flaps = 0;               // A -> B -> A within 3 frames
  std::set<std::string> sectors;  // the tracked cells' sectors ("sector_12" of "sector_12_3")
};

// Walks `timeline` at its fps from its first key, as `lintel walk` does.
inline JumpWalk walk_with_jumps(const World& world, const Timeline& timeline) {
  JumpWalk out;
  const std::vector<size_t> jumps = jump_keys(timeline);
  out.jumps = jumps.size();
  for (size_t i : jumps) out.jumps_not_1ms += std::abs((timeline.keys[i + 1].t - timeline.keys[i].t) - 0.001) > 1e-9;
  const std::vector<double> volumes = cell_volumes_m3(world);
  ViewerTracker tracker;
  std::vector<CellTransition> history;
  std::vector<size_t> frame_of;
  glm::vec3 previous{0.0f};
  out.frames = timeline_frame_count(timeline);
  for (size_t f = 0; f < out.frames; ++f) {
    const double t = timeline.keys.front().t + double(f) / timeline.fps;
    for (size_t i : jumps) out.frames_in_a_jump += t >= timeline.keys[i].t && t <= timeline.keys[i + 1].t;
    const glm::vec3 eye = timeline_view(timeline, t).eye_world;
    out.eyes_outside_cells += locate_cell(world, glm::dvec3(eye), volumes).distance_m > kOutsideM;
    if (f > 0 && glm::length(eye - previous) > TrackerOptions{}.jump_distance_m) ++out.jump_frames;
    previous = eye;
    if (!(f == 0 ? tracker.reset(world, eye) : tracker.update(world, eye)).ok()) {
      ADD_FAILURE() << "tracker failed at frame " << f;
      return out;
    }
    for (const CellTransition& tr : tracker.transitions()) {
      if (f == 0) continue;
      if (!history.empty() && history.back().to == tr.from && history.back().from == tr.to && f - frame_of.back() <= 3)
        ++out.flaps;
      history.push_back(tr);
      frame_of.push_back(f);
    }
    std::string name = world.cells[tracker.cell()].name;
    if (std::count(name.begin(), name.end(), '_') > 1) name.erase(name.rfind('_'));
    out.sectors.insert(name);
  }
  return out;
}

}  // namespace lintel::test
