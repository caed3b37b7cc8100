// The views the accuracy benchmark asks from: frames of the scene's own camera timelines
// (subsampled), eyes at portals (on either side, 1e-4..0.3 m off the plane) and eyes inside cells,
// looking in random directions. Every eye keeps a clearance from every surface larger than the
// near plane's corner distance: a near plane that reaches into a wall sees through it, which no
// portal method models. Deterministic for a given seed.
#pragma once

#include <lintel/reference/ray_ground_truth.h>
#include <lintel/view.h>
#include <lintel/world.h>

#include <cstdint>
#include <string>
#include <vector>

namespace lintel {

struct BenchView {
  View view;
  uint32_t start_cell = 0;
  std::string kind;  // "timeline", "portal", "cell"
};

// `count` views of `world` (fewer only if the world offers no clear eye positions after many
// tries). `rays` must have been built from `world` (used for the clearance probes).
std::vector<BenchView> make_bench_views(const World& world, const RayGroundTruth& rays, uint32_t count, uint64_t seed);

// No surface within `radius` meters of `eye` along 26 probe rays (axes, edges, corners).
bool eye_clear_of_surfaces(const RayGroundTruth& rays, const glm::dvec3& eye, double radius);

// Distance from the eye to a corner of the near rectangle, times 1.5: the clearance views keep.
double view_clearance_m(const View& view);

// A View from `eye` along `dir` (70 degrees, 16:9, near 0.05 m; up is +Y unless dir is nearly
// vertical).
View view_along(const glm::dvec3& eye, const glm::dvec3& dir);

// The RayGroundTruth camera of a View.
RayCamera ray_camera_of(const View& view);

}  // namespace lintel
