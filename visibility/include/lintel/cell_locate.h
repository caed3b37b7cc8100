// Which cell holds a point: containment in cell volumes, the fallback of the viewer tracker and
// how a tool picks a start cell for an eye position.
// A cell's volume is Cell::volume_triangles_cell (a closed triangle mesh in cell space) or, when
// that is empty, Cell::volume_box_cell. Containment is tested in cell space (invariant under the
// cell transform); distances and volumes are world-space meters / cubic meters.
#pragma once

#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace lintel {

// Closed containment. Triangle volumes use the generalized winding number (|w| > 1/2), which is
// robust to ray-through-edge cases a parity ray cast has; either triangle winding works.
bool cell_volume_contains(const World& world, uint32_t cell, const glm::dvec3& p_world);

// World-space distance from p to the volume's surface, 0 when contained; +infinity when the cell
// has no volume at all (empty box and no triangles).
double cell_volume_distance_m(const World& world, uint32_t cell, const glm::dvec3& p_world);

// World-space distance from p to the volume's surface (its triangles, or the box's faces), inside
// or outside; +infinity when the cell has no volume. A point contained with clearance r stays
// contained while it moves less than r (the moving instances' shortcut, dynamic_instances.h).
double cell_volume_clearance_m(const World& world, uint32_t cell, const glm::dvec3& p_world);

// World-space size of the volume (cubic meters, >= 0).
double cell_volume_m3(const World& world, uint32_t cell);
// cell_volume_m3 for every cell (allocates; call once per World).
std::vector<double> cell_volumes_m3(const World& world);

enum class LocateReason : uint8_t { Containment, Nearest };
struct CellLocation {
  uint32_t cell = 0;
  LocateReason reason = LocateReason::Containment;
  double distance_m = 0.0;  // 0 for containment
};

// The cell holding p: among cells whose volume contains it the smallest volume (ties: lower
// index); if none contains it, the nearest volume (ties: lower index). Precondition: the world
// has cells; `volumes_m3` is empty (computed on the fly) or cell_volumes_m3(world).
// Does not allocate.
CellLocation locate_cell(const World& world, const glm::dvec3& p_world, std::span<const double> volumes_m3 = {});

}  // namespace lintel
