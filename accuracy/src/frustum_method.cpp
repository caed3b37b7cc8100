// The two baselines without portals: `frustum` (every cell and instance whose world box meets the
// view frustum, the culling an engine does with no cell structure) and `none` (draw everything).
// They bound the portal methods from above: any portal method should draw no more than these.
#include <lintel/reference/cull_method.h>
#include <lintel/view_lens.h>
#include <lintel/instance_cull.h>

#include <array>

namespace lintel {
namespace {

bool box_in_frustum(const glm::dmat4& vp, const glm::dvec3& eye, const Aabb& b) {
  if (b.empty()) return false;
  const ProjectedBox p = project_aabb(vp, eye, glm::dvec3(b.min), glm::dvec3(b.max));
  return p.contains_eye || (p.in_slab && p.rect_ndc.overlaps(full_screen_rect()));
}

class FrustumMethod final : public CullMethod {
 public:
  explicit FrustumMethod(bool cull) : cull_(cull) {}
  std::string name() const override { return cull_ ? "frustum" : "none"; }
  std::string settings() const override { return ""; }
  bool claims_conservative() const override { return true; }

  Status find_visible(const World& world, const View& view, uint32_t start_cell, MethodResult& out) override {
    if (Status s = validate_view(view); !s) return s;
    if (start_cell >= world.cells.size()) return Status::error(name() + ": start cell out of range");
    lens_.update(view);  // like the builder: the lens's trigonometry once, not per view (view_lens.h)
    const glm::dmat4 vp = lens_.view_projection(view);
    const glm::dvec3 eye(view.eye_world);
    for (uint32_t c = 0; c < world.cells.size(); ++c) {
      ++out.pops;
      // The start cell is drawn whatever its box says (the eye is in it).
      const bool v = !cull_ || c == start_cell || box_in_frustum(vp, eye, cell_bounds_world(world, c));
      out.cell_visible[c] = v ? 1 : 0;
      out.cell_region_area[c] = v ? 4.0 : 0.0;
      if (v) out.cell_bounds[c] = glm::dvec4(-1.0, -1.0, 1.0, 1.0);
    }
    for (size_t i = 0; i < world.instances.size(); ++i)
      out.instance_visible[i] = (!cull_ || box_in_frustum(vp, eye, world.instances[i].bounds_world)) ? 1 : 0;
    return {};
  }

 private:
  bool cull_;
  ViewLens lens_;
};

}  // namespace

std::unique_ptr<CullMethod> make_frustum_method() { return std::make_unique<FrustumMethod>(true); }
std::unique_ptr<CullMethod> make_none_method() { return std::make_unique<FrustumMethod>(false); }

}  // namespace lintel
