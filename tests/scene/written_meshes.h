// Shared by the scene tests that write a loaded World back as a scene (optimize with nothing to
// merge) and look meshes up by name in what loads again.
#pragma once

#include <lintel/optimize.h>
#include <lintel/world.h>

#include <gtest/gtest.h>

#include <string>

namespace lintel::test {

// The first mesh named `name` (a test failure, and the first mesh, when there is none).
inline const Mesh& mesh_named(const World& world, const std::string& name) {
  for (const Mesh& mesh : world.meshes)
    if (mesh.name == name) return mesh;
  ADD_FAILURE() << "no mesh " << name;
  return world.meshes.front();
}

// Options under which optimize merges nothing: every mesh is written as loaded.
inline OptimizeOptions nothing_merges() {
  OptimizeOptions keep;
  keep.min_open_fraction = 2.0;
  keep.sliver_volume_m3 = 0.0;
  keep.sliver_thickness_m = 0.0;
  return keep;
}

}  // namespace lintel::test
