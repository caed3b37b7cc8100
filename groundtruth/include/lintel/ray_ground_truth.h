// Ray-cast ground truth (Embree 3), for tests and benchmarks only: what an eye really sees,
// ignoring portals. One ray per pixel of an R x R grid against every cell shell and instance.
// A portal method is conservative iff every cell and instance hit here is in its visible set.
// Shells are solid from behind: every shell faces into its own cell (glTF front faces), so a ray
// that meets a shell triangle from behind has left the building's interior — through the float
// crack between two cells' reveal quads far from the origin, or because the eye stands inside a
// wall — and sees nothing: the hit is reported as kNone ("blocked") and counted. A rasterizer
// with back-face culling would show whatever lies beyond; no portal method models that, and it
// is not a cell the viewer can see. Instances are double-sided (stricter for the tests).
#pragma once

#include <lintel/status.h>
#include <lintel/world.h>

#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace lintel {

// A pinhole camera in world space. Pixel (i, j) of an R x R grid looks through the NDC point
// pixel_center_ndc(i, j, R); the ray starts where it crosses the near plane, as a rasterizer's would.
struct RayCamera {
  glm::vec3 eye_world{0.0f};
  glm::vec3 target_world{0.0f, 0.0f, -1.0f};
  glm::vec3 up_world{0.0f, 1.0f, 0.0f};
  float fov_y_deg = 70.0f;
  float aspect = 16.0f / 9.0f;
  float near_m = 0.05f;
};

// NDC of pixel (i, j)'s centre: x grows right, y grows up (row 0 is the top row), both in (-1, 1).
glm::vec2 pixel_center_ndc(uint32_t i, uint32_t j, uint32_t resolution);

struct RayHitId {
  static constexpr uint32_t kNone = 0xffffffffu;
  uint32_t cell = kNone;      // cell owning the hit surface (kNone: the ray escaped)
  uint32_t instance = kNone;  // instance hit, or kNone when the surface is the cell's shell
  // cast(): view depth of the hit (meters along the view direction); cast_ray(): the ray
  // parameter. Infinity when nothing was hit.
  float depth = std::numeric_limits<float>::infinity();
};

struct GroundTruth {
  uint32_t resolution = 0;
  uint32_t blocked_pixels = 0;         // rays that met a shell from behind (see above)
  std::vector<RayHitId> pixels;        // resolution^2, row-major, row 0 at the top
  std::vector<uint8_t> cell_visible;     // per World cell: 1 if some ray hit its shell or an instance of it
  std::vector<uint8_t> instance_visible; // per World instance: 1 if some ray hit it
};

// Owns the Embree device and scene built from one World. Movable, not copyable.
class RayGroundTruth {
 public:
  RayGroundTruth();
  ~RayGroundTruth();
  RayGroundTruth(RayGroundTruth&&) noexcept;
  RayGroundTruth& operator=(RayGroundTruth&&) noexcept;

  // Builds the acceleration structure for `world` (which must outlive this object).
  Status build(const World& world);
  // Casts resolution^2 rays. Precondition: build() succeeded, resolution >= 1, camera finite.
  void cast(const RayCamera& camera, uint32_t resolution, GroundTruth& out) const;
  // Nearest hit along one world-space ray with t in [t_min, t_max]; kNone fields if none or if
  // the nearest surface is the back of a shell (then *blocked is set, when given).
  RayHitId cast_ray(const glm::vec3& origin, const glm::vec3& direction, float t_min, float t_max,
                    bool* blocked = nullptr) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lintel
