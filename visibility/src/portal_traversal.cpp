// The portal flood: from the viewer cell, nearest cell first, each portal clipped to the region of the
// cell it is seen from, regions growing by snapped polygons until nothing changes.
// Learns from: Teller & Séquin 1991 "Visibility preprocessing for interactive walkthroughs" (cells
// and portals); Luebke & Georges 1995 "Portals and Mirrors" (screen-space cull regions shrinking
// through each portal); Descent / Tomb Raider 2 (integer screen rects that only grow: termination
// by construction); Godot rooms & portals (a depth cap that drops cells on rings: here the cap
// collapses to a superset instead); Doom 3 / The Dark Mod (portals around the eye: doorway_rule.cpp).
// Linked portals (teleports, mirrors) continue the flood in a transformed view: the nodes are
// (cell, view) pairs (link_views.h), view 0 the identity, so worlds without links run as before.
#include <lintel/visibility_builder.h>

#include <lintel/doorway_rule.h>
#include <lintel/dynamic_instances.h>
#include <lintel/instance_cull.h>
#include <lintel/portal_clip.h>
#include <lintel/view_lens.h>

#include "link_views.h"
#include "flood_scratch.h"
#include "ndc_snap_testing.h"
#include "node_queue.h"
#include "packed_portals.h"
#include "portal_projections.h"
#include "pending_merge.h"
#include "portal_clip_testing.h"
#include "prefetch.h"
#include "region_lattice.h"
#include "visibility_builder_testing.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <string>

namespace lintel {
namespace {

// Unresolved link pieces kept per build (one entry per (cell, view, portal)); beyond it the last
// entry's rect grows to cover the rest, so no unresolved pixel goes unreported.
constexpr size_t kMaxUnresolvedEntries = 256;

// A target node not looked up yet (linked portals make their view on the first piece that passes).
constexpr uint32_t kTargetPending = detail::kNoNode - 1;

// state[node]: the node's detail::NodeState, which lives on the line of its region.
struct NodeStates {
  detail::RegionLattice* regions;
  detail::NodeState& operator[](uint32_t node) const { return regions->node_state(node); }
};

}  // namespace

struct VisibilityBuilder::Impl {
  // What prepare() sized things for.
  const World* world = nullptr;
  uint64_t revision = 0;
  size_t cells = 0, portals = 0, instances = 0;
  uint64_t instance_moves = 0;  // World::instance_moves that `cull` is current with

  detail::RegionLattice regions;  // per node: (cell, view 0) is the cell's index (link_views.h)
  detail::LinkViews links;
  CullData cull;
  NodeStates state{&regions};        // per node touched in this build
  bool test_only_unbounded = false;  // VisibilityBuilderTesting::disable_snap_and_cap
  bool reference_paths = false;      // VisibilityBuilderTesting::use_reference_paths
  bool merge_windows = true;         // VisibilityBuilderTesting::merge_pending_windows
  detail::NodeQueue queue;           // nearest cell first; a cell is queued at most once at a time
  detail::PackedPortals packed;      // the World's portals and links as a build reads them
  ViewLens lens;                     // the last build's lens terms
  std::vector<uint32_t> order;       // output order scratch
  std::vector<uint32_t> linked_order;
  std::vector<UnresolvedLink> unresolved;

  // Pending polygons of the cell being processed, copied out of the lattice (its own region may
  // change while its portals are processed, e.g. through a portal back into itself).
  std::vector<glm::vec2> pending_vertices;
  std::array<uint32_t, kMaxRegionPolygonsLimit> pending_counts{};
  std::array<NdcRect, kMaxRegionPolygonsLimit> pending_rects{};
  uint32_t pending_polygons = 0;

  detail::FloodScratch scratch;  // one portal's step: projection, slab, clip, snap

  detail::PortalProjections projections;  // this build's identity view's (portal_projections.h)
  uint32_t build_stamp = 0;

