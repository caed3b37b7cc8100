// The `planes` method, as Godot 3's rooms & portals: no screen regions and no clipping. A portal
// passes if no plane of the current set has all its vertices outside; the planes from the eye
// through the portal's edges (plus the far plane) then replace the set for the cell behind it.
// Depth-first along every path that does not revisit a cell already on it, at most `max_depth`
// portals deep (Godot's limit is 16): cells farther away are dropped, which is why this method
// does not claim to be conservative. A hard stop on the number of visits bounds the exponential
// number of paths in cyclic graphs (reported as bound_hit).
#include <lintel/reference/cull_method.h>
#include <lintel/view_lens.h>
#include <lintel/doorway_rule.h>

#include <cmath>

namespace lintel {
namespace {

using PlaneSet = std::vector<glm::dvec4>;  // inside: dot(xyz, p) + w >= 0

constexpr uint64_t kMaxVisitsPerCell = 4096;

bool box_outside(const PlaneSet& planes, const Aabb& b) {
  for (const glm::dvec4& pl : planes) {
    const glm::dvec3 p(pl.x >= 0 ? b.max.x : b.min.x, pl.y >= 0 ? b.max.y : b.min.y, pl.z >= 0 ? b.max.z : b.min.z);
    if (glm::dot(glm::dvec3(pl), p) + pl.w < 0.0) return true;
  }
  return false;
}

class PlanesMethod final : public CullMethod {
 public:
  explicit PlanesMethod(uint32_t depth) : max_depth_(depth) {}
  std::string name() const override { return "planes"; }
  std::string settings() const override { return "depth=" + std::to_string(max_depth_); }
  bool claims_conservative() const override { return false; }

  Status find_visible(const World& world, const View& view, uint32_t start_cell, MethodResult& out) override {
    if (Status s = validate_view(view); !s) return s;
    if (start_cell >= world.cells.size()) return Status::error("planes: start cell out of range");
    world_ = &world;
    view_ = &view;
    out_ = &out;
    eye_ = glm::dvec3(view.eye_world);
    lens_.update(view);  // like the builder: the lens's trigonometry once, not per view (view_lens.h)
    near_extent_ = lens_.near_extent;
    on_path_.assign(world.cells.size(), 0);
    hard_stop_ = kMaxVisitsPerCell * world.cells.size();
    // The frustum's six planes (Gribb & Hartmann) from the clip convention of view.h.
    const glm::dmat4 m = glm::transpose(lens_.view_projection(view));
    PlaneSet frustum{m[3] + m[0], m[3] - m[0], m[3] + m[1], m[3] - m[1], m[2], m[3] - m[2]};
    far_plane_ = m[3] - m[2];
    visit(start_cell, frustum, 0);
    for (size_t c = 0; c < world.cells.size(); ++c) out.cell_region_area[c] = out.cell_visible[c] ? -1.0 : 0.0;
    return {};
  }

 private:
  void visit(uint32_t cell, const PlaneSet& planes, uint32_t depth) {
    if (out_->pops >= hard_stop_) {
      out_->bound_hit = true;
      return;
    }
    ++out_->pops;
    out_->cell_visible[cell] = 1;
    for (uint32_t i : world_->cells[cell].instances)
      if (!box_outside(planes, world_->instances[i].bounds_world)) out_->instance_visible[i] = 1;
    if (depth >= max_depth_) {
      if (!world_->cells[cell].links.empty()) out_->bound_hit = true;
      return;
    }
    on_path_[cell] = 1;
    for (const PortalLink& link : world_->cells[cell].links) {
      const Portal& portal = world_->portals[link.portal];
      if (portal.from != cell && (portal.to != cell || !portal.two_way)) continue;
      if (on_path_[link.neighbour]) continue;
      const double s = portal_signed_distance(portal, cell, eye_);
      if (std::abs(s) <= double(view_->near_m) && projects_inside_portal(portal, eye_, near_extent_)) {
        visit(link.neighbour, planes, depth + 1);  // Doom 3's bypass: keep the planes as they are
        continue;
      }
      if (!(s < 0.0) || !portal_passes(portal, planes)) continue;
      visit(link.neighbour, edge_planes(portal), depth + 1);
    }
    on_path_[cell] = 0;
  }

  bool portal_passes(const Portal& portal, const PlaneSet& planes) const {
    for (const glm::dvec4& pl : planes) {
      bool all_out = true;
      for (const glm::vec3& v : portal.polygon_world)
        if (glm::dot(glm::dvec3(pl), glm::dvec3(v)) + pl.w >= 0.0) {
          all_out = false;
          break;
        }
      if (all_out) return false;
    }
    return true;
  }

  PlaneSet edge_planes(const Portal& portal) const {
    PlaneSet planes{far_plane_};
    const glm::dvec3 centroid(portal.centroid_world);
    const size_t n = portal.polygon_world.size();
    for (size_t i = 0; i < n; ++i) {
      const glm::dvec3 a(portal.polygon_world[i]), b(portal.polygon_world[(i + 1) % n]);
      glm::dvec3 nrm = glm::cross(a - eye_, b - eye_);
      const double len = glm::length(nrm);
      // Nearly degenerate edge planes are dropped, as The Dark Mod does: fewer planes, larger set.
      if (!(len > 1e-12 * glm::length(a - eye_) * glm::length(b - eye_))) continue;
      nrm /= len;
      if (glm::dot(nrm, centroid - eye_) < 0.0) nrm = -nrm;
      planes.emplace_back(nrm, -glm::dot(nrm, eye_));
    }
    return planes;
  }

  uint32_t max_depth_;
  ViewLens lens_;
  const World* world_ = nullptr;
  const View* view_ = nullptr;
  MethodResult* out_ = nullptr;
  glm::dvec3 eye_{0.0};
  glm::dvec4 far_plane_{0.0};
  double near_extent_ = 0.0;
  uint64_t hard_stop_ = 0;
  std::vector<uint8_t> on_path_;
};

}  // namespace

std::unique_ptr<CullMethod> make_planes_method(uint32_t max_depth) { return std::make_unique<PlanesMethod>(max_depth); }

}  // namespace lintel
