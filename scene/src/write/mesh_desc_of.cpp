// Loaded World parts back as scene-description parts (mesh_desc_of.h).
#include "write/mesh_desc_of.h"

namespace lintel {

MeshDesc mesh_desc_of(const Mesh& mesh) {
  MeshDesc desc;
  desc.name = mesh.name;
  desc.positions = mesh.positions;
  desc.normals = mesh.normals;
  desc.indices = mesh.indices;
  desc.base_color = mesh.base_color;
  desc.uvs = mesh.uvs;
  desc.texture = mesh.base_color_texture;
  desc.sampler = mesh.base_color_sampler;
  desc.double_sided = mesh.double_sided;
  desc.colors = mesh.colors;
  desc.alpha_mode = mesh.alpha_mode;
  desc.alpha_cutoff = mesh.alpha_cutoff;
  desc.emissive = mesh.emissive;
  desc.emissive_texture = mesh.emissive_texture;
  desc.emissive_sampler = mesh.emissive_sampler;
  return desc;
}

std::optional<glm::vec3> environment_desc_of(const World& world) {
  const glm::vec3 implied = world.has_light_sources() ? glm::vec3(0.0f) : glm::vec3(kDefaultEnvironmentRadiance);
  if (world.environment == implied) return std::nullopt;
  return world.environment;
}

}  // namespace lintel
