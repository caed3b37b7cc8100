// The exact oracle: Lintel's portal traversal with exact arithmetic (CGAL's Epeck kernel) and
// exact polygon sets (unions, no snapping, no polygon limit, no re-process cap). Its regions are
// the tightest conservative ones any portal method with Lintel's near handling can reach: the
// screen intersected, portal by portal, with the exact projections of the portals (clipped in
// homogeneous space at portal_clip_depth, the doorway rule passing regions through unchanged).
// Tests and benchmarks only (CGAL compiles slowly and allocates freely).
//
// Termination: every region is a union of pieces, each the screen intersected with the
// projections of the portals along one path. A path that revisits a (cell, portal) pair adds
// nothing new that a shorter path did not (the pieces only shrink along a path), so the regions
// take values in a finite lattice of unions of finitely many pieces, each change strictly grows
// a region, and the flood stops. A hard stop (kExactOracleMaxPopsPerCell per cell) is kept anyway
// and reported through MethodResult::bound_hit.
#pragma once

#include <lintel/reference/cull_method.h>

#include <glm/glm.hpp>

#include <memory>
#include <vector>

namespace lintel {

inline constexpr uint64_t kExactOracleMaxPopsPerCell = 4096;

// The `exact` method. Instances are decided as Lintel decides them (instance_cull.h: the NDC rect
// of the near/far-clipped world AABB against the region), with the exact region.
std::unique_ptr<CullMethod> make_exact_method();

// The exact regions of the last run + measure() of an `exact` method, as double polygons (outer boundaries
// only), for drift measurements: regions[cell] is empty when the cell is not visible.
// Precondition: `method` came from make_exact_method().
const std::vector<std::vector<std::vector<glm::dvec2>>>& exact_regions_of(const CullMethod& method);

}  // namespace lintel
