// What every World that load_world_from_memory() accepts must satisfy, whatever the input:
// shared by the rapidcheck property test and the libFuzzer target, which both fail on a breach.
#pragma once

#include <lintel/world.h>

#include <string>

namespace lintel::fuzz {

// Empty when `world` is internally consistent (every index in range, portal polygons of
// 3..kMaxPortalVertices finite vertices with a unit normal, meshes with whole triangles, draw
// groups that list each instance once, timelines with increasing keys); otherwise the first breach.
std::string world_invariant_violation(const World& world);

// Empty when `message` is a proper loader error for `label`: one non-empty line starting "label: ".
std::string error_message_violation(const std::string& message, const std::string& label);

}  // namespace lintel::fuzz
