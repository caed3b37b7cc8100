// Property tests of the portal traversal on generated cyclic cell graphs with non-identity cell
// frames (rapidcheck). Each property is stated in words above its code. ctest runs a fixed seed
// and 1,000 cases per property; LINTEL_SOAK=1 runs 100,000; RC_PARAMS overrides both.
#include "camera_samples.h"
#include "world_pool.h"

#include <lintel/ray_ground_truth.h>
#include <lintel/scene_io.h>
#include <lintel/visibility_builder.h>

#include <rapidcheck.h>

#include <cstdio>
#include <iomanip>
#include <cstdlib>
#include <set>

namespace lintel::fuzz {
namespace {

std::vector<std::unique_ptr<PoolScene>>& pool() {
  static auto scenes = make_world_pool(/*count=*/60, /*seed=*/2026, /*max_cells=*/16);
  return scenes;
}

const PoolScene& pick_scene() {
  const auto& scenes = pool();
  const PoolScene& scene = *scenes[*rc::gen::inRange<size_t>(0, scenes.size())];
  RC_LOG() << "scene: lintel gen " << scene.label << "\n";
  return scene;
}

// Shrinks the near plane until its corners stay clear of every wall (see camera_samples.h).
void keep_near_plane_off_walls(const World& world, View& view) {
  const double clearance = distance_to_nearest_shell(world, glm::dvec3(view.eye_world));
  const double corner = near_corner_distance(view);
  if (corner > 0.9 * clearance) view.near_m = float(view.near_m * std::max(1e-4, 0.9 * clearance / corner));
}

std::set<uint32_t> cell_set(const VisibleSet& v) {
  std::set<uint32_t> cells;
  for (const VisibleCell& c : v.cells) cells.insert(c.cell);
  return cells;
}

void log_camera(const CameraSample& s) {
  RC_LOG() << std::setprecision(9) << "up " << s.view.up_world.x << "," << s.view.up_world.y << "," << s.view.up_world.z << " eye " << s.view.eye_world.x << "," << s.view.eye_world.y << "," << s.view.eye_world.z << " target "
           << s.view.target_world.x << "," << s.view.target_world.y << "," << s.view.target_world.z << " fov "
           << s.view.fov_y_deg << " aspect " << s.view.aspect << " near " << s.view.near_m << " start "
           << s.start_cell << " portal " << s.portal << " offset " << s.offset_m << "\n";
}

}  // namespace
}  // namespace lintel::fuzz

