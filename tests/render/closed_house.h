// A house of 3 x 3 rooms authored the way a modeller exports closed rooms: every room is a closed,
// single-sided (glTF's default) shell facing its own air, and neighbouring rooms' walls lie back
// to back in ONE plane, so only back-face culling decides which of the two the camera sees. The
// house is tilted (not axis-aligned), every cell frame is a random rotation and offset
// (compensated in the vertices), doors join every pair of neighbours, a crate stands in some rooms
// and a point light in most. Each room has its own colour, so the wrong wall shows as the wrong
// albedo. Built as a SceneDesc: it goes through the writer and the validating loader.
#pragma once

#include <lintel/scene_desc.h>
#include <lintel/view.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lintel::render::test {

struct ClosedHouse {
  SceneDesc scene;
  std::vector<View> views;  // eyes inside rooms, looking through doors and along shared walls
};

// `seed` picks the cell frames; aspect is width / height of the images the views are for.
ClosedHouse closed_house(uint64_t seed, float aspect);

}  // namespace lintel::render::test
