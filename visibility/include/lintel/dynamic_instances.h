// Moving instances at run time (issue 11 item 3): a new transform per instance, with its cell
// membership kept right (its box centre followed by portal crossings, like the viewer) and its
// reach re-derived (a box straddling a doorway is listed from every cell it reaches). Incremental:
// a move touches one instance; take_moved() hands the caches the list of what changed.
//
//   lintel::DynamicInstances movers;               // one per World, next to it
//   movers.reset(world);                           // once per World (allocates)
//   movers.move(world, crate, new_mesh_to_world);  // any number per frame
//   std::span<const uint32_t> moved = movers.take_moved();  // once per frame, after the moves
//   builder.instances_moved(world, movers);        // CPU cull: re-bounds just those
//   gpu_upload(moved, movers.reach());             // GPU cull: small copies of just those
//
// Why a class next to World and not functions on World: World is the scene model every layer
// reads; the per-world adjacency, bands, reach lists and the dirty list are caches of it, like the
// tracker's and the builder's, and a game that never moves anything should not carry them. A move
// writes the World's own fields (Instance::mesh_to_world, bounds_world, cell, Cell::instances) so
// that anything reading World — or re-deriving from it — sees the truth, and bumps
// World::instance_moves so that a cache that was not handed the dirty list notices and re-derives
// everything (correct, only slower).
#pragma once

#include <lintel/cell_locate.h>
#include <lintel/instance_reach.h>
#include <lintel/portal_crossing.h>
#include <lintel/status.h>
#include <lintel/viewer_tracker.h>
#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace lintel {

class DynamicInstances {
 public:
  DynamicInstances() = default;
  // Membership thresholds: jump_distance_m, lost_tolerance_m, found_elsewhere_m and
  // max_crossings_per_move mean for an instance's box centre what they mean for the eye.
  explicit DynamicInstances(const TrackerOptions& options) : options_(options) {}

  // Binds to `world`: adjacency, bands, volumes and the reach of every instance (allocates).
  // Instances keep their Instance::cell (the cell node they sit below). The dirty list is empty.
  // Errors: bad options.
  Status reset(const World& world);

  // Gives instance `instance` the transform `mesh_to_world` (the mesh's space to world, as
  // Instance::mesh_to_world):
  //  * bounds_world = the mesh's real extent through it (transform_aabb, as finalize_world);
  //  * its cell follows its box centre (bounds_world.center()) from the old centre to the new:
  //    portal crossings by the tracker's rule (hysteresis band included, closed doors included:
  //    the opening is physical); a move of the centre longer than jump_distance_m re-locates by
  //    containment (locate_cell); after the crossings a centre outside the cell's volume by more
  //    than lost_tolerance_m, or by more than found_elsewhere_m while another volume contains it,
  //    re-locates too (so a centre that went through a wall lands in the room it is in);
  //  * Cell::instances of the old and new cell stay ascending;
  //  * its reach is recomputed (InstanceReach::update);
  //  * it joins the dirty list (once) and World::instance_moves grows by one.
  // Moving to the same transform is a move too (it costs the same; the caches re-copy it).
  // Rebinds first (as reset) when `world` is another object or its revision changed.
  // Errors (bad input; nothing changes): instance out of range, a non-finite or non-affine matrix
  // (last row not 0 0 0 1). Allocates only amortized: a reach list outgrowing its slot, or a
  // cell's Cell::instances growing when an instance enters it. Cost: docs/perf.md.
  Status move(World& world, uint32_t instance, const glm::mat4& mesh_to_world);

  // The instances moved since the previous call, ascending, each once, and empties the dirty
  // list. The span stays valid until the next take_moved() or reset() (taken() returns it again).
  std::span<const uint32_t> take_moved();
  std::span<const uint32_t> taken() const { return taken_; }
  // World::instance_moves when the previous take_moved() (or reset) ran, and when the last one
  // ran: taken() lists every instance moved between the two. A cache current through some count
  // in [taken_from(), taken_through()] is current through taken_through() after applying taken();
  // one older than taken_from() missed a take and must re-derive everything.
  uint64_t taken_from() const { return taken_from_; }
  uint64_t taken_through() const { return taken_through_; }

  // Reach lists of every instance, current after each move (for the cull caches).
  const InstanceReach& reach() const { return reach_; }
  // Portals the last move()'s centre crossed, in order, and whether it re-located by containment.
  std::span<const uint32_t> last_crossings() const { return crossed_; }
  bool last_relocated() const { return relocated_; }
  const World* bound_world() const { return world_; }
  uint64_t bound_revision() const { return revision_; }

 private:
  void bind(const World& world);
  uint32_t follow(const World& world, uint32_t instance, uint32_t cell, const glm::dvec3& c0, const glm::dvec3& c1);

  TrackerOptions options_;
  const World* world_ = nullptr;
  uint64_t revision_ = 0;
  CrossingGraph graph_;
  InstanceReach reach_;
  CellGrid grid_;  // containment candidates for re-locating
  // Per instance: how far its centre may still move while surely inside its cell's volume (the
  // clearance measured at the last full check, minus the path since): moves within it skip the
  // lost / found-elsewhere test, whose winding number dominates a move's cost otherwise.
  std::vector<double> inside_budget_m_;
  // Per instance: how far its centre may still move before it could cross a portal of its cell
  // (the distance to the nearest portal's bounds, less the crossing band and the polygon's
  // non-planarity, measured at the last full check, minus the path since). Moves within both
  // budgets skip the crossing test, and, while the box stays that far from every portal, the
  // reach flood (its list is its own cell alone).
  std::vector<double> portal_budget_m_;
  double portal_clearance_m(uint32_t cell, const glm::dvec3& p) const;
  std::vector<uint8_t> dirty_flag_;
  std::vector<uint32_t> dirty_, taken_, crossed_;
  uint64_t taken_from_ = 0, taken_through_ = 0;
  bool relocated_ = false;
};

}  // namespace lintel
