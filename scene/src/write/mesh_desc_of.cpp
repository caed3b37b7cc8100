// A loaded mesh back as a scene-description mesh (mesh_desc_of.h).
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
  desc.double_sided = mesh.double_sided;
  return desc;
}

}  // namespace lintel
