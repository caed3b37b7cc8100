// Structural checks on a SceneDesc before it is written: indices in range, parents before
// children, finite numbers, names present where the format needs them. The writer refuses what
// the loader would refuse for reasons the writer can see, with the same kind of message.
#pragma once

#include <lintel/scene_desc.h>
#include <lintel/status.h>

namespace lintel::scene_write {

Status check_scene_desc(const SceneDesc& scene);

}  // namespace lintel::scene_write
