// Properties of a world that changes while it is watched: the viewer tracker's hysteresis band on
// the generated scene pool, and door states (portals closed per direction) on cyclic worlds with
// non-identity cell frames. Part of visibility_properties (rapidcheck); each returns whether its
// properties held.
#pragma once

#include "world_pool.h"

#include <functional>

namespace lintel::fuzz {

// pick_scene: draws a pool scene inside a rapidcheck case (logs how to regenerate it).
bool check_tracker_hysteresis(const std::function<const PoolScene&()>& pick_scene);

bool check_door_states();

}  // namespace lintel::fuzz
