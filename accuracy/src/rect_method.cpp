// The `rect` method: one NDC rect per cell, as Descent and Tomb Raider 2 kept integer screen
// rects and Doom 3 its portal scissor: the bounds of each projected portal intersected with the
// current rect, unions that only grow. Rects are rounded outward to a lattice, so each side can
// move at most `lattice` times: at most 4 * lattice + 1 pops per cell (termination). Near clipping
// and the doorway rule are Lintel's own (portal_clip.h, doorway_rule.h), so only the region
// shape differs from the polygon method.
#include <lintel/reference/cull_method.h>
#include <lintel/view_lens.h>
#include <lintel/doorway_rule.h>
#include <lintel/instance_cull.h>
#include <lintel/instance_reach.h>
#include <lintel/portal_clip.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace lintel {
namespace {

class RectMethod final : public CullMethod {
 public:
  RectMethod(uint32_t lattice, bool ndc_first) : lattice_(lattice), ndc_first_(ndc_first) {}
  std::string name() const override { return ndc_first_ ? "rect-ndc-first" : "rect"; }
  std::string settings() const override { return "lattice=" + std::to_string(lattice_); }
  bool claims_conservative() const override { return !ndc_first_; }

  Status find_visible(const World& world, const View& view, uint32_t start_cell, MethodResult& out) override {
    if (Status s = validate_view(view); !s) return s;
    if (start_cell >= world.cells.size()) return Status::error("rect: start cell out of range");
    const size_t n_cells = world.cells.size();
    rects_.assign(n_cells, NdcRect{});
    queued_.assign(n_cells, 0);
    queue_.clear();
    lens_.update(view);  // like the builder: the lens's trigonometry once, not per view (view_lens.h)
    const glm::dmat4 vp = lens_.view_projection(view);
    const glm::dvec3 eye(view.eye_world);
    const double near_extent = lens_.near_extent;
    const double clip_depth = lens_.clip_depth;
    const uint64_t hard_stop = uint64_t(n_cells) * (4ull * lattice_ + 1);

    rects_[start_cell] = full_screen_rect();
    queue_.push_back(start_cell);
    queued_[start_cell] = 1;
    for (size_t head = 0; head < queue_.size(); ++head) {
      if (out.pops >= hard_stop) {
        out.bound_hit = true;
        break;
      }
      const uint32_t cell = queue_[head];
      queued_[cell] = 0;
      ++out.pops;
      const NdcRect current = rects_[cell];
      for (const PortalLink& link : world.cells[cell].links) {
        const Portal& portal = world.portals[link.portal];
        if (portal.from != cell && (portal.to != cell || !portal.two_way)) continue;
        NdcRect through;
        const double s = portal_signed_distance(portal, cell, eye);
        if (std::abs(s) <= double(view.near_m) && projects_inside_portal(portal, eye, near_extent)) {
          through = current;  // doorway rule
        } else {
          if (!(s < 0.0)) continue;
          const size_t nv = portal.polygon_world.size();
          for (size_t i = 0; i < nv; ++i) clip_in_[i] = vp * glm::dvec4(glm::dvec3(portal.polygon_world[i]), 1.0);
          SlabClipResult r;
          if (ndc_first_) {
            // Divide first, as naive engines do: a vertex behind the eye (w < 0) lands mirrored
            // on the wrong side of the screen. Only w == 0 exactly is nudged, to stay finite.
            for (size_t i = 0; i < nv; ++i) {
              slab_[i] = clip_in_[i];
              if (slab_[i].w == 0.0) slab_[i].w = 1e-12;
            }
            r.count = uint32_t(nv);
          } else {
            r = clip_to_depth_slab(std::span<const glm::dvec4>(clip_in_.data(), nv), clip_depth, slab_, scratch_);
          }
          if (r.count < 3) continue;
          for (uint32_t i = 0; i < r.count; ++i) {
            const glm::dvec2 p(slab_[i].x / slab_[i].w, slab_[i].y / slab_[i].w);
            through.extend(glm::vec2(float(outward(p.x, false)), float(outward(p.y, false))));
            through.extend(glm::vec2(float(outward(p.x, true)), float(outward(p.y, true))));
          }
          through.min = glm::max(through.min, current.min);
          through.max = glm::min(through.max, current.max);
          if (through.empty() || through.min.x == through.max.x || through.min.y == through.max.y) continue;
        }
        NdcRect& dst = rects_[link.neighbour];
        if (dst.contains(through)) continue;
        dst.extend(through);
        if (!queued_[link.neighbour]) {
          queued_[link.neighbour] = 1;
          queue_.push_back(link.neighbour);
        }
      }
    }
    for (size_t c = 0; c < n_cells; ++c) {
      if (rects_[c].empty()) continue;
      out.cell_visible[c] = 1;
      const glm::vec2 e = rects_[c].max - rects_[c].min;
      out.cell_region_area[c] = double(e.x) * double(e.y);
      out.cell_bounds[c] = glm::dvec4(rects_[c].min.x, rects_[c].min.y, rects_[c].max.x, rects_[c].max.y);
    }
    if (reach_world_ != &world || reach_.instance_count() != world.instances.size()) {
      reach_.compute(world);  // once per world: instances are listed from every cell they reach
      reach_world_ = &world;
    }
    for (uint32_t i = 0; i < world.instances.size(); ++i) {
      const Instance& inst = world.instances[i];
      bool any_visible = false;
      for (const uint32_t* c = reach_.begin(i); c != reach_.end(i); ++c)
        any_visible = any_visible || out.cell_visible[*c];
      if (!any_visible) continue;
      const ProjectedBox box =
          project_aabb(vp, eye, glm::dvec3(inst.bounds_world.min), glm::dvec3(inst.bounds_world.max));
      for (const uint32_t* c = reach_.begin(i); c != reach_.end(i) && !out.instance_visible[i]; ++c) {
        if (!out.cell_visible[*c]) continue;
        const NdcRect& r = rects_[*c];
        const std::array<glm::vec2, 4> quad{r.min, glm::vec2(r.max.x, r.min.y), r.max, glm::vec2(r.min.x, r.max.y)};
        const RegionPolygon poly{0, 4};
        const ClipRegionView region{std::span<const RegionPolygon>(&poly, 1), quad, r};
        out.instance_visible[i] = box_visible_in_region(box, region) ? 1 : 0;
      }
    }
    return {};
  }

 private:
  // Rounds an NDC coordinate outward (up or down) to the lattice, clamped to the screen.
  double outward(double v, bool up) const {
    const double step = 2.0 / lattice_;
    const double k = (v + 1.0) / step;
    const double snapped = -1.0 + (up ? std::ceil(k) : std::floor(k)) * step;
    return std::clamp(snapped, -1.0, 1.0);
  }

  uint32_t lattice_;
  bool ndc_first_;
  ViewLens lens_;
  InstanceReach reach_;
  const World* reach_world_ = nullptr;
  std::vector<NdcRect> rects_;
  std::vector<uint8_t> queued_;
  std::vector<uint32_t> queue_;
  std::array<glm::dvec4, kMaxPortalVertices> clip_in_{};
  std::array<glm::dvec4, kMaxSlabClippedVertices> slab_{}, scratch_{};
};

}  // namespace

std::unique_ptr<CullMethod> make_rect_method(uint32_t lattice_cells, bool ndc_first) {
  return std::make_unique<RectMethod>(lattice_cells, ndc_first);
}

}  // namespace lintel
