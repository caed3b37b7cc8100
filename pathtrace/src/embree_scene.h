// The path tracer's view of a World's geometry: one Embree 3 triangle geometry per cell shell and
// per instance, in world space, each with its Lambertian albedo (base colour factor, times the
// base colour texture at the hit where the mesh has one, filtered over the ray cone's footprint). Answers nearest-hit and any-hit
// (shadow) queries. glTF sidedness, as the rasterizer has it: nearest-hit (camera and bounce
// rays) passes through the back faces of single-sided meshes (doubleSided false, the default);
// any-hit (shadow rays) is blocked by both faces, as the renderer's shadow maps are. Cut-outs
// (alphaMode MASK): every ray passes through the points whose coverage is below the cutoff.
#pragma once

#include <lintel/reference/cut_out.h>
#include <lintel/reference/linear_texture.h>

#include <lintel/status.h>
#include <lintel/world.h>

#include <embree3/rtcore.h>

#include <glm/glm.hpp>

#include <vector>

namespace lintel::pathtrace_detail {

// The footprint a ray carries for texture filtering, a ray cone (Akenine-Moller et al., "Texture
// Level of Detail Strategies for Real-Time Ray Tracing", Ray Tracing Gems, 2019, ch. 20): width
// `width_m` at the ray's origin, growing by `spread` metres per metre travelled (the pixel's
// angle). Zero: a point, which reads texture level 0 with the magnification filter.
struct RayCone {
  float width_m = 0.0f;
  float spread = 0.0f;
};

struct SurfaceHit {
  glm::vec3 position_world{0.0f};  // from the barycentrics (exact to float, unlike org + t * dir)
  glm::vec3 normal_world{0.0f};    // unit geometric normal, facing the incoming ray
  glm::vec3 albedo{0.0f};          // at the hit: factor x texture (when textured)
  glm::vec3 emission{0.0f};        // radiance the surface gives off at the hit (Mesh::emissive x texture)
  float cone_width_m = 0.0f;       // the ray cone's width at the hit
};

class EmbreeScene {
 public:
  EmbreeScene() = default;
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  Status build(const World& world);

  // Nearest hit of the ray origin + t * dir, t in (0, inf), skipping back faces of single-sided
  // meshes; false when it escapes. A textured hit reads its texture at the level of detail of
  // the cone's footprint there: lod = 0.5 log2(texels per m^2 of the triangle) + log2(width /
  // |cos|), width = cone.width_m + cone.spread * distance, cos between the ray and the triangle's
  // normal (the cone's section stretched along the slope).
  bool intersect(const glm::vec3& origin, const glm::vec3& dir, const RayCone& cone, SurfaceHit& hit) const;
  // True when any triangle lies on origin + t * dir for t in (0, t_max) (a cut-out's covered
  // points only, its texture read at level 0 with the magnification filter: a shadow ray has no
  // footprint).
  bool occluded(const glm::vec3& origin, const glm::vec3& dir, float t_max) const;

 private:
  struct Geometry {
    const float* vertices = nullptr;                    // world space, xyz per vertex (Embree's buffer)
    const uint32_t* indices = nullptr;                  // 3 per triangle (Embree's buffer)
    glm::vec3 albedo{0.0f};                             // the base colour factor
    const glm::vec2* uvs = nullptr;                     // per vertex, when textured (mesh_uvs_)
    const glm::vec4* colors = nullptr;                  // per vertex COLOR_0, or null (white; mesh_colors_)
    const reference::LinearTexture* texture = nullptr;  // the base colour texture, or null (textures_)
    TextureSampler sampler;                             // how `texture` is read (Mesh::base_color_sampler)
    bool single_sided = true;                           // glTF doubleSided false: back faces are not seen
    float winding = 1.0f;                               // -1 under a mirroring transform (front faces clockwise)
    reference::CutOut cut;                              // Mesh::AlphaMode::Mask: rays pass where coverage < cutoff
    glm::vec3 emission{0.0f};                           // Mesh::emissive
    const reference::LinearTexture* emissive_texture = nullptr;  // its texture, or null (textures_)
    TextureSampler emissive_sampler;
  };
  Status add_mesh(const World& world, uint32_t mesh, const glm::mat4& to_world);

  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  std::vector<Geometry> geometries_;  // by Embree geometry id
  bool has_masks_ = false;            // some geometry is masked: shadow rays test coverage too
  // Copies of the World's textures (decoded to linear), of textured meshes' uvs and of vertex
  // colours, sized once in build() so that the Geometry pointers into them stay valid.
  std::vector<reference::LinearTexture> textures_;
  std::vector<std::vector<glm::vec2>> mesh_uvs_;     // by World mesh index; empty without a texture
  std::vector<std::vector<glm::vec4>> mesh_colors_;  // by World mesh index; empty without COLOR_0
};

}  // namespace lintel::pathtrace_detail
