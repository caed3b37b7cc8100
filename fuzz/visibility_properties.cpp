// Property tests of the portal traversal on generated cyclic cell graphs with non-identity cell
// frames (rapidcheck). Each property is stated in words above its code. ctest runs a fixed seed
// and 1,000 cases per property; LINTEL_SOAK=1 runs 100,000; RC_PARAMS overrides both.
#include "camera_samples.h"
#include "dynamic_properties.h"
#include "link_properties.h"
#include "mover_properties.h"
#include "world_pool.h"

#include <lintel/reference/ray_ground_truth.h>
#include <lintel/scene_io.h>
#include <lintel/visibility_builder.h>

#include <rapidcheck.h>

#include <cstdio>
#include <iomanip>
#include <limits>
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

// Random scenes put cell frames up to 1e4 m from their rooms, which leaves about 1 mm of float
// error in the loaded geometry (geometry_error_bound): coplanar surfaces of two cells (a one-way
// window's closing panel and its portal, two half reveals at a wall's mid-plane) may swap sides
// by that much. An eye inside that error band of a wall sees the error, not the building; such
// cases are discarded.
// Discards eyes inside the error band, then shrinks the near plane until its corners stay clear of
// every wall (a near plane through a wall sees through it, which no portal method models).
void keep_near_plane_off_walls(const World& world, View& view) {
  const double clearance = distance_to_nearest_shell(world, glm::dvec3(view.eye_world));
  RC_PRE(clearance > std::max(1e-5, 4.0 * geometry_error_bound(world)));
  const double corner = near_corner_distance(view);
  if (corner > 0.9 * clearance) view.near_m = float(view.near_m * (0.9 * clearance / corner));
}

std::set<uint32_t> cell_set(const VisibleSet& v) {
  std::set<uint32_t> cells;
  for (const VisibleCell& c : v.cells) cells.insert(c.cell);
  return cells;
}

// Whether a visible cell is seen only through a sliver: every polygon of its region is at most 4
// lattice cells thick (its narrowest width across an edge), or the region covers at most 256
// lattice cells^2 (0.02 % of the screen). A portal seen edge-on (the eye in its plane, as with two
// coplanar doors of one wall) or ending a hair from its parent region's edge opens or closes with
// the eye moving a hair or with the geometry's float rounding (about 1 mm far from the origin);
// conservative snapping widens such a zero-area opening to a band a few lattice cells thick.
bool seen_through_sliver(const VisibleSet& v, const VisibleCell& c, const VisibilityOptions& options) {
  const double cell = 2.0 / double(options.snap_lattice_cells);
  const ClipRegionView region = v.region(c);
  double area = 0.0, thickest = 0.0;
  for (size_t p = 0; p < region.polygons.size(); ++p) {
    const auto poly = region.polygon(p);
    double narrowest = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < poly.size(); ++i) {
      const glm::dvec2 a(poly[i]), b(poly[(i + 1) % poly.size()]);
      area += 0.5 * (a.x * b.y - b.x * a.y);
      const glm::dvec2 edge = b - a;
      const double length = glm::length(edge);
      if (length == 0.0) continue;
      double across = 0.0;
      for (const glm::vec2& q : poly)
        across = std::max(across, std::abs(edge.x * (double(q.y) - a.y) - edge.y * (double(q.x) - a.x)) / length);
      narrowest = std::min(narrowest, across);
    }
    thickest = std::max(thickest, narrowest);
  }
  return thickest <= 4.0 * cell || std::abs(area) <= 256.0 * cell * cell;
}

// Whether two visible sets hold the same cells, except cells that one of them lacks and the other
// sees only through a sliver (seen_through_sliver).
bool same_cells_up_to_slivers(const VisibleSet& a, const VisibleSet& b, const VisibilityOptions& options) {
  auto extra_are_slivers = [&](const VisibleSet& has, const VisibleSet& other) {
    for (const VisibleCell& c : has.cells)
      if (!other.cell_visible(c.cell) && !seen_through_sliver(has, c, options)) return false;
    return true;
  };
  return extra_are_slivers(a, b) && extra_are_slivers(b, a);
}

