// Camera timelines: key frames of eye and target, sampled at a frame rate.
#pragma once

#include <lintel/status.h>
#include <lintel/view.h>
#include <lintel/world.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace lintel {

struct CameraPose {
  glm::vec3 eye_world{0.0f};
  glm::vec3 target_world{0.0f, 0.0f, -1.0f};
};

// Eye and target at time t (seconds), linearly interpolated between keys (as a + s (b - a), so a
// stretch between two equal keys is bit-exact), clamped to the ends.
// Precondition: timeline.keys is non-empty with strictly increasing t.
CameraPose sample_timeline(const Timeline& timeline, double t);

// The camera at time t: the timeline's lens (fov, aspect) with sample_timeline's eye and target;
// up, near and far keep View's defaults. Same precondition as sample_timeline.
View timeline_view(const Timeline& timeline, double t);

// Resolves each event's portal name to World::portals (TimelineEvent::portal_index). Error (bad
// input): an event names no portal of `world`; the message names the timeline, event and name.
Status resolve_timeline_events(const World& world, Timeline& timeline);

// Applies the door events with t <= `t` that are not applied yet: events[next..] in order, each
// setting its portal's state in both directions. Returns the new `next` (the caller keeps it from
// frame to frame, starting at 0). Precondition: events resolved against `world`. O(events applied).
size_t apply_timeline_events(const Timeline& timeline, double t, size_t next, World& world);

// The motion of one instance on a timeline: its keys (indices into Timeline::instance_keys, in
// time order) and its transform's linear part when resolved (the L of TimelineInstanceKey).
struct InstanceTrack {
  uint32_t instance = 0;
  glm::mat3 linear{1.0f};
  glm::vec3 resolved_translation{0.0f};
  std::vector<uint32_t> keys;
};

// Resolves each instance key's name to World::instances and groups the keys into one track per
// instance (tracks in order of first appearance). Instances that share a name and a transform
// are one object (a mesh of several materials loads as one instance per material) and move
// together: the key is on each one's track, and TimelineInstanceKey::instance_index is the first.
// Error (bad input): a key names no instance of `world`, or instances of that name placed apart;
// the message names the timeline, key and name. Allocates.
Status resolve_timeline_instances(const World& world, Timeline& timeline, std::vector<InstanceTrack>& tracks);

// The track's transform at time t (see TimelineInstanceKey); false before its first key (the
// instance is not driven yet). Equal neighbouring keys give exactly their transform.
bool sample_instance_track(const Timeline& timeline, const InstanceTrack& track, double t, glm::mat4& mesh_to_world);

// Number of frames timeline.fps yields from the first key to the last, both included (>= 1).
size_t timeline_frame_count(const Timeline& timeline);

}  // namespace lintel
