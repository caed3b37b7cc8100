// Camera timelines as JSON: the objects in scene.extras.lintel.timelines and the standalone
// timeline files (the same object). Validated so that sample_timeline() and
// timeline_frame_count() can rely on their preconditions.
#pragma once

#include "read/load_context.h"

#include <lintel/world.h>

#include <nlohmann/json.hpp>

#include <cstddef>

namespace lintel::scene_read {

inline constexpr double kMaxTimelineFps = 1000.0;
inline constexpr double kMaxTimelineAspect = 100.0;
// (last t - first t) * fps. Bounds `lintel walk`'s time and memory (one build and 8 bytes of
// timing per frame): 1 M frames is 4.6 hours at 60 fps and a few seconds of walking the cottage.
inline constexpr double kMaxTimelineFrames = 1e6;
// Eye and target coordinates, meters from the origin (far beyond any building; keeps float
// view matrices finite).
inline constexpr double kMaxTimelineCoordinate = 1e6;

// Parses one timeline object; `index` names it in messages until its name is known.
Status parse_timeline(const LoadContext& ctx, const nlohmann::json& value, size_t index, Timeline& out);

}  // namespace lintel::scene_read
