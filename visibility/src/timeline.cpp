// Linear key-frame interpolation; a walk-through needs nothing smoother to test doorway crossings.
#include <lintel/timeline.h>

#include <cassert>
#include <cmath>

namespace lintel {

CameraPose sample_timeline(const Timeline& timeline, double t) {
  assert(!timeline.keys.empty());
  const auto& keys = timeline.keys;
  if (t <= keys.front().t) return {keys.front().eye_world, keys.front().target_world};
  if (t >= keys.back().t) return {keys.back().eye_world, keys.back().target_world};
  size_t i = 1;
  while (keys[i].t < t) ++i;
  const TimelineKey& a = keys[i - 1];
  const TimelineKey& b = keys[i];
  const float s = static_cast<float>((t - a.t) / (b.t - a.t));
  return {glm::mix(a.eye_world, b.eye_world, s), glm::mix(a.target_world, b.target_world, s)};
}

View timeline_view(const Timeline& timeline, double t) {
  const CameraPose pose = sample_timeline(timeline, t);
  View view;
  view.eye_world = pose.eye_world;
  view.target_world = pose.target_world;
  view.fov_y_deg = static_cast<float>(timeline.fov_y_deg);
  view.aspect = static_cast<float>(timeline.aspect);
  return view;
}

size_t timeline_frame_count(const Timeline& timeline) {
  assert(!timeline.keys.empty() && timeline.fps > 0.0);
  const double duration = timeline.keys.back().t - timeline.keys.front().t;
  return static_cast<size_t>(std::floor(duration * timeline.fps + 1e-9)) + 1;
}

}  // namespace lintel
