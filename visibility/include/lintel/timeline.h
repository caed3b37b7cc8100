// Camera timelines: key frames of eye and target, sampled at a frame rate.
#pragma once

#include <lintel/view.h>
#include <lintel/world.h>

#include <cstddef>

namespace lintel {

struct CameraPose {
  glm::vec3 eye_world{0.0f};
  glm::vec3 target_world{0.0f, 0.0f, -1.0f};
};

// Eye and target at time t (seconds), linearly interpolated between keys, clamped to the ends.
// Precondition: timeline.keys is non-empty with strictly increasing t.
CameraPose sample_timeline(const Timeline& timeline, double t);

// The camera at time t: the timeline's lens (fov, aspect) with sample_timeline's eye and target;
// up, near and far keep View's defaults. Same precondition as sample_timeline.
View timeline_view(const Timeline& timeline, double t);

// Number of frames timeline.fps yields from the first key to the last, both included (>= 1).
size_t timeline_frame_count(const Timeline& timeline);

}  // namespace lintel
