// One pass over textures, meshes, lights, nodes, timelines and the environment; the first fault is
// reported.
#include "write/scene_desc_check.h"

#include <cmath>
#include <string>

namespace lintel::scene_write {
namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string element(const char* kind, size_t index, const std::string& name) {
  return std::string(kind) + " " + std::to_string(index) + (name.empty() ? "" : " '" + name + "'");
}

Status fail(const std::string& where, const std::string& what) {
  return Status::error("scene: " + where + ": " + what);
}

Status check_mesh(const MeshDesc& m, size_t i, size_t texture_count) {
  const std::string e = element("mesh", i, m.name);
  if (m.positions.empty()) return fail(e, "has no positions");
  if (m.indices.empty() || m.indices.size() % 3 != 0)
    return fail(e, "index count " + std::to_string(m.indices.size()) + " is not a positive multiple of 3");
  if (!m.normals.empty() && m.normals.size() != m.positions.size())
    return fail(e, "has " + std::to_string(m.normals.size()) + " normals for " + std::to_string(m.positions.size()) +
                       " positions");
  if (m.positions.size() > UINT32_MAX - 1) return fail(e, "has too many vertices");
  for (uint32_t index : m.indices)
    if (index >= m.positions.size()) return fail(e, "index " + std::to_string(index) + " is out of range");
  for (const glm::vec3& p : m.positions)
    if (!finite(p)) return fail(e, "has a non-finite position");
  for (const glm::vec3& n : m.normals)
    if (!finite(n)) return fail(e, "has a non-finite normal");
  for (int c = 0; c < 4; ++c)
    if (!(m.base_color[c] >= 0.0f && m.base_color[c] <= 1.0f)) return fail(e, "base colour is outside [0, 1]");
  if (!m.uvs.empty() && m.uvs.size() != m.positions.size())
    return fail(
        e, "has " + std::to_string(m.uvs.size()) + " uvs for " + std::to_string(m.positions.size()) + " positions");
  for (const glm::vec2& uv : m.uvs)
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return fail(e, "has a non-finite uv");
  if (!m.colors.empty() && m.colors.size() != m.positions.size())
    return fail(e, "has " + std::to_string(m.colors.size()) + " colours for " + std::to_string(m.positions.size()) +
                       " positions");
  for (const glm::vec4& c : m.colors)
    if (!(glm::all(glm::greaterThanEqual(c, glm::vec4(0.0f))) && glm::all(glm::lessThanEqual(c, glm::vec4(1.0f)))))
      return fail(e, "has a vertex colour outside [0, 1]");
  if (m.texture < -1 || m.texture >= int(texture_count))
    return fail(e, "texture " + std::to_string(m.texture) + " is out of range");
  if (m.texture >= 0 && m.uvs.empty()) return fail(e, "has a texture but no uvs");
  if (m.emissive_texture < -1 || m.emissive_texture >= int(texture_count))
    return fail(e, "emissive texture " + std::to_string(m.emissive_texture) + " is out of range");
  if (m.emissive_texture >= 0 && m.uvs.empty()) return fail(e, "has an emissive texture but no uvs");
  // The loader reads the strength-scaled factor up to 1e9 (gltf_model_looks.cpp).
  if (!(glm::all(glm::greaterThanEqual(m.emissive, glm::vec3(0.0f))) &&
        glm::all(glm::lessThanEqual(m.emissive, glm::vec3(1e9f)))))
    return fail(e, "emissive is negative, beyond 1e9 or not finite");
  for (const TextureSampler* t : {&m.sampler, &m.emissive_sampler})  // enums cast from bad numbers have no glTF code
    if (uint8_t(t->wrap_s) > 2 || uint8_t(t->wrap_t) > 2 || uint8_t(t->mag) > 1 || uint8_t(t->min) > 1 ||
        uint8_t(t->mip) > 2)
      return fail(e, "sampler has a wrap, filter or mipmap mode outside its enum");
  if (uint8_t(m.alpha_mode) > 2) return fail(e, "alpha mode is outside its enum");
  if (!(m.alpha_cutoff >= 0.0f && std::isfinite(m.alpha_cutoff)))
    return fail(e, "alpha cutoff is negative or not finite");
  return {};
}

// The loader's limits (load_limits.h): what is written must load back.
Status check_texture(const TextureDesc& t, size_t i) {
  const std::string e = element("texture", i, t.name);
  if (t.width < 1 || t.height < 1 || t.width > 8192 || t.height > 8192)
    return fail(e, "size " + std::to_string(t.width) + "x" + std::to_string(t.height) + " is outside 1..8192");
  if (t.rgba8.size() != size_t(t.width) * t.height * 4)
    return fail(e, "has " + std::to_string(t.rgba8.size()) + " bytes, width * height * 4 is " +
                       std::to_string(size_t(t.width) * t.height * 4));
  return {};
}

Status check_node(const SceneDesc& scene, const NodeDesc& n, size_t i) {
  const std::string e = element("node", i, n.name);
  if (n.parent < -1 || n.parent >= int(i))
    return fail(e, "parent " + std::to_string(n.parent) + " does not come before the node");
  if (n.mesh < -1 || n.mesh >= int(scene.meshes.size()))
    return fail(e, "mesh " + std::to_string(n.mesh) + " is out of range");
  if (n.light < -1 || n.light >= int(scene.lights.size()))
    return fail(e, "light " + std::to_string(n.light) + " is out of range");
  if (!finite(n.translation) || !finite(n.scale) || !std::isfinite(n.rotation.w) || !std::isfinite(n.rotation.x) ||
      !std::isfinite(n.rotation.y) || !std::isfinite(n.rotation.z))
    return fail(e, "transform is not finite");
  if (glm::length(n.rotation) < 1e-6f) return fail(e, "rotation quaternion has zero length");
  switch (n.kind) {
    case NodeDesc::Kind::Cell:
      if (n.cell_name.empty()) return fail(e, "cell node has an empty cell name");
      break;
    case NodeDesc::Kind::Portal:
      if (n.portal_from.empty() || n.portal_to.empty()) return fail(e, "portal node needs 'from' and 'to' cell names");
      if (n.mesh < 0) return fail(e, "portal node has no mesh");
      break;
    case NodeDesc::Kind::Volume:
      if (n.mesh < 0) return fail(e, "volume node has no mesh");
      break;
    case NodeDesc::Kind::Plain:
      break;
  }
  return {};
}

Status check_timeline(const Timeline& t, size_t i) {
  const std::string e = element("timeline", i, t.name);
  if (t.name.empty()) return fail(e, "has no name");
  if (!(t.fps > 0.0) || !std::isfinite(t.fps)) return fail(e, "fps must be positive");
  if (!(t.fov_y_deg > 0.0 && t.fov_y_deg < 180.0)) return fail(e, "fov_y_deg must be in (0, 180)");
  if (!(t.aspect > 0.0) || !std::isfinite(t.aspect)) return fail(e, "aspect must be positive");
  if (t.keys.empty()) return fail(e, "has no keys");
  for (size_t k = 0; k < t.keys.size(); ++k) {
    const TimelineKey& key = t.keys[k];
    if (!std::isfinite(key.t) || !finite(key.eye_world) || !finite(key.target_world))
      return fail(e, "key " + std::to_string(k) + " is not finite");
    if (k > 0 && !(key.t > t.keys[k - 1].t)) return fail(e, "key " + std::to_string(k) + ": t does not increase");
    if (key.eye_world == key.target_world) return fail(e, "key " + std::to_string(k) + ": eye and target coincide");
  }
  return {};
}

}  // namespace

