// A scene as the generator builds it, before it becomes glTF: nodes with TRS and Lintel tags,
// meshes and lights. save_scene() writes it in the scene format (docs/scene-format.md);
// load_world() is the only way back to a World, so every generated scene passes the validator.
#pragma once

#include <lintel/world.h>

#include <glm/gtc/quaternion.hpp>

#include <optional>
#include <string>
#include <vector>

namespace lintel {

// An RGBA8 image the writer embeds as a PNG (in the buffer); the same fields and conventions as
// lintel::Texture (world.h): width, height in 1..8192, rgba8 = width*height*4 bytes, sRGB, row 0
// at the top. The name becomes the glTF image's name (omitted when empty).
using TextureDesc = Texture;

struct MeshDesc {
  std::string name;
  std::vector<glm::vec3> positions;  // mesh space
  std::vector<glm::vec3> normals;    // empty, or one per position
  std::vector<uint32_t> indices;     // triangle list
  glm::vec4 base_color{0.8f, 0.8f, 0.8f, 1.0f};
  std::vector<glm::vec2> uvs;  // empty, or one per position (TEXCOORD_0; required with `texture`)
  int texture = -1;            // base colour texture: index into SceneDesc::textures, or -1
  // How `texture` is sampled: its glTF sampler (Mesh::base_color_sampler). The default (REPEAT,
  // trilinear) is written as no sampler; one image used with two samplers becomes two glTF
  // textures. Ignored without a texture.
  TextureSampler sampler;
  bool double_sided = false;      // glTF material doubleSided (false: counter-clockwise faces only)
  std::vector<glm::vec4> colors;  // empty, or one per position (COLOR_0, linear RGBA in [0, 1])
  Mesh::AlphaMode alpha_mode = Mesh::AlphaMode::Opaque;  // glTF alphaMode (Mesh::alpha_mode)
  float alpha_cutoff = 0.5f;                             // glTF alphaCutoff, written for Mask only
  // Mesh::emissive: written as emissiveFactor, with KHR_materials_emissive_strength when a
  // component is above 1. Finite, >= 0.
  glm::vec3 emissive{0.0f};
  int emissive_texture = -1;        // Mesh::emissive_texture: index into SceneDesc::textures, or -1 (needs `uvs`)
  TextureSampler emissive_sampler;  // how emissive_texture is sampled (as `sampler` is)
};

struct LightDesc {
  std::string name;
  Light::Type type = Light::Type::Point;
  glm::vec3 color{1.0f};
  float intensity = 10.0f;
  float range = 0.0f;  // 0: unlimited (omitted from the file)
  float inner_cone_rad = 0.0f;
  float outer_cone_rad = 0.785398f;
};

struct NodeDesc {
  enum class Kind { Plain, Cell, Portal, Volume };
  std::string name;
  int parent = -1;  // index into SceneDesc::nodes (must come earlier), -1 for a scene root
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // w, x, y, z
  glm::vec3 scale{1.0f};
  int mesh = -1;   // index into SceneDesc::meshes
  int light = -1;  // index into SceneDesc::lights (KHR_lights_punctual)
  Kind kind = Kind::Plain;
  std::string cell_name;    // Kind::Cell
  std::string portal_from;  // Kind::Portal
  std::string portal_to;
  bool two_way = true;
  bool portal_open = true;  // Kind::Portal: extras.lintel.portal.open (written only when false)
  // Kind::Portal links (written only when set; two_way must then be false): a mirror (portal_to is
  // not written), or the name of the target portal whose polygon this one maps onto.
  bool portal_mirror = false;
  std::string portal_link;
  std::optional<glm::dmat4> portal_link_matrix;  // a teleport given by its world matrix instead
};

struct SceneDesc {
  std::vector<MeshDesc> meshes;
  std::vector<NodeDesc> nodes;
  std::vector<LightDesc> lights;
  std::vector<Timeline> timelines;
  std::vector<TextureDesc> textures;  // one glTF image each, in this order (and a glTF texture each)
  // The sky, extras.lintel.environment (World::environment): linear radiance, each component
  // finite and >= 0, written as its "color" (intensity 1, implicit). Empty: not written, and the
  // loader gives the sky its default (radiance 1 when the scene has no lights, else none).
  std::optional<glm::vec3> environment;
};

}  // namespace lintel
