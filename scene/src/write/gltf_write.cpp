// The writer's public entry points (scene_io.h): the extension picks .gltf + .bin or .glb; both
// come from the same serialization, so the two forms of a scene always agree.
#include <lintel/scene_io.h>

#include <lintel/file_commit.h>
#include "write/gltf_serialize.h"

#include <filesystem>

namespace lintel {
namespace {

std::string lower(std::string s) {
  for (char& c : s)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  return s;
}

Status glb_bytes(const scene_write::SerializedScene& serialized, std::vector<uint8_t>& out) {
  if (serialized.json.size() + serialized.bin.size() + 64 > kMaxSceneFileBytes)
    return Status::error("scene: the GLB would exceed " + std::to_string(kMaxSceneFileBytes) + " bytes");
  out = scene_write::pack_glb(serialized);
  return {};
}

}  // namespace

Status save_scene(const SceneDesc& scene, const std::string& path) {
  const std::filesystem::path p(path);
  const std::string ext = lower(p.extension().string());
  if (ext != ".gltf" && ext != ".glb")
    return Status::error(path + ": unsupported extension '" + p.extension().string() + "' (use .gltf or .glb)");
  if (p.filename().string() == ext) return Status::error(path + ": the file name is empty");
  std::error_code ec;
  const std::filesystem::path dir = p.parent_path().empty() ? std::filesystem::path(".") : p.parent_path();
  if (!std::filesystem::is_directory(dir, ec))
    return Status::error(path + ": directory '" + dir.string() + "' does not exist");

  const std::string bin_name = p.stem().string() + ".bin";
  for (const std::filesystem::path& target : {p, dir / bin_name})
    if ((target == p || ext == ".gltf") && std::filesystem::is_directory(target, ec))
      return Status::error(path + ": cannot write '" + target.string() + "': it is a directory");

  scene_write::SerializedScene serialized;
  if (ext == ".glb") {
    if (Status s = scene_write::serialize_scene(scene, "", false, serialized); !s)
      return Status::error(path + ": " + s.message());
    std::vector<uint8_t> bytes;
    if (Status s = glb_bytes(serialized, bytes); !s) return Status::error(path + ": " + s.message());
    return commit_files({{path, bytes.data(), bytes.size()}});
  }
  if (Status s = scene_write::serialize_scene(scene, scene_write::uri_escape(bin_name), true, serialized); !s)
    return Status::error(path + ": " + s.message());
  const std::string bin_path = (dir / bin_name).string();
  std::vector<FileContent> files;
  if (!serialized.bin.empty()) files.push_back({bin_path, serialized.bin.data(), serialized.bin.size()});
  files.push_back({path, reinterpret_cast<const uint8_t*>(serialized.json.data()), serialized.json.size()});
  return commit_files(files);
}

Status scene_to_glb(const SceneDesc& scene, std::vector<uint8_t>& out) {
  out.clear();
  scene_write::SerializedScene serialized;
  if (Status s = scene_write::serialize_scene(scene, "", false, serialized); !s) return s;
  return glb_bytes(serialized, out);
}

Status build_world(const SceneDesc& scene, const std::string& label, World& out, std::vector<std::string>* warnings) {
  std::vector<uint8_t> glb;
  if (Status s = scene_to_glb(scene, glb); !s) return Status::error(label + ": " + s.message());
  return load_world_from_memory(glb.data(), glb.size(), label, "", out, warnings);
}

}  // namespace lintel
