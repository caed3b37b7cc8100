// Properties of moving instances (dynamic_instances.h) with random door states on cyclic worlds
// with non-identity cell frames. Part of visibility_properties (rapidcheck).
#pragma once

namespace lintel::fuzz {

bool check_moving_instances();

}  // namespace lintel::fuzz
