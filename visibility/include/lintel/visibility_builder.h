// The visibility query: from a viewer cell and a View, which cells can be seen (each with its clip
// region in NDC) and which instances in them survive culling. Algorithm, rules and bounds:
// docs/visibility.md. Single-threaded and deterministic: the same world, view, start cell and
// options give a bit-identical VisibleSet.
//
//   lintel::VisibilityBuilder builder;            // owns all scratch; one per thread
//   lintel::VisibleSet visible;                   // caller-owned, reused every frame
//   builder.prepare(world);                       // once per World (allocates)
//   lintel::Status s = builder.build(world, view, tracker.cell(), {}, visible);
//   if (!s) report(s.message());
//   for (const lintel::VisibleCell& c : visible.cells) draw_cell(c.cell, visible.region(c));
#pragma once

#include <lintel/ndc_snap.h>
#include <lintel/status.h>
#include <lintel/view.h>
#include <lintel/visible_set.h>
#include <lintel/world.h>

#include <algorithm>
#include <cstdint>
#include <memory>

namespace lintel {

class DynamicInstances;  // dynamic_instances.h

struct VisibilityOptions {
  // N: lattice cells per NDC axis for snapping (power of two, 2..2^21, i.e. a snap of 1 down to
  // 9.5e-7 NDC; ndc_snap.h says why that range). 1024 is about one pixel at 1024 px across; the
  // pop bound grows with N (see pop_bound()).
  uint32_t snap_lattice_cells = kDefaultSnapLatticeCells;
  // K: how many times a cell may be queued again after its first processing while its region is
  // still polygons. Reaching it collapses the region to its lattice rect (a superset).
  uint32_t reprocess_cap = 16;
  // P: convex polygons a region may hold (1..kMaxRegionPolygonsLimit); one more collapses it to
  // its lattice rect (a superset).
  uint32_t max_region_polygons = 8;
  // Cull the instances of visible cells (instance_cull.h). Off: VisibleSet::instances stays empty.
  bool cull_instances = true;
  // Cull the instances of linked cells (cull_linked_instances: each with its view transform).
  // Separate from cull_instances because a renderer whose GPU culls the plain entries still wants
  // these few on the CPU. Off: VisibleSet::linked_instances stays empty.
  bool cull_linked_instances = true;
};

// Bad options are reported, not asserted (they come from command lines).
Status validate_options(const VisibilityOptions& options);

// Worst-case number of pops for a world of `cell_count` cells: cell_count * (K + 2N).
// Per cell: 1 first processing + K re-processings while its region is polygons + 1 after it
// becomes a rect + at most 2(N - 1) more, because a lattice rect at least one cell wide can only
// grow 2(N - 1) times. Derivation: docs/visibility.md.
uint64_t pop_bound(uint32_t cell_count, const VisibilityOptions& options);

// Linked portals (teleports, mirrors; docs/visibility.md, "Linked portals"). The traversal's
// nodes are (cell, view) pairs; view 0 is the identity. At most kMaxViewTransforms views (the
// identity included; a view is a chain of at most kMaxLinkDepth links, portal_link.h) and
// linked_node_budget(cells) nodes with a view other than the identity; what would need more is
// reported as VisibleSet::unresolved, never dropped silently.
inline constexpr uint32_t kMaxViewTransforms = 64;
inline constexpr uint32_t kMaxLinkedNodes = 1024;
inline uint32_t linked_node_budget(uint32_t cell_count) {
  return uint32_t(std::min<uint64_t>(kMaxLinkedNodes, uint64_t(kMaxViewTransforms - 1) * cell_count));
}
// The pop bound of a build on `world`: pop_bound(nodes), nodes = cells, plus
// linked_node_budget(cells) when some portal is linked. Equal to pop_bound(cells) without links.
uint64_t pop_bound(const World& world, const VisibilityOptions& options);

class VisibilityBuilder {
 public:
  VisibilityBuilder();
  ~VisibilityBuilder();
  VisibilityBuilder(VisibilityBuilder&&) noexcept;
  VisibilityBuilder& operator=(VisibilityBuilder&&) noexcept;
  VisibilityBuilder(const VisibilityBuilder&) = delete;
  VisibilityBuilder& operator=(const VisibilityBuilder&) = delete;

  // Sizes all scratch for `world` (allocates: per-cell region slots of
  // cells x P x kMaxRegionPolygonVertices x 8 bytes, the queue, the culling SoA, a projection
  // slot per portal for its vertices plus two). build() calls it
  // by itself when the world's address, World::revision or its cell/portal/instance counts change
  // or P grows: after editing a world in place, call finalize_world() (or prepare() again).
  // Door state (Portal::open_*) is read live by build(): toggling a door needs neither.
  void prepare(const World& world, const VisibilityOptions& options = {});
  // The same, and sizes `out` for the worst case on `world` (every cell visible with the most
  // polygons, every instance), so that even the first build() into it allocates nothing: a game
  // calls this at level load, and its first frame has no allocation hitch. (Linked instances of
  // worlds with teleports or mirrors may still grow `out.linked_instances` once.)
  void prepare(const World& world, const VisibilityOptions& options, VisibleSet& out);

  // Fast path after instances moved (dynamic_instances.h): re-bounds, in the CPU cull's data,
  // only the instances of movers.taken() (the last take_moved()), from the World and
  // movers.reach(). Without this call a build() that finds World::instance_moves changed
  // re-derives the whole cull data from the World (same result, O(instances)). Does nothing when
  // the builder is not prepared for `world` (its next build() prepares from scratch anyway).
  void instances_moved(const World& world, const DynamicInstances& movers);

  // Fills `out` (cleared first) with what is visible from `view` when the eye is in `start_cell`.
  // Errors: invalid view (NaN/Inf, eye == target...), invalid options or start_cell out of range
  // (out is left empty); the hard stop of the test-only unbounded mode (out holds what was
  // reached, with stats.bound_exceeded set; visibility/src/visibility_builder_testing.h).
  // Does not allocate once prepare() has run and `out` has held a frame at least as large, or
  // has been sized by prepare(world, options, out).
  Status build(const World& world, const View& view, uint32_t start_cell, const VisibilityOptions& options,
               VisibleSet& out);

 private:
  friend struct VisibilityBuilderTesting;  // test-only switches: visibility/src/visibility_builder_testing.h
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lintel
