// The answer of one visibility query: the visible cells with their clip regions (NDC), the
// visible instances, and counters that say how the traversal went. Caller-owned and reusable:
// clear() keeps every vector's capacity, so a VisibleSet filled again by VisibilityBuilder::build
// does not allocate once it has held the largest frame.
// Linked portals (teleports, mirrors; docs/visibility.md, "Linked portals") add entries seen
// through a view transform: `cells` and `instances` stay the plain (identity) entries every
// existing reader knows; `linked_cells` and `linked_instances` carry the others, each naming its
// transform in `transforms` (transforms[0] is the identity).
#pragma once

#include <lintel/clip_region.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace lintel {

struct VisibleCell {
  uint32_t cell = 0;                    // index into World::cells
  uint32_t first_polygon = 0;           // its region: VisibleSet::polygons[first_polygon, + polygon_count)
  uint32_t polygon_count = 0;           // >= 1
  NdcRect rect_ndc;                     // bounds of the region, inside [-1, 1]^2
  uint32_t reached_from = 0;            // cell whose portal first gave it a region (itself for the start)
  uint32_t transform = 0;               // index into VisibleSet::transforms: 0 in `cells`, >= 1 in `linked_cells`
  uint32_t reached_from_transform = 0;  // the transform of the entry it was reached from
  uint32_t pops = 0;                    // times the traversal processed it (>= 1)
  bool collapsed_to_rect = false;       // the cap or the polygon limit turned its region into one rect
  friend bool operator==(const VisibleCell&, const VisibleCell&) = default;
};

// A view through linked portals. A cell entry with this transform is drawn with its geometry
// (shell and instances, world space) mapped by `seen_from_world`: what the eye sees through the
// chain of linked portals. Culling it is culling the cell in world space from the eye
// inverse(seen_from_world) * eye with view_proj * seen_from_world.
struct ViewTransform {
  glm::dmat4 seen_from_world{1.0};
  uint32_t parent = 0;                                     // the transform it was seen from
  uint32_t portal = std::numeric_limits<uint32_t>::max();  // the linked portal it was seen through
  uint32_t depth = 0;                                      // linked portals in the chain, <= kMaxLinkDepth
  bool mirrored = false;                                   // determinant -1: front faces flip
  friend bool operator==(const ViewTransform&, const ViewTransform&) = default;
};

struct LinkedInstance {
  uint32_t transform = 0;  // index into VisibleSet::transforms (>= 1)
  uint32_t instance = 0;   // World::instances index
  friend bool operator==(const LinkedInstance&, const LinkedInstance&) = default;
};

// Pixels seen through a linked portal that the traversal did not follow (link depth beyond
// kMaxLinkDepth, or the view / linked-cell budget spent): a renderer fills `rect_ndc` (a superset
// of those pixels) with a flat colour, as engines do at their recursion limit.
struct UnresolvedLink {
  uint32_t cell = 0;       // the cell the linked portal was seen from
  uint32_t transform = 0;  // ... through this transform
  uint32_t portal = 0;     // the linked portal
  NdcRect rect_ndc;
  friend bool operator==(const UnresolvedLink&, const UnresolvedLink&) = default;
};

struct VisibilityStats {
  uint64_t pops = 0;                        // cells taken from the queue
  uint64_t reenqueues = 0;                  // times a processed cell was queued again after growing
  uint64_t cap_hits = 0;                    // cells whose re-process count reached the cap K
  uint64_t polygon_overflows = 0;           // regions collapsed by the polygon limit
  uint64_t snapped_duplicates_skipped = 0;  // new polygons equal to / inside one already there
  uint64_t near_plane_clips = 0;            // portals partly closer than portal_clip_depth()
  uint64_t doorway_passes = 0;              // portals passed by the doorway rule
  uint64_t closed_portals_skipped = 0;      // (cell, portal) pairs not looked through: a closed door
  uint64_t portals_tested = 0;              // (cell, portal) pairs examined
  uint64_t polygons_added = 0;              // polygons that changed some region
  uint64_t windows_merged = 0;              // pending polygons merged into another's hull before clipping
  uint64_t instances_tested = 0;            // instance slots of visible cells (one per reached cell) tested
  uint64_t linked_portals_followed = 0;     // (entry, linked portal) pairs that passed a region on
  uint64_t link_limit_hits = 0;             // pieces of region not followed: depth or budget (unresolved)
  uint64_t pop_bound = 0;                   // the worst case for this world and these options
  bool bound_exceeded = false;              // only possible with the test-only switch
  friend bool operator==(const VisibilityStats&, const VisibilityStats&) = default;
};

struct VisibleSet {
  uint32_t start_cell = 0;
  std::vector<VisibleCell> cells;       // ascending cell index
  std::vector<RegionPolygon> polygons;  // region polygons, counter-clockwise, canonical order
  std::vector<glm::vec2> vertices_ndc;  // what `polygons` index into
  std::vector<int32_t> slot_of_cell;    // one per world cell: index into `cells`, or -1
  std::vector<uint32_t> instances;      // visible instances (World::instances indices), ascending
  // Linked entries (empty for worlds without linked portals, apart from transforms[0]).
  std::vector<ViewTransform> transforms;         // [0] = identity; the views the entries use
  std::vector<VisibleCell> linked_cells;         // transform >= 1, ascending (transform, cell)
  std::vector<LinkedInstance> linked_instances;  // ascending (transform, instance)
  std::vector<UnresolvedLink> unresolved;        // in traversal order
  VisibilityStats stats;

  bool cell_visible(uint32_t cell) const { return cell < slot_of_cell.size() && slot_of_cell[cell] >= 0; }
  // The entry of a visible cell, or nullptr.
  const VisibleCell* find(uint32_t cell) const {
    return cell_visible(cell) ? &cells[size_t(slot_of_cell[cell])] : nullptr;
  }
  // Region of an entry of `cells` or `linked_cells` (both index `polygons`).
  ClipRegionView region(const VisibleCell& c) const {
    return {std::span<const RegionPolygon>(polygons).subspan(c.first_polygon, c.polygon_count), vertices_ndc,
            c.rect_ndc};
  }
  // Empties the set, keeping capacity.
  void clear();

  friend bool operator==(const VisibleSet&, const VisibleSet&) = default;
};

}  // namespace lintel
