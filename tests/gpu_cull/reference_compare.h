// Comparing the GPU cull with the CPU reference (lintel::cull_instances) on one frame, honestly
// about float: the reference works in double, the GPU in float, so an instance whose decision
// flips under a perturbation of float-error size is "borderline" and may differ; every other
// instance must match exactly. Also: random cull scenes for the property test.
#pragma once

#include <lintel/gpu/cull_pass.h>
#include <lintel/view.h>
#include <lintel/visible_set.h>
#include <lintel/world.h>

#include <cstdint>
#include <string>
#include <vector>

namespace lintel::gpu::test {

// Perturbations that define "borderline": the world box inflated and deflated by
// kWorldTolerance x (largest coordinate of the box relative to the eye, at least 1 m), and the NDC rect
// widened and narrowed by kNdcTolerance x max(1, |coordinate|). Float's unit roundoff is 6e-8,
// so both leave more than 100x room for the GPU's float error.
inline constexpr double kWorldTolerance = 1e-5;
inline constexpr double kNdcTolerance = 1e-5;

// Whether the reference's decision for instance box `box` in a cell with `region` could flip
// under the perturbations above.
bool borderline(const glm::dmat4& view_proj, const glm::dvec3& eye, const Aabb& box, const ClipRegionView& region);

struct FrameComparison {
  uint32_t tested = 0;  // instances in visible cells
  uint32_t cpu_visible = 0;
  uint32_t gpu_visible = 0;
  uint32_t borderline = 0;              // tested instances classified borderline
  uint32_t borderline_gpu_extra = 0;    // borderline, drawn by the GPU only
  uint32_t borderline_gpu_missing = 0;  // borderline, drawn by the CPU only
  std::vector<std::string> errors;      // mismatches on non-borderline instances, bad output
};

// Checks `rb` (the GPU pass on `world` packed by pack_scene and `visible` packed by
// pack_visible_set) against the reference set visible.instances (as cull_instances fills it):
// every id in its own group's range, no duplicates, commands consistent with the groups, and the
// drawn set equal to the reference except on borderline instances.
FrameComparison compare_frame(const World& world, const View& view, const VisibleSet& visible, const CullScene& scene,
                              const CullReadback& rb);

// A random cull scene: `cells` cells, instances spread around and in front of the eye (some
// containing it, some across the near plane), `groups` draw groups, a random visible subset of
// cells with random convex regions (1..kMaxRegionPolygonsLimit polygons of 3..32 vertices, some
// on the snap lattice), and the reference's instances filled by cull_instances.
struct RandomCullCase {
  World world;
  View view;
  VisibleSet visible;
};
RandomCullCase make_random_case(uint64_t seed);

}  // namespace lintel::gpu::test
