// One interface for every visibility method the accuracy benchmark compares (docs/accuracy.md):
// Lintel's polygon regions at several snap lattices and caps, one screen rect per cell
// (Descent / Doom 3), per-portal plane sets (Godot), the view frustum alone, everything, and the
// exact CGAL oracle (Lintel::oracle, built on this header). Tests and benchmarks only.
#pragma once

#include <lintel/status.h>
#include <lintel/view.h>
#include <lintel/world.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace lintel {

// What one method decided for one view. Vectors are sized to the world (cells / instances).
struct MethodResult {
  std::vector<uint8_t> cell_visible;      // 1: the method draws the cell
  std::vector<uint8_t> instance_visible;  // 1: the method draws the instance
  // Per cell: NDC area of its clip region (the full screen is 4). Methods without a screen
  // region (planes) write a negative value: "not measured".
  std::vector<double> cell_region_area;
  // Per cell: bounds of its region in NDC as (min x, min y, max x, max y); NaN where the method
  // has no screen region (planes). Compared against the exact oracle's bounds ("drift").
  std::vector<glm::dvec4> cell_bounds;
  uint64_t pops = 0;       // cells processed (a frustum/none method processes each cell once)
  bool bound_hit = false;  // a safety stop or depth cap fired (results are what was reached)

  void reset(const World& world);  // sizes and zeroes everything for `world`
};

class CullMethod {
 public:
  virtual ~CullMethod() = default;
  virtual std::string name() const = 0;      // "polygon", "rect", ...
  virtual std::string settings() const = 0;  // "lattice=1024 cap=16", "" when none
  // Whether the method claims it never culls what is visible (a false negative is then a bug).
  virtual bool claims_conservative() const = 0;
  // Fills `out` for `view` with the eye in `start_cell`: `out` reset for `world`, then
  // find_visible(). Errors: bad view or start cell.
  Status run(const World& world, const View& view, uint32_t start_cell, MethodResult& out) {
    out.reset(world);
    return find_visible(world, view, start_cell, out);
  }
  // The visibility work alone, which is what the benchmark times (it resets `out` before its
  // clock starts: sizing and zeroing the per-cell and per-instance arrays is the benchmark's
  // bookkeeping, not the method's). `out` has been reset for `world`. Methods whose region areas
  // or bounds cost real work (polygon unions, exact sets) leave them to measure().
  virtual Status find_visible(const World& world, const View& view, uint32_t start_cell, MethodResult& out) = 0;
  // Completes `out` after a successful run() with the scoring data only (cell_region_area,
  // cell_bounds) that run() left out; outside the benchmark's clock. Default: run() wrote them.
  virtual void measure(MethodResult& out) { (void)out; }
  // Called before run() on the same view, outside the clock: what a method that carries state
  // from frame to frame (portal+hiz's last-frame visibility) knows from the frames before this
  // one. Default: nothing.
  virtual Status warm_up(const World& world, const View& view, uint32_t start_cell) {
    (void)world, (void)view, (void)start_cell;
    return {};
  }
};

// run() then measure(): a full result, for tests and tools that do not time the method.
inline Status run_and_measure(CullMethod& method, const World& world, const View& view, uint32_t start_cell,
                              MethodResult& out) {
  Status s = method.run(world, view, start_cell, out);
  if (s) method.measure(out);
  return s;
}

// Lintel's VisibilityBuilder with these options (instances culled against the regions).
std::unique_ptr<CullMethod> make_polygon_method(uint32_t snap_lattice_cells, uint32_t reprocess_cap,
                                                uint32_t max_region_polygons = 8);
// One NDC rect per cell: the bounds of each projected portal intersected with the current rect,
// unions that only grow, on a lattice of `lattice_cells` per axis (outward rounding: finite).
// ndc_first: the broken projection some engines ship, every vertex divided by w before any near
// clip (vertices behind the eye mirror across the screen); kept to show where it fails
// (stability suite), so it does not claim to be conservative.
std::unique_ptr<CullMethod> make_rect_method(uint32_t lattice_cells = 4096, bool ndc_first = false);
// Godot-style plane sets: a portal passes if no plane of the current set has all its vertices
// outside; its own edge planes from the eye then replace the set. Depth-first, depth <= max_depth.
std::unique_ptr<CullMethod> make_planes_method(uint32_t max_depth = 16);
// No portals: every cell / instance whose world box meets the view frustum.
std::unique_ptr<CullMethod> make_frustum_method();
// Everything is drawn.
std::unique_ptr<CullMethod> make_none_method();

// Where `portal+hiz` takes its last frame from (hiz_method.cpp, docs/accuracy.md "portal+hiz").
enum class HizHistory : uint8_t {
  Still,  // the same view: two frames untimed (warm_up) before the timed one, a camera at rest
  Cut,    // the previous run() call's view, whatever it was: a camera cut on every frame
};
// The polygon method (lattice 1024, cap 16), then two-phase hierarchical-Z occlusion inside the
// visible cells, as niagara does it: draw the shells and instances visible last frame into a
// conservative depth buffer of size x size texels (occlusion_raster.h), build the max pyramid,
// test every portal-visible shell and instance against it, draw what passes and was not drawn,
// keep what passed as the next frame's "visible last frame". Instances seen only through linked
// portals are the polygon method's (none are scored). size: a power of two in [1, 4096].
std::unique_ptr<CullMethod> make_portal_hiz_method(uint32_t size = 128, HizHistory history = HizHistory::Still);

// World-space AABB of a cell's volume box (cell_to_world applied to the 8 corners).
Aabb cell_bounds_world(const World& world, uint32_t cell);

}  // namespace lintel