  // The scratch and output lines every build writes first, asked for together at its start
  // (prefetch.h): a game's build finds them out of every cache.
  void prefetch_scratch(const VisibleSet& out) const {
    using detail::kCacheLine;
    using detail::prefetch_write;
    regions.prefetch_heads();
    queue.prefetch_head();
    projections.prefetch();
    scratch.prefetch();
    prefetch_write(pending_vertices.data(), 2 * kCacheLine);
    prefetch_write(pending_counts.data(), kCacheLine);
    prefetch_write(pending_rects.data(), 2 * kCacheLine);
    prefetch_write(order.data(), kCacheLine);
    prefetch_write(&out, sizeof(VisibleSet));
    prefetch_write(out.cells.data(), 4 * kCacheLine);
    prefetch_write(out.polygons.data(), 2 * kCacheLine);
    prefetch_write(out.vertices_ndc.data(), 4 * kCacheLine);
    prefetch_write(out.instances.data(), 2 * kCacheLine);
    prefetch_write(out.transforms.data(), kCacheLine);
  }

  // What processing `cell` reads of each link: the portal's packed line and vertices and the
  // neighbour's region line, asked for together before the first link is looked at.
  void prefetch_links(std::span<const PortalLink> cell_links) const {
    for (const PortalLink& link : cell_links) {
      packed.prefetch(link.portal);
      regions.prefetch_cell(link.neighbour);
    }
  }

  // Per-build settings.
  const World* w = nullptr;
  VisibilityStats* stats = nullptr;
  uint32_t lattice_cells = 0;
  uint32_t reprocess_cap = 0;

  bool prepared_for(const World& world_in, const VisibilityOptions& options) const {
    return world == &world_in && revision == world_in.revision && cells == world_in.cells.size() &&
           portals == world_in.portals.size() && instances == world_in.instances.size() &&
           regions.max_polygons() == options.max_region_polygons;
  }

  // The queue's key for a node reached through `portal` from `from`: the squared distance from
  // the eye that looked through it (the frame's, or a linked view's) to the portal's box.
  float queue_key(uint32_t from, uint32_t portal) const {
    const Aabb& b = packed[portal].box;
    const glm::vec3 e(links.view(links.view_of(from)).eye);
    const glm::vec3 d = glm::max(glm::max(b.min - e, e - b.max), glm::vec3(0.0f));
    return glm::dot(d, d);
  }

  void enqueue(uint32_t cell, float key) {
    queue.push(key, cell);
    state[cell].queued = true;
  }

  uint32_t pop() {
    const uint32_t cell = queue.pop();
    state[cell].queued = false;
    return cell;
  }

  // The enqueue policy; the termination argument in docs/visibility.md counts exactly these paths.
  void on_region_changed(uint32_t cell, uint32_t from, uint32_t portal) {
    detail::NodeState& st = state[cell];
    if (!st.ever_queued) {
      st.ever_queued = true;
      st.reached_from = from;
      enqueue(cell, queue_key(from, portal));
      return;
    }
    if (st.queued) return;  // the pending polygons will be handled when it is popped
    ++stats->reenqueues;
    if (!regions.is_rect(cell)) {
      if (st.reprocess < reprocess_cap) {
        ++st.reprocess;
      } else {
        // Cap reached: keep everything (the region already holds the new polygon) as one lattice
        // rect; from now on it can only grow finitely often.
        regions.collapse_to_rect(cell);
        ++stats->cap_hits;
      }
    }
    enqueue(cell, queue_key(from, portal));
  }

  void add_to(uint32_t neighbour, std::span<const glm::vec2> poly, const NdcRect& rect, uint32_t from,
              uint32_t portal) {
    const detail::RegionAdd result = regions.add(neighbour, poly, rect);
    if (result == detail::RegionAdd::Skipped) {
      ++stats->snapped_duplicates_skipped;
      return;
    }
    ++stats->polygons_added;
    if (result == detail::RegionAdd::Collapsed) ++stats->polygon_overflows;
    on_region_changed(neighbour, from, portal);
  }