Status check_scene_desc(const SceneDesc& scene) {
  for (size_t i = 0; i < scene.textures.size(); ++i)
    if (Status s = check_texture(scene.textures[i], i); !s) return s;
  for (size_t i = 0; i < scene.meshes.size(); ++i)
    if (Status s = check_mesh(scene.meshes[i], i, scene.textures.size()); !s) return s;
  for (size_t i = 0; i < scene.nodes.size(); ++i)
    if (Status s = check_node(scene, scene.nodes[i], i); !s) return s;
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const LightDesc& l = scene.lights[i];
    if (!finite(l.color) || !std::isfinite(l.intensity) || l.intensity < 0.0f || !std::isfinite(l.range) ||
        l.range < 0.0f || !std::isfinite(l.inner_cone_rad) || !std::isfinite(l.outer_cone_rad))
      return fail(element("light", i, l.name), "has a non-finite or negative parameter");
    if (l.type == Light::Type::Spot &&
        !(l.inner_cone_rad >= 0.0f && l.inner_cone_rad < l.outer_cone_rad && l.outer_cone_rad <= 1.5707964f))
      return fail(element("light", i, l.name), "spot cones need 0 <= inner < outer <= pi/2");
  }
  for (size_t i = 0; i < scene.timelines.size(); ++i)
    if (Status s = check_timeline(scene.timelines[i], i); !s) return s;
  if (const auto& sky = scene.environment; sky && !(finite(*sky) && sky->x >= 0.0f && sky->y >= 0.0f && sky->z >= 0.0f))
    return fail("environment", "radiance must be finite and >= 0");
  return {};
}

}  // namespace lintel::scene_write
