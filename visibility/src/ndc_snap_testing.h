// Test-only: the snap computed the way it was first written (every corner as a double, the hull in
// double), the reference the integer lattice path is checked against bit for bit. Reached like
// visibility_builder_testing.h (tests add visibility/src to their include path); never installed.
#pragma once

#include <lintel/ndc_snap.h>

namespace lintel::detail {

// Same contract and output as snap_polygon_conservative.
uint32_t snap_polygon_by_double_hull(std::span<const glm::dvec2> poly_ndc, uint32_t lattice_cells,
                                     std::span<glm::vec2> out, SnapScratch& scratch);

}  // namespace lintel::detail
