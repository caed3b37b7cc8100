// Linear key-frame interpolation; a walk-through needs nothing smoother to test doorway crossings.
#include <lintel/timeline.h>

#include <cassert>
#include <cmath>
#include <string>

namespace lintel {
namespace {

// a + s (b - a), and exactly a when a == b: glm::mix computes a (1 - s) + b s, which is not
// exactly a in float, so a stationary stretch of a timeline would jitter by an ulp.
glm::vec3 lerp_exact(const glm::vec3& a, const glm::vec3& b, float s) { return a == b ? a : a + s * (b - a); }

}  // namespace

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
  return {lerp_exact(a.eye_world, b.eye_world, s), lerp_exact(a.target_world, b.target_world, s)};
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

Status resolve_timeline_events(const World& world, Timeline& timeline) {
  for (size_t i = 0; i < timeline.events.size(); ++i) {
    TimelineEvent& e = timeline.events[i];
    e.portal_index = world.find_portal(e.portal);
    if (e.portal_index < 0)
      return Status::error("timeline '" + timeline.name + "' event " + std::to_string(i) + ": no portal named '" +
                           e.portal + "'");
  }
  return {};
}

size_t apply_timeline_events(const Timeline& timeline, double t, size_t next, World& world) {
  while (next < timeline.events.size() && timeline.events[next].t <= t) {
    const TimelineEvent& e = timeline.events[next++];
    assert(e.portal_index >= 0 && size_t(e.portal_index) < world.portals.size());
    world.set_portal_open(uint32_t(e.portal_index), e.open);
  }
  return next;
}

size_t timeline_frame_count(const Timeline& timeline) {
  assert(!timeline.keys.empty() && timeline.fps > 0.0);
  const double duration = timeline.keys.back().t - timeline.keys.front().t;
  return static_cast<size_t>(std::floor(duration * timeline.fps + 1e-9)) + 1;
}

}  // namespace lintel
