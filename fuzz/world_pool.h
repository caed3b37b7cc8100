// A deterministic pool of generated scenes for the visibility properties: random cyclic graphs
// with non-identity cell frames (rotations about any axis, offsets up to 1e4 m, scales 0.1-10),
// jittered grids and rings, each loaded through the real glTF path and paired with its Embree
// ground truth. Cases pick a scene from the pool, so a case costs a query, not a scene build.
#pragma once

#include <lintel/reference/ray_ground_truth.h>
#include <lintel/scene_desc.h>
#include <lintel/world.h>

#include <memory>
#include <string>
#include <vector>

namespace lintel::fuzz {

struct PoolScene {
  std::string label;  // how to regenerate it, e.g. "random --cells 9 --seed 17"
  SceneDesc desc;
  World world;
  RayGroundTruth rays;
};

// `count` scenes, mixing random graphs (most), jittered grids and rings. Aborts with a message
// if a generated scene fails to load: that is a generator or loader bug, not a property failure.
std::vector<std::unique_ptr<PoolScene>> make_world_pool(size_t count, uint64_t seed, uint32_t max_cells);

// `desc` with every root node moved by the rigid motion (rotation then translation).
SceneDesc rigidly_moved(const SceneDesc& desc, const glm::dquat& rotation, const glm::dvec3& translation);

}  // namespace lintel::fuzz
