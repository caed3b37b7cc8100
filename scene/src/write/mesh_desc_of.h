// Parts of a loaded World back as scene-description parts: what the exporters that write a loaded
// World (`export rooms`, `optimize`) hand to the writer.
#pragma once

#include <lintel/scene_desc.h>
#include <lintel/world.h>

#include <optional>

namespace lintel {

// Geometry, colour, texture index, its sampler and sidedness.
MeshDesc mesh_desc_of(const Mesh& mesh);

// World::environment as SceneDesc::environment: empty where the loader would give the same sky
// without it (radiance kDefaultEnvironmentRadiance for a world without lights, else 0), so that
// a re-written scene names its sky only when its source did (or the source's sky was not the
// default). Assumes the written scene keeps the world's lights, or has none when it has none.
std::optional<glm::vec3> environment_desc_of(const World& world);

}  // namespace lintel
