// A loaded mesh back as a scene-description mesh: what the exporters that write a loaded World
// (`export rooms`, `optimize`) hand to the writer.
#pragma once

#include <lintel/scene_desc.h>
#include <lintel/world.h>

namespace lintel {

// Geometry, colour, texture index and sidedness. The texture sampler is not carried: the
// description has no sampler field yet, so a re-written scene samples with glTF's defaults.
MeshDesc mesh_desc_of(const Mesh& mesh);

}  // namespace lintel
