// Area of a union of convex NDC polygons, the region-size metric of the accuracy benchmark.
// Exact unions of Lintel's overlapping region polygons would need a polygon-set library; the
// benchmark only needs a ratio, so it integrates slice by slice: every convex polygon covers one
// exact x-interval on each horizontal line, the interval union is exact, and the midpoint rule
// over `rows` lines across the bounding rect has an error below perimeter x (rect height / rows).
#pragma once

#include <lintel/reference/cull_method.h>
#include <lintel/visible_set.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace lintel {

// `polygons`: each a convex polygon, either winding, >= 3 vertices (fewer are ignored).
double union_area_ndc(std::span<const std::vector<glm::dvec2>> polygons, uint32_t rows = 1024);

// The portal-region methods' scoring (outside the benchmark's clock): each visible cell's NDC rect
// as its bounds and the union area of its region's polygons (~25x the cost of the build itself).
// `scratch` holds the polygons between calls.
void measure_regions(const VisibleSet& visible, std::vector<std::vector<glm::dvec2>>& scratch, MethodResult& out);

}  // namespace lintel