  std::span<const glm::vec2> pending_polygon(uint32_t i) const {
    return {pending_vertices.data() + size_t(i) * kMaxRegionPolygonVertices, pending_counts[i]};
  }

  void take_pending(uint32_t cell) {
    pending_polygons = 0;
    for (uint32_t i = 0; i < regions.polygon_count(cell); ++i) {
      if (!regions.pending(cell, i)) continue;
      const auto poly = regions.polygon(cell, i);
      std::copy(poly.begin(), poly.end(),
                pending_vertices.begin() + std::ptrdiff_t(pending_polygons) * kMaxRegionPolygonVertices);
      pending_rects[pending_polygons] = regions.polygon_rect(cell, i);
      pending_counts[pending_polygons++] = static_cast<uint32_t>(poly.size());
      regions.clear_pending(cell, i);
    }
    // Fewer windows, fewer pieces: each hull holds the polygons it replaces (pending_merge.h).
    // At a cell's first pop only: later pops take late arrivals, often pieces come round a cycle
    // of portals, and a hull's extra area sent round the cycle again would come back as a new
    // polygon, lap after lap, until the cap (docs/visibility.md).
    if (merge_windows && pending_polygons > 1 && state[cell].pops == 1) {
      const uint32_t windows =
          detail::merge_pending_windows(pending_vertices, pending_counts, pending_rects, pending_polygons);
      stats->windows_merged += pending_polygons - windows;
      pending_polygons = windows;
    }
  }

  // Region pieces that cannot be followed (link depth or budget): reported, never dropped silently.
  void add_unresolved(uint32_t node, uint32_t portal, std::span<const glm::vec2> poly) {
    ++stats->link_limit_hits;
    NdcRect rect;
    for (const glm::vec2& p : poly) rect.extend(p);
    const uint32_t cell = links.cell_of(node), view = links.view_of(node);
    for (UnresolvedLink& u : unresolved)
      if (u.cell == cell && u.transform == view && u.portal == portal) {
        u.rect_ndc.extend(rect);
        return;
      }
    if (unresolved.size() < kMaxUnresolvedEntries) {
      unresolved.push_back({cell, view, portal, rect});
    } else {
      unresolved.back().rect_ndc.extend(rect);
    }
  }

  // The node behind `portal` seen from `node`: (neighbour, same view) for a plain portal, (to,
  // view through the link) for a linked one; kNoNode when a budget is spent.
  uint32_t target_of(uint32_t node, uint32_t portal_index, uint32_t neighbour) {
    const uint32_t view = links.view_of(node);
    const Portal& portal = w->portals[portal_index];
    if (!portal.linked()) return view == 0 ? neighbour : links.node(view, neighbour);
    const uint32_t through = links.view_through(view, portal, portal_index);
    return through == detail::kNoNode ? detail::kNoNode : links.node(through, portal.to);
  }

  // `rect` is bounds_of(poly).
  void pass_on(uint32_t node, uint32_t portal, uint32_t neighbour, uint32_t& target, std::span<const glm::vec2> poly,
               const NdcRect& rect) {
    if (target == kTargetPending) {
      target = target_of(node, portal, neighbour);
      if (target != detail::kNoNode && packed[portal].linked) ++stats->linked_portals_followed;
    }
    if (target == detail::kNoNode) {
      add_unresolved(node, portal, poly);
      return;
    }
    add_to(target, poly, rect, node, portal);
  }

