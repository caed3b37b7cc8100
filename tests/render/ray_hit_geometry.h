// Where a ground-truth ray hit lies relative to its triangle's edges ON SCREEN: the world point
// of pixel (i, j)'s hit (from its view depth, as RayGroundTruth::cast computes rays), and the
// distance in pixels from that pixel's centre to the nearest edge of the triangle it hit,
// projected. The void and fragment tests excuse a raster/ray disagreement only when a pixel
// centre lies within a tiny fraction of a pixel of an edge — where the rasterizer's sub-pixel
// snapping of vertices (8 bits on lavapipe: 1/256 pixel) and the ray's float rounding decide
// differently — and count such pixels. Screen space is the right measure: a world distance
// means nothing for a floor seen at a grazing angle 13 m away.
#pragma once

#include <lintel/reference/ray_ground_truth.h>
#include <lintel/view.h>
#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>

namespace lintel::render::test {

RayCamera ray_camera(const View& view);

// The ray of pixel (i, j) of an R x R grid, as RayGroundTruth::cast builds it (unit length along
// the view direction, so its parameter is the view depth).
glm::vec3 pixel_ray_direction(const RayCamera& camera, uint32_t i, uint32_t j, uint32_t resolution);

// World point seen at pixel (i, j) of an R x R grid at view depth `depth`.
glm::dvec3 hit_point(const RayCamera& camera, uint32_t i, uint32_t j, uint32_t resolution, float depth);

// What pixel (i, j)'s ray hits WITHOUT cast()'s portal-rim rule (shells are still solid from
// behind): for the pixels cast() reports as seeing nothing, so that a rim ray that does hit
// something is checked like any other pixel instead of being skipped.
RayHitId raw_pixel_hit(const RayGroundTruth& truth, const RayCamera& camera, uint32_t i, uint32_t j,
                       uint32_t resolution);

// Distance in pixels of the R x R grid (rendered with view.aspect, so pixels are not square)
// from pixel (i, j)'s centre to the nearest projected edge of the hit surface's triangle (the
// instance's mesh, or the cell's shell when hit.instance is kNone) nearest to the hit point.
// Edges are clipped at the near plane before projecting.
double pixels_to_triangle_edge(const World& world, const View& view, const RayHitId& hit, uint32_t i, uint32_t j,
                               uint32_t resolution);

}  // namespace lintel::render::test
