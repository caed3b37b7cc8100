// The `polygon` method: Lintel's own VisibilityBuilder (docs/visibility.md) behind the
// CullMethod interface, with the snap lattice, re-process cap and polygon limit as settings.
#include <lintel/reference/cull_method.h>
#include <lintel/reference/region_area.h>
#include <lintel/visibility_builder.h>

#include <limits>

namespace lintel {

void MethodResult::reset(const World& world) {
  cell_visible.assign(world.cells.size(), 0);
  instance_visible.assign(world.instances.size(), 0);
  cell_region_area.assign(world.cells.size(), 0.0);
  cell_bounds.assign(world.cells.size(), glm::dvec4(std::numeric_limits<double>::quiet_NaN()));
  pops = 0;
  bound_hit = false;
}

Aabb cell_bounds_world(const World& world, uint32_t cell) {
  return transform_aabb(world.cells[cell].cell_to_world, world.cells[cell].volume_box_cell);
}

namespace {

class PolygonMethod final : public CullMethod {
 public:
  explicit PolygonMethod(VisibilityOptions options) : options_(options) {}
  std::string name() const override { return "polygon"; }
  std::string settings() const override {
    return "lattice=" + std::to_string(options_.snap_lattice_cells) + " cap=" + std::to_string(options_.reprocess_cap);
  }
  bool claims_conservative() const override { return true; }

  Status find_visible(const World& world, const View& view, uint32_t start_cell, MethodResult& out) override {
    if (Status s = builder_.build(world, view, start_cell, options_, visible_); !s) return s;
    out.pops = visible_.stats.pops;
    out.bound_hit = visible_.stats.bound_exceeded;  // cap hits are by design, not a failure
    for (const VisibleCell& c : visible_.cells) out.cell_visible[c.cell] = 1;
    for (uint32_t i : visible_.instances) out.instance_visible[i] = 1;
    return {};
  }

  // Scoring only (outside the benchmark's clock): the union area of each region costs ~25x the
  // build itself.
  void measure(MethodResult& out) override { measure_regions(visible_, polys_, out); }

 private:
  VisibilityOptions options_;
  VisibilityBuilder builder_;
  VisibleSet visible_;
  std::vector<std::vector<glm::dvec2>> polys_;
};

}  // namespace

std::unique_ptr<CullMethod> make_polygon_method(uint32_t snap_lattice_cells, uint32_t reprocess_cap,
                                                uint32_t max_region_polygons) {
  VisibilityOptions o;
  o.snap_lattice_cells = snap_lattice_cells;
  o.reprocess_cap = reprocess_cap;
  o.max_region_polygons = max_region_polygons;
  return std::make_unique<PolygonMethod>(o);
}

}  // namespace lintel
