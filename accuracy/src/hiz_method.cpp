// The `portal+hiz` method: Lintel's portal visibility (the polygon method's builder at its
// defaults), then two-phase hierarchical-Z occlusion inside the visible cells, the scheme of
// niagara (Kapoulkine; Haar and Aaltonen, "GPU-Driven Rendering Pipelines", SIGGRAPH 2015):
//   1. draw what was visible last frame (and is in a visible cell now) into the depth buffer, and
//      the shells of every visible cell whatever last frame said (Lintel's change: walls are
//      the main occluders and almost never hidden, and a camera that enters a cell or cuts to a
//      new view has them in the pyramid at once);
//   2. build the depth pyramid from it;
//   3. test every portal-visible shell and instance against the pyramid;
//   4. draw those that pass and were not drawn in 1 (the newly visible);
//   5. what passed in 3 is next frame's "visible last frame".
// Conservative whatever the history: the pyramid holds only surfaces drawn this frame from this
// camera, and occlusion_raster.h rejects a box only where those surfaces provably lie in front of
// it over its whole screen rect. History decides how much is culled, never whether something
// visible is. Step 4's drawing is the renderer's work, not the cull's: the CPU model leaves it out.
#include <lintel/reference/cull_method.h>
#include <lintel/reference/occlusion_raster.h>
#include <lintel/reference/ray_ground_truth.h>
#include <lintel/reference/region_area.h>
#include <lintel/visibility_builder.h>

#include <algorithm>

namespace lintel {
namespace {

class PortalHizMethod final : public CullMethod {
 public:
  PortalHizMethod(uint32_t size, HizHistory history) : size_(size), history_mode_(history) {}
  std::string name() const override { return "portal+hiz"; }
  std::string settings() const override {
    return "res=" + std::to_string(size_) + (history_mode_ == HizHistory::Still ? " history=still" : " history=cut");
  }
  bool claims_conservative() const override { return true; }

  Status warm_up(const World& world, const View& view, uint32_t start_cell) override {
    if (history_mode_ != HizHistory::Still) return {};
    prepare(world);
    std::fill(history_.begin(), history_.end(), uint8_t{0});
    // Frame 1 from nothing draws only the shells first; frame 2 draws frame 1's survivors; the
    // timed frame draws frame 2's survivors first: the camera's steady state.
    for (int frame = 0; frame < 2; ++frame)
      if (Status s = run(world, view, start_cell, scratch_); !s) return s;
    return {};
  }

  // Scoring only: the portal regions' areas and bounds, as the polygon method reports them.
  void measure(MethodResult& out) override { measure_regions(visible_, polys_, out); }

  Status find_visible(const World& world, const View& view, uint32_t start_cell, MethodResult& out) override {
    if (Status s = builder_.build(world, view, start_cell, options_, visible_); !s) return s;
    prepare(world);
    out.pops = visible_.stats.pops;
    out.bound_hit = visible_.stats.bound_exceeded;
    const size_t cells = world.cells.size();
    // Phase 1: last frame's visible shells and instances, if portal-visible now.
    shell_drawn_.assign(cells, 0);
    for (const VisibleCell& c : visible_.cells)
      shell_drawn_[c.cell] = world.cells[c.cell].shell_mesh >= 0;  // shells first, always
    // A portal whose two shells are both drawn: their reveals meet there up to the rim radius.
    for (size_t p = 0; p < world.portals.size(); ++p)
      sealed_[p] = shell_drawn_[world.portals[p].from] && shell_drawn_[world.portals[p].to];
    buffer_.begin(view, size_, rim_pad_m_);
    for (const VisibleCell& c : visible_.cells)
      if (shell_drawn_[c.cell] && occludes_[c.cell]) buffer_.add_mesh(occluders_[c.cell], sealed_);
    for (uint32_t i : visible_.instances)
      if (history_[cells + i] && occludes_[cells + i]) buffer_.add_mesh(occluders_[cells + i]);
    buffer_.build_pyramid();
    // Phase 2: every portal-visible drawable against the pyramid. Drawn: phase 1's or passing now.
    next_.assign(history_.size(), 0);
    for (const VisibleCell& c : visible_.cells) {
      if (world.cells[c.cell].shell_mesh < 0) continue;
      next_[c.cell] = !buffer_.box_occluded(occluders_[c.cell].bounds_world);
      out.cell_visible[c.cell] = shell_drawn_[c.cell] | next_[c.cell];  // the shell is drawn
    }
    for (uint32_t i : visible_.instances) {
      next_[cells + i] = !buffer_.box_occluded(occluders_[cells + i].bounds_world);
      out.instance_visible[i] = history_[cells + i] | next_[cells + i];
      // A cell is drawn when its shell or one of its own instances is (the ground truth's rule).
      const uint32_t own = world.instances[i].cell;
      if (out.instance_visible[i] && visible_.cell_visible(own)) out.cell_visible[own] = 1;
    }
    history_.swap(next_);
    return {};
  }

