// Internal: the regions of all cells during one traversal, growing by conservative snapped
// polygons, deduplicated, bounded in polygon count and collapsing to a lattice rect (the "cap"
// fallback). Storage is allocated by prepare() (room for cells x max_polygons polygons of
// kMaxRegionPolygonVertices vertices, 256 bytes each, plus one) and reused: add() never allocates.
// A build touches few cells of many and runs between other work that evicts its data, so the
// storage is laid out for few cache lines per build: a cell's polygon slots are a block handed out
// in the order cells are first touched (the blocks of one build are neighbours), polygon vertices
// are appended to one arena (a build's polygons are packed, not 256 bytes apart), and reset() only
// moves a stamp (the previous build's cells are not written again; a stale cell reads as empty).
#pragma once

#include <lintel/clip_region.h>

#include <glm/glm.hpp>

#include <cassert>
#include <cstdint>
#include <span>
#include <vector>

namespace lintel::detail {

enum class RegionAdd : uint8_t {
  Skipped,    // equal to or inside a polygon already there (or inside the rect): nothing changed
  Added,      // appended as a new pending polygon (polygons it contains were removed)
  Collapsed,  // the polygon limit overflowed: the region became the bounding rect of all + new
  RectGrew,   // the region is a rect and grew to cover the new polygon
};

// The traversal's bookkeeping of one node (portal_traversal.cpp), kept on the line of the node's
// region: a build reads both for every node it touches, and a node first touched in a build
// starts both empty.
struct NodeState {
  uint32_t pops = 0;
  uint32_t reprocess = 0;     // times queued again after the first processing (while polygons)
  uint32_t reached_from = 0;  // node
  bool queued = false;
  bool ever_queued = false;
};

class RegionLattice {
 public:
  void prepare(uint32_t cell_count, uint32_t max_polygons);
  uint32_t cell_count() const { return static_cast<uint32_t>(cells_.size()); }
  uint32_t max_polygons() const { return max_polygons_; }

  // Empties every region touched since the last reset; O(1) (a stamp: stale cells read as empty).
  void reset();
  std::span<const uint32_t> touched() const { return touched_; }
  // Asks for the lines a build's first cells will write (the heads of the touch-ordered slots,
  // vertices and touched list), and for `cell`'s own line (prefetch.h).
  void prefetch_heads() const;
  void prefetch_cell(uint32_t cell) const;

  bool has_region(uint32_t cell) const { return polygon_count(cell) > 0; }
  bool is_rect(uint32_t cell) const { return fresh(cell) && cells_[cell].rect_mode; }
  // Bounds of the region (empty rect when there is no region).
  const NdcRect& rect(uint32_t cell) const { return fresh(cell) ? cells_[cell].rect : kEmpty; }

  // The start cell's region: the full screen, one pending polygon.
  void set_full_screen(uint32_t cell);

  // Adds convex polygon `poly_ccw` (3..kMaxRegionPolygonVertices vertices, counter-clockwise,
  // canonical order when it came from the snapper). Never drops any part of it.
  RegionAdd add(uint32_t cell, std::span<const glm::vec2> poly_ccw);
  // The same with the polygon's bounds already known (`rect` == bounds_of(poly_ccw)).
  RegionAdd add(uint32_t cell, std::span<const glm::vec2> poly_ccw, const NdcRect& rect);

  // True when the region already holds every point of convex `piece` (a clipped portal before
  // snapping): adding its snap could only grow the region beyond what the piece shows.
  bool covers(uint32_t cell, std::span<const glm::dvec2> piece) const;

  // Replaces the region by its bounding rect (a superset) and marks it pending. From then on
  // add() only grows the rect.
  void collapse_to_rect(uint32_t cell);

  uint32_t polygon_count(uint32_t cell) const { return fresh(cell) ? cells_[cell].polygon_count : 0; }
  // Valid until the next add(), set_full_screen() or collapse_to_rect() (the arena may compact).
  std::span<const glm::vec2> polygon(uint32_t cell, uint32_t i) const;
  // bounds_of(polygon(cell, i)), kept with the polygon.
  const NdcRect& polygon_rect(uint32_t cell, uint32_t i) const { return slots_[slot_index(cell, i)].rect; }
  bool pending(uint32_t cell, uint32_t i) const { return slots_[slot_index(cell, i)].pending; }
  void clear_pending(uint32_t cell, uint32_t i) { slots_[slot_index(cell, i)].pending = false; }

  // The node's traversal state; only for a node touched since reset() (empty when first touched).
  NodeState& node_state(uint32_t cell) {
    assert(fresh(cell));
    return cells_[cell].state;
  }
  const NodeState& node_state(uint32_t cell) const {
    assert(fresh(cell));
    return cells_[cell].state;
  }

  // Times the vertex arena was compacted since prepare() (tests: the rare path is exercised).
  uint64_t compactions() const { return compactions_; }

 private:
  struct Slot {
    uint32_t first = 0;  // its vertices: vertices_[first, first + vertex_count)
    uint8_t vertex_count = 0;
    bool pending = false;
    NdcRect rect;  // bounds of the polygon: containment needs containment of bounds first
  };
  struct alignas(64) CellRegion {  // one cache line
    uint32_t stamp = 0;            // the reset it was touched after; any other: no region
    uint32_t first_slot = 0;       // its max_polygons_ slots: slots_[first_slot, + max_polygons_)
    uint8_t polygon_count = 0;
    bool rect_mode = false;
    NdcRect rect;
    NodeState state;
  };
  inline static const NdcRect kEmpty{};

  bool fresh(uint32_t cell) const { return cells_[cell].stamp == stamp_; }
  size_t slot_index(uint32_t cell, uint32_t i) const {
    assert(fresh(cell) && i < max_polygons_);
    return size_t(cells_[cell].first_slot) + i;
  }
  void touch(uint32_t cell);
  // Room for `n` more vertices at the arena's end (compacts it when full); returns the offset.
  uint32_t allocate(uint32_t n);
  void compact();
  // `rect` is bounds_of(poly) (the callers have it already).
  void write_slot(uint32_t cell, uint32_t i, std::span<const glm::vec2> poly, const NdcRect& rect);
  void write_rect(uint32_t cell, const NdcRect& rect);

  uint32_t max_polygons_ = 0;
  uint32_t stamp_ = 1;
  uint32_t used_ = 0;  // vertices_[0, used_) handed out since reset()
  uint64_t compactions_ = 0;
  std::vector<CellRegion> cells_;
  std::vector<Slot> slots_;          // blocks of max_polygons_, one per touched cell, in touch order
  std::vector<glm::vec2> vertices_;  // the arena
  std::vector<uint32_t> touched_;
  std::vector<uint64_t> live_;  // compact() scratch: (first << 32 | slot) of every live polygon
};

}  // namespace lintel::detail
