// PLACEHOLDER: replaced by the writer.
#include <lintel/scene_io.h>
namespace lintel {
Status save_scene(const SceneDesc&, const std::string& path) { return Status::error(path + ": writer not implemented yet"); }
Status scene_to_glb(const SceneDesc&, std::vector<uint8_t>&) { return Status::error("writer not implemented yet"); }
Status build_world(const SceneDesc&, const std::string& label, World&, std::vector<std::string>*) { return Status::error(label + ": writer not implemented yet"); }
}  // namespace lintel