  // One portal seen from `node` (cell `cell`): a plain link of the cell or one of its linked
  // portals. The view's matrix and eye are the frame's own for view 0 (bit for bit as before).
  void process_link(uint32_t node, uint32_t cell, const PortalLink& link, const View& view, double near_extent,
                    double clip_depth) {
    const detail::PackedPortal& portal = packed[link.portal];
    if (portal.from != cell && portal.to != cell) return;  // a link that does not touch its cell
    if (portal.from != cell && !portal.two_way) return;    // one-way: seen from `from` only
    // A closed door blocks sight in its direction (O(1) to toggle: read here, nothing cached).
    if (!w->portal_open(link.portal, portal.from == cell ? PortalDirection::FromTo : PortalDirection::ToFrom)) {
      ++stats->closed_portals_skipped;
      return;
    }
    ++stats->portals_tested;
    const detail::LinkView& lv = links.view(links.view_of(node));
    const glm::dvec3& eye = lv.eye;
    const double s = portal_signed_distance(portal.normal, portal.plane_d, cell == portal.from, eye);
    uint32_t target = kTargetPending;

    if (std::abs(s) <= double(view.near_m) && projects_inside_portal(w->portals[link.portal], eye, near_extent)) {
      // Doorway rule: the projected portal degenerates here; pass the region through unchanged.
      ++stats->doorway_passes;
      for (uint32_t i = 0; i < pending_polygons; ++i)
        pass_on(node, link.portal, link.neighbour, target, pending_polygon(i), pending_rects[i]);
      return;
    }
    if (!(s < 0.0)) return;  // seen from behind: it does not face the eye

    const glm::dvec2* ndc_data = scratch.portal_ndc.data();
    detail::Projection uncached;
    const detail::Projection* projection = &uncached;
    if (links.view_of(node) == 0 && !reference_paths) {
      projection = &projections.get(packed, link.portal, build_stamp, lv.view_proj, clip_depth, scratch);
      ndc_data = projections.vertices(*projection);
    } else {
      detail::project_portal(packed.polygon(link.portal), lv.view_proj, clip_depth, scratch, scratch.portal_ndc.data(),
                             uncached);
    }
    if (projection->near_clipped) ++stats->near_plane_clips;
    if (projection->count < 3) return;
    const std::span<const glm::dvec2> ndc(ndc_data, projection->count);
    const glm::dvec2 lo = projection->lo, hi = projection->hi;

    for (uint32_t i = 0; i < pending_polygons; ++i) {
      // Apart from the polygon's bounds by any gap: the clip is empty, no need to compute it.
      const NdcRect& r = pending_rects[i];
      if (hi.x < double(r.min.x) || lo.x > double(r.max.x) || hi.y < double(r.min.y) || lo.y > double(r.max.y))
        continue;
      const uint32_t m =
          reference_paths
              ? detail::clip_convex_by_convex_plain(ndc, pending_polygon(i), scratch.clipped, scratch.clip_scratch)
              : clip_convex_by_convex(ndc, pending_polygon(i), scratch.clipped, scratch.clip_scratch);
      if (m < 3) continue;
      const std::span<const glm::dvec2> piece(scratch.clipped.data(), m);
      if (twice_signed_area(piece) <= 2.0 * detail::kMinVisibleArea) continue;
      if (target == kTargetPending) {
        target = target_of(node, link.portal, link.neighbour);
        if (target != detail::kNoNode && portal.linked) ++stats->linked_portals_followed;
      }
      // Already inside the target's region: its snap could only add area the piece does not show
      // (and work). Skipping it keeps the region a superset of everything passed to it.
      if (target != detail::kNoNode && lattice_cells != 0 && regions.covers(target, piece)) {
        ++stats->snapped_duplicates_skipped;
        continue;
      }
      NdcRect rect;
      const uint32_t k = reference_paths && lattice_cells != 0
                             ? detail::snap_polygon_by_double_hull(piece, lattice_cells, scratch.snapped, scratch.snap)
                             : snap_polygon_conservative(piece, lattice_cells, scratch.snapped, scratch.snap, &rect);
      if (k < 3) continue;
      const std::span<const glm::vec2> poly(scratch.snapped.data(), k);
      pass_on(node, link.portal, link.neighbour, target, poly, reference_paths ? bounds_of(poly) : rect);
    }
  }
};

namespace {

// Sizes `out` for the worst case of a build on `world` (every node visible with
// `options.max_region_polygons` polygons of the most vertices, every instance visible), so that
// building into it does not allocate; what it holds is kept.
void reserve_output(const detail::LinkViews& links, const World& world, const VisibilityOptions& options,
                    VisibleSet& out) {
  const size_t cells = world.cells.size();
  if (out.cells.capacity() < cells) {
    const size_t nodes = links.node_capacity();  // the cells, plus linked entries when the world has links
    out.cells.reserve(cells);
    out.polygons.reserve(nodes * options.max_region_polygons);
    out.vertices_ndc.reserve(nodes * options.max_region_polygons * kMaxRegionPolygonVertices);
    out.instances.reserve(world.instances.size());
    out.slot_of_cell.reserve(cells);
  }
  if (out.transforms.capacity() == 0) out.transforms.reserve(1);  // [0], the identity, in every build
  if (out.transforms.capacity() < kMaxViewTransforms && links.has_links()) {
    out.transforms.reserve(kMaxViewTransforms);
    out.linked_cells.reserve(links.node_capacity() - cells);
    out.unresolved.reserve(kMaxUnresolvedEntries);
  }
}

}  // namespace

Status validate_options(const VisibilityOptions& options) {
  if (!valid_snap_lattice(options.snap_lattice_cells))
    return Status::error("visibility: snap_lattice_cells " + std::to_string(options.snap_lattice_cells) +
                         " is not a power of two in [2, " + std::to_string(kMaxSnapLatticeCells) + "]");
  if (options.max_region_polygons < 1 || options.max_region_polygons > kMaxRegionPolygonsLimit)
    return Status::error("visibility: max_region_polygons " + std::to_string(options.max_region_polygons) +
                         " is outside [1, " + std::to_string(kMaxRegionPolygonsLimit) + "]");
  if (options.reprocess_cap > (1u << 20))
    return Status::error("visibility: reprocess_cap " + std::to_string(options.reprocess_cap) + " is above 2^20");
  return {};
}

uint64_t pop_bound(uint32_t cell_count, const VisibilityOptions& options) {
  return uint64_t(cell_count) * (uint64_t(options.reprocess_cap) + 2 * uint64_t(options.snap_lattice_cells));
}

uint64_t pop_bound(const World& world, const VisibilityOptions& options) {
  const uint32_t cells = static_cast<uint32_t>(world.cells.size());
  const bool links =
      std::any_of(world.portals.begin(), world.portals.end(), [](const Portal& p) { return p.linked(); });
  return pop_bound(cells + (links ? linked_node_budget(cells) : 0), options);
}

VisibilityBuilder::VisibilityBuilder() : impl_(std::make_unique<Impl>()) {}

void VisibilityBuilderTesting::disable_snap_and_cap(VisibilityBuilder& builder, bool on) {
  builder.impl_->test_only_unbounded = on;
}
void VisibilityBuilderTesting::use_reference_paths(VisibilityBuilder& builder, bool on) {
  builder.impl_->reference_paths = on;
}
void VisibilityBuilderTesting::merge_pending_windows(VisibilityBuilder& builder, bool on) {
  builder.impl_->merge_windows = on;
}
VisibilityBuilder::~VisibilityBuilder() = default;
VisibilityBuilder::VisibilityBuilder(VisibilityBuilder&&) noexcept = default;
VisibilityBuilder& VisibilityBuilder::operator=(VisibilityBuilder&&) noexcept = default;

void VisibilityBuilder::prepare(const World& world, const VisibilityOptions& options) {
  assert(options.max_region_polygons >= 1 && options.max_region_polygons <= kMaxRegionPolygonsLimit);
  Impl& im = *impl_;
  const uint32_t cells = static_cast<uint32_t>(world.cells.size());
  im.world = &world;
  im.revision = world.revision;
  im.cells = world.cells.size();
  im.portals = world.portals.size();
  im.instances = world.instances.size();
  im.links.prepare(world);
  const uint32_t nodes = im.links.node_capacity();
  im.regions.prepare(nodes, options.max_region_polygons);
  im.cull.prepare(world);
  im.instance_moves = world.instance_moves;
  im.queue.prepare(nodes);
  im.order.clear();
  im.order.reserve(cells);
  im.linked_order.clear();
  im.linked_order.reserve(nodes - cells);
  im.unresolved.clear();
  im.unresolved.reserve(im.links.has_links() ? kMaxUnresolvedEntries : 0);
  im.pending_vertices.assign(size_t(options.max_region_polygons) * kMaxRegionPolygonVertices, glm::vec2(0.0f));
  im.projections.prepare(world);
  im.build_stamp = 0;
  im.packed.prepare(world);  // every projection stamp 0: none made
}

void VisibilityBuilder::prepare(const World& world, const VisibilityOptions& options, VisibleSet& out) {
  prepare(world, options);
  reserve_output(impl_->links, world, options, out);
}

void VisibilityBuilder::instances_moved(const World& world, const DynamicInstances& movers) {
  Impl& im = *impl_;
  if (im.world != &world || im.revision != world.revision || im.cells != world.cells.size() ||
      im.portals != world.portals.size() || im.instances != world.instances.size())
    return;
  if (movers.bound_world() != &world || movers.bound_revision() != world.revision) return;
  // A builder that missed an earlier take cannot catch up from this one: build() re-derives.
  if (im.instance_moves < movers.taken_from() || im.instance_moves > movers.taken_through()) return;
  im.cull.update(world, movers.reach(), movers.taken());
  // Current through the take; moves after it (if any) leave the counters apart: build() re-derives.
  im.instance_moves = movers.taken_through();
}

Status VisibilityBuilder::build(const World& world, const View& view, uint32_t start_cell,
                                const VisibilityOptions& options, VisibleSet& out) {
  impl_->prefetch_scratch(out);  // first, so that its misses overlap the checks below
  out.clear();
  if (Status s = validate_view(view); !s) return s;
  if (Status s = validate_options(options); !s) return s;
  if (start_cell >= world.cells.size())
    return Status::error("visibility: start cell " + std::to_string(start_cell) + " is not one of the world's " +
                         std::to_string(world.cells.size()) + " cells");
  Impl& im = *impl_;
  if (!im.prepared_for(world, options)) {
    prepare(world, options);
  } else if (im.instance_moves != world.instance_moves) {  // moved without instances_moved(): re-derive
    im.cull.prepare(world);
    im.instance_moves = world.instance_moves;
  }

  // Forget the previous frame: regions and cached projections by their stamps.
  if (++im.build_stamp == 0) {  // wrapped: no stale stamp may equal the new one
    im.packed.clear_projection_stamps();
    im.build_stamp = 1;
  }
  im.projections.reset();
  im.regions.reset();  // a node's region and state start empty when the build first touches it
  im.queue.clear();

  const uint32_t cells = static_cast<uint32_t>(world.cells.size());
  const bool unbounded = im.test_only_unbounded;
  im.w = &world;
  im.stats = &out.stats;
  im.lattice_cells = unbounded ? 0 : options.snap_lattice_cells;
  im.reprocess_cap = unbounded ? std::numeric_limits<uint32_t>::max() : options.reprocess_cap;
  const uint64_t bound = pop_bound(im.links.node_capacity(), options);
  // Defaults: the bound is a theorem (asserted in debug); release builds still stop there rather
  // than hang if it were ever wrong. Test-only mode: the hard stop of the drift-hang test.
  const uint64_t hard_limit = unbounded ? kUnboundedSafetyFactor * bound : bound;
  out.stats.pop_bound = bound;

  im.lens.update(view);
  const glm::dmat4 view_proj = im.lens.view_projection(view);
  const double near_extent = im.lens.near_extent;
  const double clip_depth = im.lens.clip_depth;
  im.links.reset(view_proj, glm::dvec3(view.eye_world));
  im.unresolved.clear();

  im.regions.set_full_screen(start_cell);
  im.state[start_cell].ever_queued = true;
  im.state[start_cell].reached_from = start_cell;
  im.enqueue(start_cell, 0.0f);
  while (!im.queue.empty()) {
    if (out.stats.pops >= hard_limit) {
      out.stats.bound_exceeded = true;
      break;
    }
    const uint32_t node = im.pop();
    ++im.state[node].pops;
    ++out.stats.pops;
    im.take_pending(node);
    const uint32_t cell = im.links.cell_of(node);
    const std::span<const PortalLink> cell_links = im.packed.links(cell);
    if (im.state[node].pops == 1) im.prefetch_links(cell_links);  // a later pop finds them cached
    for (const PortalLink& link : cell_links) im.process_link(node, cell, link, view, near_extent, clip_depth);
    for (uint32_t p : world.cells[cell].linked_portals)
      im.process_link(node, cell, {p, world.portals[p].to}, view, near_extent, clip_depth);
  }
  assert(unbounded || out.stats.pops <= bound);

  // Output: visible cells in ascending index order, their regions copied compactly.
  out.start_cell = start_cell;
  reserve_output(im.links, world, options, out);  // once: a no-op when `out` already has the room
  out.slot_of_cell.assign(cells, -1);
  im.order.clear();
  im.linked_order.clear();
  for (uint32_t n : im.regions.touched()) (n < cells ? im.order : im.linked_order).push_back(n);
  std::sort(im.order.begin(), im.order.end());
  std::sort(im.linked_order.begin(), im.linked_order.end(), [&im](uint32_t a, uint32_t b) {
    const uint32_t va = im.links.view_of(a), vb = im.links.view_of(b);
    return va != vb ? va < vb : im.links.cell_of(a) < im.links.cell_of(b);
  });
  auto emit = [&](uint32_t n) {
    VisibleCell vc;
    vc.cell = im.links.cell_of(n);
    vc.transform = im.links.view_of(n);
    vc.first_polygon = static_cast<uint32_t>(out.polygons.size());
    vc.polygon_count = im.regions.polygon_count(n);
    vc.rect_ndc = im.regions.rect(n);
    vc.reached_from = im.links.cell_of(im.state[n].reached_from);
    vc.reached_from_transform = im.links.view_of(im.state[n].reached_from);
    vc.pops = im.state[n].pops;
    vc.collapsed_to_rect = im.regions.is_rect(n);
    for (uint32_t i = 0; i < vc.polygon_count; ++i) {
      const auto poly = im.regions.polygon(n, i);
      out.polygons.push_back({static_cast<uint32_t>(out.vertices_ndc.size()), static_cast<uint32_t>(poly.size())});
      out.vertices_ndc.insert(out.vertices_ndc.end(), poly.begin(), poly.end());
    }
    return vc;
  };
  for (uint32_t c : im.order) {
    if (!im.regions.has_region(c)) continue;
    const VisibleCell vc = emit(c);
    out.slot_of_cell[c] = static_cast<int32_t>(out.cells.size());
    out.cells.push_back(vc);
  }
  for (uint32_t n : im.linked_order)
    if (im.regions.has_region(n)) out.linked_cells.push_back(emit(n));
  out.transforms.push_back(ViewTransform{});  // view 0: the identity (its stored copy's lines stay cold)
  for (uint32_t v = 1; v < im.links.view_count(); ++v) out.transforms.push_back(im.links.view(v).transform);
  out.unresolved.assign(im.unresolved.begin(), im.unresolved.end());
  if (options.cull_instances) cull_instances(im.cull, view_proj, glm::dvec3(view.eye_world), out);
  if (options.cull_linked_instances && !out.linked_cells.empty())
    cull_linked_instances(im.cull, view_proj, glm::dvec3(view.eye_world), out);
  im.stats = nullptr;

  if (out.stats.bound_exceeded)
    return Status::error("visibility: traversal stopped after " + std::to_string(out.stats.pops) +
                         " pops, beyond its bound of " + std::to_string(bound) +
                         (unbounded ? " (test-only unbounded mode)" : " (a bug: the bound is proven)"));
  return {};
}

}  // namespace lintel