int main() {
  using namespace lintel;
  using namespace lintel::fuzz;
  const bool soak = std::getenv("LINTEL_SOAK") != nullptr;
  if (!std::getenv("RC_PARAMS"))
    setenv("RC_PARAMS", soak ? "max_success=100000 seed=77" : "max_success=1000 seed=20261121", 1);
  std::printf("building the scene pool (%zu scenes)...\n", pool().size());
  bool ok = true;

  // Termination: for any scene, any camera (eye anywhere, even inside walls or outside the
  // building), any start cell and any snap/cap/polygon settings, build() returns having popped
  // at most pop_bound() cells — the bound holds by construction, not by luck.
  ok &= rc::check("terminates within the documented pop bound", [] {
    const PoolScene& scene = pick_scene();
    const World& world = scene.world;
    View view;
    if (*rc::gen::element(0, 1)) {
      view = (*gen_camera_at_portal(world, false)).view;
    } else {
      Aabb box;
      for (const Instance& i : world.instances) box.extend(i.bounds_world);
      for (const Portal& p : world.portals) box.extend(p.centroid_world);
      const glm::vec3 e = box.extent();
      view.eye_world = box.min + e * glm::vec3(*rc::gen::inRange(0, 1001) / 1000.0f, *rc::gen::inRange(0, 1001) / 1000.0f,
                                               *rc::gen::inRange(0, 1001) / 1000.0f);
      view.target_world = view.eye_world + glm::vec3(*rc::gen::inRange(-100, 101), *rc::gen::inRange(-100, 101),
                                                     *rc::gen::inRange(-100, 101)) * 0.01f + glm::vec3(0.001f, 0, 0);
    }
    VisibilityOptions options;
    options.snap_lattice_cells = 1u << *rc::gen::inRange(1, 17);
    options.reprocess_cap = *rc::gen::inRange(0, 33);
    options.max_region_polygons = *rc::gen::inRange(1, 17);
    const uint32_t start = *rc::gen::inRange<uint32_t>(0, uint32_t(world.cells.size()));
    RC_PRE(validate_view(view).ok());
    VisibilityBuilder builder;
    VisibleSet visible;
    const Status s = builder.build(world, view, start, options, visible);
    RC_ASSERT(s.ok());
    RC_ASSERT(!visible.stats.bound_exceeded);
    RC_ASSERT(visible.stats.pops <= pop_bound(uint32_t(world.cells.size()), options));
  });

  // Conservative: every cell and instance that a ray from the eye through a pixel of a 32 x 32
  // grid hits first (Embree, all shells and instances, portals ignored) is in the visible set,
  // and the hit cell's region contains that pixel's NDC point within one snap cell. Rays running
  // inside a portal's plane are skipped: they see the float crack of the test geometry's wall
  // seam, not the building (camera_samples.h, ray_runs_in_portal_plane).
  ok &= rc::check("never loses a visible cell, instance or pixel", [] {
    const PoolScene& scene = pick_scene();
    CameraSample cam = *gen_camera_at_portal(scene.world, false);
    keep_near_plane_off_walls(scene.world, cam.view);
    log_camera(cam);
    VisibilityBuilder builder;
    VisibleSet visible;
    VisibilityOptions options;
    RC_ASSERT(builder.build(scene.world, cam.view, cam.start_cell, options, visible).ok());
    RayCamera rc_cam{cam.view.eye_world, cam.view.target_world, cam.view.up_world, cam.view.fov_y_deg,
                     cam.view.aspect, cam.view.near_m};
    GroundTruth truth;
    scene.rays.cast(rc_cam, 32, truth);
    const double tolerance = 2.0 / double(options.snap_lattice_cells);
    for (uint32_t j = 0; j < truth.resolution; ++j)
      for (uint32_t i = 0; i < truth.resolution; ++i) {
        const RayHitId hit = truth.pixels[size_t(j) * truth.resolution + i];
        if (hit.cell == RayHitId::kNone) continue;
        const glm::vec2 ndc = pixel_center_ndc(i, j, truth.resolution);
        if (ray_runs_in_portal_plane(scene.world, glm::dvec3(cam.view.eye_world), pixel_ray_direction(cam.view, ndc)))
          continue;
        const VisibleCell* vc = visible.find(hit.cell);
        RC_ASSERT(vc != nullptr);
        if (!visible.region(*vc).contains(glm::dvec2(ndc), tolerance)) {
          RC_LOG() << "pixel " << i << "," << j << " ndc " << ndc.x << "," << ndc.y << " hits cell " << hit.cell
                   << " instance " << int(hit.instance) << "; its region (reached from " << vc->reached_from
                   << ", collapsed " << vc->collapsed_to_rect << "): rect " << vc->rect_ndc.min.x << ","
                   << vc->rect_ndc.min.y << " .. " << vc->rect_ndc.max.x << "," << vc->rect_ndc.max.y << "\n";
          RC_FAIL("a pixel seeing a cell lies outside that cell's region");
        }
        if (hit.instance != RayHitId::kNone)
          RC_ASSERT(std::binary_search(visible.instances.begin(), visible.instances.end(), hit.instance));
      }
  });

  // Deterministic: the same world, view, start cell and options give a bit-identical VisibleSet,
  // from a fresh builder and from one that answered another query in between.
  ok &= rc::check("deterministic, bit for bit", [] {
    const PoolScene& scene = pick_scene();
    const CameraSample a = *gen_camera_at_portal(scene.world, false);
    const CameraSample b = *gen_camera_at_portal(scene.world, false);
    VisibilityBuilder first, second;
    VisibleSet va, vb;
    RC_ASSERT(first.build(scene.world, a.view, a.start_cell, {}, va).ok());
    RC_ASSERT(second.build(scene.world, b.view, b.start_cell, {}, vb).ok());
    RC_ASSERT(second.build(scene.world, a.view, a.start_cell, {}, vb).ok());
    RC_ASSERT(va == vb);
  });

  // Invariance: moving the whole building and the camera by one rigid motion (any rotation axis,
  // translations up to 1 km) leaves the set of visible cells unchanged.
  ok &= rc::check("invariant under a rigid motion of world and camera", [] {
    const PoolScene& scene = pick_scene();
    const CameraSample cam = *gen_camera_at_portal(scene.world, false);
    log_camera(cam);
    const glm::dvec3 axis = glm::normalize(glm::dvec3(*rc::gen::inRange(-100, 101), *rc::gen::inRange(-100, 101),
                                                      *rc::gen::inRange(-100, 101)) + glm::dvec3(0.0, 0.0, 1e-3));
    const double angle = *rc::gen::inRange(0, 6283) / 1000.0;
    const glm::dquat rotation = glm::angleAxis(angle, axis);
    const glm::dvec3 translation(*rc::gen::inRange(-1000, 1001), *rc::gen::inRange(-1000, 1001),
                                 *rc::gen::inRange(-1000, 1001));
    World moved;
    RC_ASSERT(build_world(rigidly_moved(scene.desc, rotation, translation), "moved", moved).ok());
    View moved_view = cam.view;
    moved_view.eye_world = glm::vec3(rotation * glm::dvec3(cam.view.eye_world) + translation);
    moved_view.target_world = glm::vec3(rotation * glm::dvec3(cam.view.target_world) + translation);
    moved_view.up_world = glm::vec3(rotation * glm::dvec3(cam.view.up_world));
    VisibilityBuilder builder;
    VisibleSet before, after;
    RC_ASSERT(builder.build(scene.world, cam.view, cam.start_cell, {}, before).ok());
    RC_ASSERT(builder.build(moved, moved_view, cam.start_cell, {}, after).ok());
    RC_ASSERT(cell_set(before) == cell_set(after));
  });

  // Doorway continuity: for an eye inside a two-way portal's polygon and at most 1 cm (a fifth of
  // the near distance) off its plane, the visible cells do not depend on which side's cell the
  // traversal starts from (the tracker may still say `from` a hair past the plane); and as the eye
  // moves across the plane within 0.1 mm (from -1e-4 m in `from` to +1e-4 m in `to`), the set stays
  // the same. (Across a full centimetre a new portal can legitimately slide onto the screen edge.)
  ok &= rc::check("visible cells are continuous across a doorway", [] {
    const PoolScene& scene = pick_scene();
    const World& world = scene.world;
    const CameraSample cam = *gen_camera_at_portal(world, true);
    log_camera(cam);
    const Portal& portal = world.portals[cam.portal];
    const glm::dvec3 n(portal.normal_world);
    const glm::dvec3 on_plane = glm::dvec3(cam.view.eye_world) - n * cam.offset_m;
    const glm::dvec3 dir = glm::dvec3(cam.view.target_world) - glm::dvec3(cam.view.eye_world);
    VisibilityBuilder builder;
    VisibleSet from_side, to_side;
    std::set<uint32_t> across;
    bool first = true;
    for (double offset : {-1e-2, -1e-3, -1e-4, -1e-5, -1e-7, 0.0, 1e-7, 1e-5, 1e-4, 1e-3, 1e-2}) {
      View view = cam.view;
      view.eye_world = glm::vec3(on_plane + n * offset);
      view.target_world = glm::vec3(glm::dvec3(view.eye_world) + dir);
      RC_LOG() << "offset " << offset << "\n";
      RC_ASSERT(builder.build(world, view, portal.from, {}, from_side).ok());
      RC_ASSERT(builder.build(world, view, portal.to, {}, to_side).ok());
      RC_ASSERT(cell_set(from_side) == cell_set(to_side));
      if (std::abs(offset) > 1e-4) continue;
      const std::set<uint32_t> here = cell_set(offset > 0.0 ? to_side : from_side);
      if (first) {
        across = here;
        first = false;
      }
      RC_ASSERT(here == across);
    }
  });

  std::printf(ok ? "all visibility properties hold\n" : "a visibility property FAILED\n");
  return ok ? 0 : 1;
}
