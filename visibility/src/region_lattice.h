// Internal: the regions of all cells during one traversal, growing by conservative snapped
// polygons, deduplicated, bounded in polygon count and collapsing to a lattice rect (the "cap"
// fallback). Storage is allocated by prepare() (cells x max_polygons x kMaxRegionPolygonVertices
// vertex slots, 256 bytes per slot) and reused: add() never allocates.
#pragma once

#include <lintel/clip_region.h>

#include <glm/glm.hpp>

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

class RegionLattice {
 public:
  void prepare(uint32_t cell_count, uint32_t max_polygons);
  uint32_t cell_count() const { return static_cast<uint32_t>(cells_.size()); }
  uint32_t max_polygons() const { return max_polygons_; }

  // Empties every region touched since the last reset; O(touched cells).
  void reset();
  std::span<const uint32_t> touched() const { return touched_; }

  bool has_region(uint32_t cell) const { return cells_[cell].polygon_count > 0; }
  bool is_rect(uint32_t cell) const { return cells_[cell].rect_mode; }
  // Bounds of the region (empty rect when there is no region).
  const NdcRect& rect(uint32_t cell) const { return cells_[cell].rect; }

  // The start cell's region: the full screen, one pending polygon.
  void set_full_screen(uint32_t cell);

  // Adds convex polygon `poly_ccw` (3..kMaxRegionPolygonVertices vertices, counter-clockwise,
  // canonical order when it came from the snapper). Never drops any part of it.
  RegionAdd add(uint32_t cell, std::span<const glm::vec2> poly_ccw);

  // True when the region already holds every point of convex `piece` (a clipped portal before
  // snapping): adding its snap could only grow the region beyond what the piece shows.
  bool covers(uint32_t cell, std::span<const glm::dvec2> piece) const;

  // Replaces the region by its bounding rect (a superset) and marks it pending. From then on
  // add() only grows the rect.
  void collapse_to_rect(uint32_t cell);

  uint32_t polygon_count(uint32_t cell) const { return cells_[cell].polygon_count; }
  std::span<const glm::vec2> polygon(uint32_t cell, uint32_t i) const;
  // bounds_of(polygon(cell, i)), kept with the polygon.
  const NdcRect& polygon_rect(uint32_t cell, uint32_t i) const { return slots_[slot_index(cell, i)].rect; }
  bool pending(uint32_t cell, uint32_t i) const { return slots_[slot_index(cell, i)].pending; }
  void clear_pending(uint32_t cell, uint32_t i) { slots_[slot_index(cell, i)].pending = false; }

 private:
  struct Slot {
    uint8_t vertex_count = 0;
    bool pending = false;
    NdcRect rect;  // bounds of the polygon: containment needs containment of bounds first
  };
  struct CellRegion {
    uint8_t polygon_count = 0;
    bool rect_mode = false;
    bool touched = false;
    NdcRect rect;
  };

  size_t slot_index(uint32_t cell, uint32_t i) const { return size_t(cell) * max_polygons_ + i; }
  glm::vec2* slot_vertices(size_t slot) { return vertices_.data() + slot * kMaxRegionPolygonVertices; }
  void touch(uint32_t cell);
  // `rect` is bounds_of(poly) (the callers have it already).
  void write_slot(uint32_t cell, uint32_t i, std::span<const glm::vec2> poly, const NdcRect& rect);
  void write_rect(uint32_t cell, const NdcRect& rect);

  uint32_t max_polygons_ = 0;
  std::vector<CellRegion> cells_;
  std::vector<Slot> slots_;
  std::vector<glm::vec2> vertices_;
  std::vector<uint32_t> touched_;
};

}  // namespace lintel::detail
