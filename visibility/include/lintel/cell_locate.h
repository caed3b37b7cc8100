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

// cell_volume_contains for many points of one World: each volume triangle's bounds across the
// containment ray (which runs just off +x) are taken once and filed in a grid along the ray's
// cross-section, so that a test meets only the triangles whose bounds hold its point instead of
// every triangle of the volume. The same answer as cell_volume_contains for every cell and point
// (tests/visibility/test_cell_volume_index.cpp); the loader orients each portal with it.
class CellVolumeIndex {
 public:
  // Allocates (about 70 bytes per volume triangle); build again when a cell's volume changes.
  void build(const World& world);
  // cell_volume_contains(world, cell, p_world), `world` being the one built from. Does not allocate.
  bool contains(const World& world, uint32_t cell, const glm::dvec3& p_world) const;

 private:
  struct Shadow {  // a triangle's bounds across the ray (widened by a few ulps) and along it
    double u_lo, u_hi, v_lo, v_hi, x_hi;
    uint32_t triangle;  // within the cell
    double lo(int axis) const { return axis == 0 ? u_lo : v_lo; }
    double hi(int axis) const { return axis == 0 ? u_hi : v_hi; }
  };
  struct CellEntry {
    size_t first_shadow = 0, triangles = 0;
    bool sorted = false;                   // shadows by x_hi descending (all vertices finite)
    size_t first_bucket = 0, buckets = 0;  // buckets == 0: no grid, every triangle is met
    int axis = 0;                          // the grid runs along u (0) or v (1)
    double min = 0.0, max = 0.0, buckets_per_unit = 0.0;
    size_t bucket_of(double x) const;
  };
  std::vector<CellEntry> cells_;
  std::vector<Shadow> shadows_;
  std::vector<size_t> bucket_begin_;  // per cell with a grid, its buckets + 1 offsets into filed_
  std::vector<uint32_t> filed_;       // per bucket, positions in the cell's shadows (ascending)
};

// Which cells' volumes may hold a point: a uniform grid over the cells' world-space volume boxes,
// so that locating a moving object by containment tests a handful of cells instead of every one
// (mover_bench's doorway case located over 1,024 rooms on most frames of a crossing).
class CellGrid {
 public:
  // Allocates; once per World revision. About 4 buckets per cell at most.
  void build(const World& world);
  // The cells (ascending) whose world volume box, widened by more than the float error between a
  // cell's two frames, contains p: every cell cell_volume_contains() can accept is among them.
  std::span<const uint32_t> candidates(const glm::dvec3& p_world) const;
  // Distance from p to cell c's widened world volume box: a lower bound of
  // cell_volume_distance_m (0 inside the box; +infinity for a cell without a volume).
  double box_distance_m(uint32_t cell, const glm::dvec3& p_world) const;

 private:
  std::vector<Aabb> boxes_;  // per cell, widened
  glm::dvec3 origin_{0.0};
  double bucket_m_ = 1.0;
  glm::ivec3 dims_{0};
  std::vector<uint32_t> begin_, cells_;  // CSR: bucket -> cells
};

// The cell locate_cell finds by containment -- the smallest volume holding p,
// ties to the lower index -- testing only `grid`'s candidates; false when no volume holds p.
bool contained_cell(const World& world, const CellGrid& grid, const glm::dvec3& p_world,
                    std::span<const double> volumes_m3, uint32_t& cell);
// locate_cell with the containment pass over `grid`'s candidates, and the nearest-volume pass
// (no cell contains p) measuring only cells whose box lies no farther than the best so far: the
// same answer.
CellLocation locate_cell(const World& world, const CellGrid& grid, const glm::dvec3& p_world,
                         std::span<const double> volumes_m3);

}  // namespace lintel
