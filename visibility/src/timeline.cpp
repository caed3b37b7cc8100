// Linear key-frame interpolation; a walk-through needs nothing smoother to test doorway crossings.
#include <lintel/timeline.h>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
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

Status resolve_timeline_instances(const World& world, Timeline& timeline, std::vector<InstanceTrack>& tracks) {
  tracks.clear();
  std::vector<int> track_of(world.instances.size(), -1);
  for (size_t k = 0; k < timeline.instance_keys.size(); ++k) {
    TimelineInstanceKey& key = timeline.instance_keys[k];
    const std::string where = "timeline '" + timeline.name + "' instance key " + std::to_string(k) + ": ";
    key.instance_index = -1;
    // The instances of that name must be one placed object: the parts of a mesh of several
    // materials (one instance per material, the node's transform each) move together.
    for (size_t i = 0; i < world.instances.size(); ++i) {
      if (world.instances[i].name != key.instance) continue;
      if (key.instance_index < 0) {
        key.instance_index = int(i);
      } else if (world.instances[i].mesh_to_world != world.instances[size_t(key.instance_index)].mesh_to_world) {
        return Status::error(where + "more than one instance is named '" + key.instance + "'");
      }
    }
    if (key.instance_index < 0) return Status::error(where + "no instance named '" + key.instance + "'");
    for (size_t i = size_t(key.instance_index); i < world.instances.size(); ++i) {
      if (world.instances[i].name != key.instance) continue;
      int& track = track_of[i];
      if (track < 0) {
        track = int(tracks.size());
        InstanceTrack fresh;
        fresh.instance = uint32_t(i);
        const glm::mat4& m = world.instances[i].mesh_to_world;
        fresh.linear = glm::mat3(m);
        fresh.resolved_translation = glm::vec3(m[3]);
        tracks.push_back(std::move(fresh));
      }
      tracks[size_t(track)].keys.push_back(uint32_t(k));
    }
  }
  return {};
}

namespace {

glm::quat quat_of(const TimelineInstanceKey& key) {
  if (!key.has_rotation) return glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
  return glm::quat(key.rotation_xyzw.w, key.rotation_xyzw.x, key.rotation_xyzw.y, key.rotation_xyzw.z);
}

}  // namespace

bool sample_instance_track(const Timeline& timeline, const InstanceTrack& track, double t, glm::mat4& mesh_to_world) {
  assert(!track.keys.empty());
  const auto& keys = timeline.instance_keys;
  if (t < keys[track.keys.front()].t) return false;
  size_t i = 1;
  while (i < track.keys.size() && keys[track.keys[i]].t < t) ++i;
  const TimelineInstanceKey& a = keys[track.keys[i - 1]];
  const TimelineInstanceKey& b = i < track.keys.size() ? keys[track.keys[i]] : a;
  const float s = (&a == &b || !(b.t > a.t)) ? 0.0f : static_cast<float>(std::min(1.0, (t - a.t) / (b.t - a.t)));
  const glm::vec3 ta = a.has_translation ? a.translation_world : track.resolved_translation;
  const glm::vec3 tb = b.has_translation ? b.translation_world : track.resolved_translation;
  const glm::quat qa = quat_of(a), qb = quat_of(b);
  const glm::vec3 translation = lerp_exact(ta, tb, s);
  const glm::quat rotation = qa == qb ? qa : glm::slerp(qa, qb, s);
  mesh_to_world = glm::mat4(glm::mat3_cast(rotation) * track.linear);
  mesh_to_world[3] = glm::vec4(translation, 1.0f);
  return true;
}

size_t timeline_frame_count(const Timeline& timeline) {
  assert(!timeline.keys.empty() && timeline.fps > 0.0);
  const double duration = timeline.keys.back().t - timeline.keys.front().t;
  return static_cast<size_t>(std::floor(duration * timeline.fps + 1e-9)) + 1;
}

}  // namespace lintel