 private:
  // Occluder meshes of every shell and instance, built once per world (the accuracy worlds do not
  // change between views).
  void prepare(const World& world) {
    if (world_ == &world && revision_ == world.revision) return;
    world_ = &world;
    revision_ = world.revision;
    const size_t cells = world.cells.size();
    occluders_.assign(cells + world.instances.size(), OccluderMesh{});
    // Cut-outs and see-through surfaces hide nothing here: the ground truth sees through their
    // holes and through glass, and this depth buffer would have to know where the holes are.
    occludes_.assign(occluders_.size(), 0);
    for (uint32_t c = 0; c < cells; ++c)
      if (world.cells[c].shell_mesh >= 0)
        occludes_[c] = world.meshes[size_t(world.cells[c].shell_mesh)].alpha_mode == Mesh::AlphaMode::Opaque;
    for (size_t i = 0; i < world.instances.size(); ++i)
      occludes_[cells + i] = world.meshes[world.instances[i].mesh].alpha_mode == Mesh::AlphaMode::Opaque;
    // The ground truth's rim radius per portal (ray_ground_truth.h): the larger float error of its cells.
    std::vector<double> error, rim(world.portals.size(), 0.0);
    scene_float_error_m(world, &error);
    rim_pad_m_ = 0.0;
    for (size_t p = 0; p < world.portals.size(); ++p) {
      rim[p] = std::max(error[world.portals[p].from], error[world.portals[p].to]);
      rim_pad_m_ = std::max(rim_pad_m_, 4.0 * rim[p]);
    }
    sealed_.assign(world.portals.size(), 0);
    for (uint32_t c = 0; c < cells; ++c)
      if (world.cells[c].shell_mesh >= 0) {
        occluders_[c] =
            make_occluder_mesh(world.meshes[size_t(world.cells[c].shell_mesh)], world.cells[c].cell_to_world);
        mark_portal_rims(world, c, rim, occluders_[c]);
      }
    for (size_t i = 0; i < world.instances.size(); ++i)
      occluders_[cells + i] =
          make_occluder_mesh(world.meshes[world.instances[i].mesh], world.instances[i].mesh_to_world);
    history_.assign(occluders_.size(), 0);
  }

  uint32_t size_;
  HizHistory history_mode_;
  VisibilityOptions options_;  // the polygon method's defaults
  VisibilityBuilder builder_;
  VisibleSet visible_;
  OcclusionBuffer buffer_;
  const World* world_ = nullptr;
  uint64_t revision_ = 0;
  std::vector<OccluderMesh> occluders_;        // cells' shells, then instances
  std::vector<uint8_t> history_, next_;        // per drawable: passed the occlusion test last frame
  std::vector<uint8_t> occludes_;              // per drawable: opaque, so drawn into the depth buffer
  std::vector<uint8_t> shell_drawn_, sealed_;  // per cell: shell drawn in phase 1; per portal: both are
  double rim_pad_m_ = 0.0;
  MethodResult scratch_;
  std::vector<std::vector<glm::dvec2>> polys_;
};

}  // namespace

std::unique_ptr<CullMethod> make_portal_hiz_method(uint32_t size, HizHistory history) {
  return std::make_unique<PortalHizMethod>(size, history);
}

}  // namespace lintel