void log_camera(const CameraSample& s) {
  RC_LOG() << std::setprecision(9) << "up " << s.view.up_world.x << "," << s.view.up_world.y << "," << s.view.up_world.z
           << " eye " << s.view.eye_world.x << "," << s.view.eye_world.y << "," << s.view.eye_world.z << " target "
           << s.view.target_world.x << "," << s.view.target_world.y << "," << s.view.target_world.z << " fov "
           << s.view.fov_y_deg << " aspect " << s.view.aspect << " near " << s.view.near_m << " start " << s.start_cell
           << " portal " << s.portal << " offset " << s.offset_m << "\n";
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
      view.eye_world =
          box.min + e * glm::vec3(*rc::gen::inRange(0, 1001) / 1000.0f, *rc::gen::inRange(0, 1001) / 1000.0f,
                                  *rc::gen::inRange(0, 1001) / 1000.0f);
      view.target_world =
          view.eye_world +
          glm::vec3(*rc::gen::inRange(-100, 101), *rc::gen::inRange(-100, 101), *rc::gen::inRange(-100, 101)) * 0.01f +
          glm::vec3(0.001f, 0, 0);
    }
    VisibilityOptions options;
    options.snap_lattice_cells = 1u << *rc::gen::inRange(1, 22);  // 2 .. kMaxSnapLatticeCells
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
  // and the hit cell's region contains that pixel's NDC point within one snap cell — up to the
  // scene's own float precision: rays running inside a portal's plane (they travel along the
  // seam of two cells' reveal quads, a float crack far from the origin) and hits within the
  // scene's float error of a portal, where two cells' surfaces meet and either may be in front,
  // are not judged (camera_samples.h).
  ok &= rc::check("never loses a visible cell, instance or pixel", [] {
    const PoolScene& scene = pick_scene();
    CameraSample cam = *gen_camera_at_portal(scene.world, false);
    keep_near_plane_off_walls(scene.world, cam.view);
    log_camera(cam);
    VisibilityBuilder builder;
    VisibleSet visible;
    VisibilityOptions options;
    RC_ASSERT(builder.build(scene.world, cam.view, cam.start_cell, options, visible).ok());
    RayCamera rc_cam{cam.view.eye_world, cam.view.target_world, cam.view.up_world,
                     cam.view.fov_y_deg, cam.view.aspect,       cam.view.near_m};
    GroundTruth truth;
    scene.rays.cast(rc_cam, 32, truth);
    const double tolerance = 2.0 / double(options.snap_lattice_cells);
    const double seam = 2.0 * geometry_error_bound(scene.world);
    for (uint32_t j = 0; j < truth.resolution; ++j)
      for (uint32_t i = 0; i < truth.resolution; ++i) {
        const RayHitId hit = truth.pixels[size_t(j) * truth.resolution + i];
        if (hit.cell == RayHitId::kNone) continue;
        const glm::vec2 ndc = pixel_center_ndc(i, j, truth.resolution);
        const glm::dvec3 dir = pixel_ray_direction(cam.view, ndc);
        if (ray_runs_in_portal_plane(scene.world, glm::dvec3(cam.view.eye_world), dir)) continue;
        if (on_portal_seam(scene.world, hit.cell, glm::dvec3(cam.view.eye_world) + dir * double(hit.depth), seam))
          continue;
        const VisibleCell* vc = visible.find(hit.cell);
        if (vc == nullptr) {
          RC_LOG() << "pixel " << i << "," << j << " ndc " << ndc.x << "," << ndc.y << " hits cell " << hit.cell
                   << " instance " << int(hit.instance) << ", which is not visible\n";
          RC_FAIL("a pixel sees a cell the traversal did not reach");
        }
        if (!visible.region(*vc).contains(glm::dvec2(ndc), tolerance)) {
          RC_LOG() << "pixel " << i << "," << j << " ndc " << ndc.x << "," << ndc.y << " hits cell " << hit.cell
                   << " instance " << int(hit.instance) << "; its region (reached from " << vc->reached_from
                   << ", collapsed " << vc->collapsed_to_rect << "): rect " << vc->rect_ndc.min.x << ","
                   << vc->rect_ndc.min.y << " .. " << vc->rect_ndc.max.x << "," << vc->rect_ndc.max.y << "\n";
          RC_FAIL("a pixel seeing a cell lies outside that cell's region");
        }
        if (hit.instance != RayHitId::kNone &&
            !std::binary_search(visible.instances.begin(), visible.instances.end(), hit.instance)) {
          RC_LOG() << "pixel " << i << "," << j << " sees instance " << hit.instance << " of cell " << hit.cell
                   << ", which was culled\n";
          RC_FAIL("a pixel sees an instance the culling dropped");
        }
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
  // translations up to 1 km) leaves the set of visible cells unchanged — up to cells seen through
  // a sliver (same_cells_up_to_slivers), which the motion's float rounding may open or close.
  ok &= rc::check("invariant under a rigid motion of world and camera", [] {
    const PoolScene& scene = pick_scene();
    const CameraSample cam = *gen_camera_at_portal(scene.world, false);
    log_camera(cam);
    const glm::dvec3 axis = glm::normalize(
        glm::dvec3(*rc::gen::inRange(-100, 101), *rc::gen::inRange(-100, 101), *rc::gen::inRange(-100, 101)) +
        glm::dvec3(0.0, 0.0, 1e-3));
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
    if (!same_cells_up_to_slivers(before, after, {})) {
      for (const VisibleSet* v : {&before, &after}) {
        RC_LOG() << (v == &before ? "before:" : "after: ");
        for (const VisibleCell& c : v->cells)
          RC_LOG() << " " << c.cell << "[" << c.rect_ndc.min.x << "," << c.rect_ndc.min.y << ".." << c.rect_ndc.max.x
                   << "," << c.rect_ndc.max.y << " via " << c.reached_from << "]";
        RC_LOG() << " doorway passes " << v->stats.doorway_passes << "\n";
      }
      RC_FAIL("the visible cells changed under a rigid motion");
    }
  });

  // Doorway continuity: for an eye inside a two-way portal's polygon and at most 1 cm (a fifth of
  // the near distance) off its plane, the visible cells do not depend on which side's cell the
  // traversal starts from (the tracker may still say `from` a hair past the plane); and as the eye
  // moves across the plane within 0.1 mm (from -1e-4 m in `from` to +1e-4 m in `to`), the set stays
  // the same, cells seen through a sliver aside (same_cells_up_to_slivers; across a centimetre a
  // whole portal can slide onto the screen edge).
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
    VisibleSet from_side, to_side, reference;
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
      const VisibleSet& here = offset > 0.0 ? to_side : from_side;
      if (first) {
        reference = here;
        first = false;
      }
      RC_ASSERT(same_cells_up_to_slivers(here, reference, {}));
    }
  });

  ok &= check_tracker_hysteresis(pick_scene);
  ok &= check_door_states();
  ok &= check_moving_instances();
  ok &= check_linked_portals();

  std::printf(ok ? "all visibility properties hold\n" : "a visibility property FAILED\n");
  return ok ? 0 : 1;
}
