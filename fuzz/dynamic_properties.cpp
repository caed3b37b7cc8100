// Rapidcheck properties of the tracker's hysteresis and of door states (dynamic_properties.h).
// The door properties use the hand-built grids and rings of tests/visibility (cheap to build per
// case, cyclic, non-identity frames) and its ray-walk oracle, which treats closed doors as walls.
#include "dynamic_properties.h"

#include "camera_samples.h"
#include "ray_walk.h"
#include "test_worlds.h"

#include <lintel/cell_locate.h>
#include <lintel/doorway_rule.h>
#include <lintel/viewer_tracker.h>
#include <lintel/visibility_builder.h>

#include <rapidcheck.h>

#include <cmath>
#include <iomanip>

namespace lintel::fuzz {
namespace {

constexpr float kPi = 3.14159265358979f;

// A grid (2..4 x 2..4 rooms) or a ring (3..8 sectors), random frames and portal winding, random
// door states (each direction of each portal closed with probability 2/5), and an eye inside a
// random room, at least 1.5 m from its walls. start_cell is the room containing it.
struct DoorCase {
  testing::TestWorld t;
  uint32_t start_cell = 0;
  glm::vec3 eye_layout{0.0f};
};

DoorCase gen_door_case() {
  testing::WorldOptions options;
  options.frame_seed = *rc::gen::inRange<uint64_t>(1, 1000);
  options.reverse_portal_winding = *rc::gen::arbitrary<bool>();
  DoorCase c;
  if (*rc::gen::arbitrary<bool>()) {
    const uint32_t w = *rc::gen::inRange(2u, 5u), h = *rc::gen::inRange(2u, 5u);
    c.t = testing::make_grid(w, h, options);
    const uint32_t room = *rc::gen::inRange(0u, w * h);
    c.eye_layout = {4.0f * float(room % w) + 2.0f, 1.5f, 4.0f * float(room / w) + 2.0f};
  } else {
    const uint32_t n = *rc::gen::inRange(3u, 9u);
    c.t = testing::make_ring(n, options);
    const float angle = (float(*rc::gen::inRange(0u, n)) + 0.5f) * 2.0f * kPi / float(n);
    const float r = testing::ring_inner_radius(n) + 2.0f;
    c.eye_layout = {r * std::cos(angle), 1.5f, r * std::sin(angle)};
  }
  c.eye_layout += glm::vec3(*rc::gen::inRange(-50, 51), *rc::gen::inRange(-50, 51), *rc::gen::inRange(-50, 51)) * 0.01f;
  for (uint32_t p = 0; p < c.t.world.portals.size(); ++p)
    for (PortalDirection d : {PortalDirection::FromTo, PortalDirection::ToFrom})
      c.t.world.set_portal_open(p, d, *rc::gen::inRange(0, 5) >= 2);
  const CellLocation where = locate_cell(c.t.world, glm::dvec3(c.t.to_world(c.eye_layout)));
  RC_PRE(where.reason == LocateReason::Containment);
  c.start_cell = where.cell;
  return c;
}

View gen_view(const DoorCase& c) {
  const glm::vec3 look = pick_layout_look();
  return c.t.view(c.eye_layout, c.eye_layout + look * 0.05f, float(*rc::gen::inRange(30, 120)));
}

}  // namespace

bool check_tracker_hysteresis(const std::function<const PoolScene&()>& pick_scene) {
  bool ok = true;
  // Hysteresis: an eye that stays inside a two-way portal's polygon and within half its hysteresis
  // band of the plane (on either side, measured on the float eye the tracker gets), jittering by
  // micrometres along the plane, never changes cell after its placement; and a straight walk
  // through the portal's middle from 0.3 m before it to 0.3 m past it switches exactly once, by a
  // crossing of that portal.
  ok &= rc::check("the tracker holds still in a doorway and switches once through it", [&] {
    const World& world = pick_scene().world;
    const CameraSample cam = *gen_camera_at_portal(world, true);
    const Portal& portal = world.portals[cam.portal];
    const double band = hysteresis_band_m(portal);
    const glm::dvec3 n(portal.normal_world);
    const glm::dvec3 middle =
        point_in_portal(portal, *rc::gen::inRange(0, 1000) / 1000.0, *rc::gen::inRange(0, 1000) / 1000.0, 0.5);
    const glm::dvec3 along =
        glm::normalize(glm::cross(n, glm::dvec3(portal.polygon_world[1]) - glm::dvec3(portal.polygon_world[0])));
    ViewerTracker resting;
    RC_ASSERT(resting.reset(world, glm::vec3(middle)).ok());
    glm::vec3 previous(middle);
    for (int frame = 0; frame < 60; ++frame) {
      const double offset = band * *rc::gen::inRange(-500, 501) / 1000.0;
      const double slide = 3e-6 * *rc::gen::inRange(-1000, 1001) / 1000.0;
      const glm::vec3 eye(middle + n * offset + along * slide);
      const double s_eye = portal_signed_distance(portal, portal.from, glm::dvec3(eye));
      if (!(std::fabs(s_eye) <= band)) continue;  // float rounding took it past the band
      RC_ASSERT(resting.update(world, eye).ok());
      for (const CellTransition& tr : resting.transitions())
        RC_LOG() << std::setprecision(17) << "frame " << frame << " offset " << offset << " band " << band << ": "
                 << tr.from << " -> " << tr.to << " reason " << transition_reason_name(tr.reason) << " portal "
                 << int(tr.portal) << " (resting at " << cam.portal << ", from " << portal.from << " to " << portal.to
                 << ") s_from " << portal_signed_distance(portal, portal.from, glm::dvec3(previous)) << " -> "
                 << portal_signed_distance(portal, portal.from, glm::dvec3(eye)) << " band(tr.portal) "
                 << hysteresis_band_m(world.portals[tr.portal]) << "\n";
      previous = eye;
      RC_ASSERT(resting.transitions().empty());
    }
    ViewerTracker walker;
    RC_ASSERT(walker.reset(world, glm::vec3(middle - n * 0.3)).ok());
    RC_PRE(walker.cell() == portal.from);  // the room before the door contains the start
    int crossings = 0;
    for (int step = 1; step <= 60; ++step) {
      RC_ASSERT(walker.update(world, glm::vec3(middle + n * (-0.3 + 0.01 * step))).ok());
      for (const CellTransition& tr : walker.transitions()) {
        RC_ASSERT(tr.reason == TransitionReason::PortalCrossing);
        RC_ASSERT(tr.portal == cam.portal);
        ++crossings;
      }
    }
    RC_ASSERT(crossings == 1);
    RC_ASSERT(walker.cell() == portal.to);
  });
  return ok;
}

bool check_door_states() {
  bool ok = true;
  // Doors, termination: with any door states and any snap/cap/polygon settings, build() stops
  // within pop_bound() — closed portals only remove paths from the flood.
  ok &= rc::check("with doors, terminates within the documented pop bound", [] {
    const DoorCase c = gen_door_case();
    const View view = gen_view(c);
    VisibilityOptions options;
    options.snap_lattice_cells = 1u << *rc::gen::inRange(1, 22);
    options.reprocess_cap = *rc::gen::inRange(0, 33);
    options.max_region_polygons = *rc::gen::inRange(1, 17);
    VisibilityBuilder builder;
    VisibleSet visible;
    const Status built = builder.build(c.t.world, view, c.start_cell, options, visible);
    if (!built) RC_FAIL(built.message());
    RC_ASSERT(!visible.stats.bound_exceeded);
    RC_ASSERT(visible.stats.pops <= pop_bound(uint32_t(c.t.world.cells.size()), options));
  });

  // Doors, conservative: every cell a view ray reaches through open portals (closed ones are
  // walls; the ray-walk oracle, rays within a millimetre of a portal edge not judged) is visible
  // with the ray's pixel in its region. Extra visible cells or pixels (the regions over-estimate)
  // are accepted; a miss is not.
  ok &= rc::check("with doors, never loses what a ray sees through open portals", [] {
    const DoorCase c = gen_door_case();
    const View view = gen_view(c);
    VisibilityBuilder builder;
    VisibleSet visible;
    RC_ASSERT(builder.build(c.t.world, view, c.start_cell, {}, visible).ok());
    for (int j = 0; j < 12; ++j)
      for (int i = 0; i < 12; ++i) {
        const glm::dvec2 ndc((i + 0.5) / 6.0 - 1.0, (j + 0.5) / 6.0 - 1.0);
        const testing::RayWalk walk = testing::walk_view_ray(c.t.world, view, c.start_cell, ndc);
        if (walk.ambiguous) continue;
        for (uint32_t seen : walk.seen_cells) {
          const VisibleCell* vc = visible.find(seen);
          if (vc == nullptr) {
            RC_LOG() << "pixel " << ndc.x << "," << ndc.y << ": cell " << seen << " not visible; start " << c.start_cell
                     << ", ray cells";
            for (uint32_t w : walk.seen_cells) RC_LOG() << " " << w;
            RC_LOG() << "; closed (portal from->to dir):";
            for (uint32_t p = 0; p < c.t.world.portals.size(); ++p)
              RC_LOG() << " " << p << ":" << c.t.world.portals[p].from << "->" << c.t.world.portals[p].to
                       << (c.t.world.portals[p].open_from_to ? "" : " F")
                       << (c.t.world.portals[p].open_to_from ? "" : " T");
            RC_LOG() << "\n";
            RC_FAIL("a cell a ray sees through open portals is not visible");
          }
          RC_ASSERT(visible.region(*vc).contains(ndc, 1e-6));
        }
      }
  });

  // Doors, deterministic: the same world, door states, view and start cell give a bit-identical
  // VisibleSet from a fresh builder and from one that answered another door state in between.
  ok &= rc::check("with doors, deterministic bit for bit", [] {
    DoorCase c = gen_door_case();
    const View view = gen_view(c);
    VisibilityBuilder first, second;
    VisibleSet a, b;
    RC_ASSERT(first.build(c.t.world, view, c.start_cell, {}, a).ok());
    const uint32_t toggled = *rc::gen::inRange<uint32_t>(0, uint32_t(c.t.world.portals.size()));
    const bool was_open = c.t.world.portal_open(toggled, PortalDirection::FromTo);
    c.t.world.set_portal_open(toggled, PortalDirection::FromTo, !was_open);
    RC_ASSERT(second.build(c.t.world, view, c.start_cell, {}, b).ok());
    c.t.world.set_portal_open(toggled, PortalDirection::FromTo, was_open);
    RC_ASSERT(second.build(c.t.world, view, c.start_cell, {}, b).ok());
    RC_ASSERT(a == b);
  });
  return ok;
}

}  // namespace lintel::fuzz
