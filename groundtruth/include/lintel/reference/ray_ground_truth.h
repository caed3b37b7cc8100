// Ray-cast ground truth (Embree 3), for tests and benchmarks only: what an eye really sees,
// ignoring portals. One ray per pixel of an R x R grid against every cell shell and instance.
// A portal method is conservative iff every cell and instance hit here is in its visible set.
//
// Two rules make the truth that of the building rather than of its float rounding:
// * Shells are solid from behind: every shell faces into its own cell (glTF front faces), so a
//   ray that meets a shell triangle from behind has left the building's interior — through the
//   float crack between two cells' reveal quads far from the origin, or because the eye stands
//   inside a wall — and sees nothing: the hit is reported as kNone ("blocked") and counted. A
//   rasterizer with back-face culling would show whatever lies beyond; no portal method models
//   that, and it is not a cell the viewer can see.
// * Portal rims are where two cells' surfaces meet (the reveals of both cells end on the portal's
//   edges); everywhere else the space between two cells is closed by back faces. Each cell's
//   vertices are exact only to its float error (scene_float_error_m), so at a rim the two
//   cells' surfaces leave a crack or overlap. Both cells' edges there lie within their own error
//   of the true rim, so the crack or the overlapping sliver lies within the larger of the two
//   errors of it; the portal polygon itself is exact to far less (its vertices are stored next
//   to the portal node's origin). A ray that passes within rim_radius_m() = that larger error of
//   a portal edge cannot be decided at the scene's precision: it may slip between the reveals
//   into the wall and out through another rim, or see the far cell's reveal poking through a
//   one-way portal's plug (the false negatives of the first full accuracy run; docs/accuracy.md).
//   Such a "rim ray" sees nothing here, is counted (GroundTruth::rim_pixels), and what it would
//   have hit is reported apart (past_rim_*), never dropped silently. The radius is 2..10 mm for
//   random scenes whose cell frames sit up to 1e4 m from their rooms (measured: up to 1.9 mm)
//   and 11..23 um for the committed scenes.
// Instances are double-sided (stricter for the tests). Cut-outs (alphaMode MASK, shells and
// instances) are surface only where covered (lintel/reference/cut_out.h, the texture at level 0):
// a ray passes their uncovered points, so what a grate or a fence shows counts as visible.
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
  uint32_t blocked_pixels = 0;            // rays that met a shell from behind (see above), rim rays excepted
  uint32_t rim_pixels = 0;                // rays that passed within rim_radius_m() of a portal rim (see above)
  std::vector<RayHitId> pixels;           // resolution^2, row-major, row 0 at the top; kNone for rim rays
  std::vector<uint8_t> cell_visible;      // per World cell: 1 if some ray hit its shell or an instance of it
  std::vector<uint8_t> instance_visible;  // per World instance: 1 if some ray hit it
  // Per cell / instance: 1 if only rim rays hit it (cell_visible is 0): what the rays past a rim
  // would have shown, undecidable at the scene's precision, reported apart by the benchmarks.
  std::vector<uint8_t> past_rim_cell_visible;
  std::vector<uint8_t> past_rim_instance_visible;
};

// How far (meters) a loaded cell's world-space vertices may lie from where the scene meant them:
// the largest over cells with a shell of 4 float half-ulps (vertex storage in cell space, matrix
// entries, translation, the transform's sums) of the magnitudes the transform adds up,
// |translation| + sum_i |column_i| * max |vertex_i|. Per cell in `out` when given (0 without a shell).
double scene_float_error_m(const World& world, std::vector<double>* per_cell = nullptr);

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
  // Whether the ray passes within rim_radius_m(p) of an edge of some portal p for t in
  // [t_min, t_max] (a box of that half-width around each edge, so up to sqrt(2) times that).
  bool passes_portal_rim(const glm::vec3& origin, const glm::vec3& direction, float t_min, float t_max) const;
  // The larger scene_float_error_m of the portal's two cells. Precondition: build() succeeded.
  double rim_radius_m(uint32_t portal) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lintel
