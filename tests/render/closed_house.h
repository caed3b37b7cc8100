// The closed-shell house of the renderer's tests: lintel::generate_house (scene_gen.h) and its
// inspection cameras for images of a given aspect.
#pragma once

#include <lintel/scene_desc.h>
#include <lintel/scene_gen.h>
#include <lintel/view.h>

#include <cstdint>
#include <vector>

namespace lintel::render::test {

struct ClosedHouse {
  SceneDesc scene;
  std::vector<View> views;  // eyes inside rooms, looking through doors and along shared walls
};

// `seed` picks the cell frames; aspect is width / height of the images the views are for.
inline ClosedHouse closed_house(uint64_t seed, float aspect) {
  ClosedHouse out;
  out.scene = generate_house({seed}, &out.views);
  for (View& v : out.views) v.aspect = aspect;
  return out;
}

}  // namespace lintel::render::test
