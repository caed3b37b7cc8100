// The path tracer's view of a World's geometry: one Embree 3 triangle geometry per cell shell and
// per instance, in world space, each with its Lambertian albedo. Answers nearest-hit and
// any-hit (shadow) queries; both see every triangle from both sides.
#pragma once

#include <lintel/status.h>
#include <lintel/world.h>

#include <embree3/rtcore.h>

#include <glm/glm.hpp>

#include <vector>

namespace lintel::pathtrace_detail {

struct SurfaceHit {
  glm::vec3 position_world{0.0f};  // from the barycentrics (exact to float, unlike org + t * dir)
  glm::vec3 normal_world{0.0f};    // unit geometric normal, facing the incoming ray
  glm::vec3 albedo{0.0f};
};

class EmbreeScene {
 public:
  EmbreeScene() = default;
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  Status build(const World& world);

  // Nearest hit of the ray origin + t * dir, t in (0, inf); false when it escapes.
  bool intersect(const glm::vec3& origin, const glm::vec3& dir, SurfaceHit& hit) const;
  // True when any triangle lies on origin + t * dir for t in (0, t_max).
  bool occluded(const glm::vec3& origin, const glm::vec3& dir, float t_max) const;

 private:
  struct Geometry {
    const float* vertices = nullptr;    // world space, xyz per vertex (Embree's buffer)
    const uint32_t* indices = nullptr;  // 3 per triangle (Embree's buffer)
    glm::vec3 albedo{0.0f};
  };
  Status add_mesh(const Mesh& mesh, const glm::mat4& to_world);

  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  std::vector<Geometry> geometries_;  // by Embree geometry id
};

}  // namespace lintel::pathtrace_detail
