// The answer of one visibility query: the visible cells with their clip regions (NDC), the
// visible instances, and counters that say how the traversal went. Caller-owned and reusable:
// clear() keeps every vector's capacity, so a VisibleSet filled again by VisibilityBuilder::build
// does not allocate once it has held the largest frame.
#pragma once

#include <lintel/clip_region.h>

#include <cstdint>
#include <span>
#include <vector>

namespace lintel {

struct VisibleCell {
  uint32_t cell = 0;               // index into World::cells
  uint32_t first_polygon = 0;      // its region: VisibleSet::polygons[first_polygon, + polygon_count)
  uint32_t polygon_count = 0;      // >= 1
  NdcRect rect_ndc;                // bounds of the region, inside [-1, 1]^2
  uint32_t reached_from = 0;       // cell whose portal first gave it a region (itself for the start)
  uint32_t pops = 0;               // times the traversal processed it (>= 1)
  bool collapsed_to_rect = false;  // the cap or the polygon limit turned its region into one rect
  friend bool operator==(const VisibleCell&, const VisibleCell&) = default;
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
  uint64_t instances_tested = 0;            // instance slots of visible cells (one per reached cell) tested
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
  VisibilityStats stats;

  bool cell_visible(uint32_t cell) const { return cell < slot_of_cell.size() && slot_of_cell[cell] >= 0; }
  // The entry of a visible cell, or nullptr.
  const VisibleCell* find(uint32_t cell) const {
    return cell_visible(cell) ? &cells[size_t(slot_of_cell[cell])] : nullptr;
  }
  ClipRegionView region(const VisibleCell& c) const {
    return {std::span<const RegionPolygon>(polygons).subspan(c.first_polygon, c.polygon_count), vertices_ndc,
            c.rect_ndc};
  }
  // Empties the set, keeping capacity.
  void clear();

  friend bool operator==(const VisibleSet&, const VisibleSet&) = default;
};

}  // namespace lintel
