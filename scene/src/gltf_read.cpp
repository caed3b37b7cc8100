// PLACEHOLDER: replaced by the validating loader.
#include <lintel/scene_io.h>
namespace lintel {
Status load_world(const std::string& path, World&, std::vector<std::string>*) { return Status::error(path + ": loader not implemented yet"); }
Status load_world_from_memory(const uint8_t*, size_t, const std::string& label, const std::string&, World&, std::vector<std::string>*) { return Status::error(label + ": loader not implemented yet"); }
Status load_timeline_file(const std::string& path, Timeline&) { return Status::error(path + ": not implemented yet"); }
}  // namespace lintel
