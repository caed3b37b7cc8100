// Per-cell regions on the snap lattice: dedup by containment, a polygon limit, and the rect
// fallback that keeps every point it was given.
// Learns from: Descent / Tomb Raider 2 (integer screen rects that only grow terminate a portal
// flood by construction) and Luebke & Georges 1995 (a cell may be entered through several portals;
// its view is the union of what each gives it).
#include "region_lattice.h"

#include "prefetch.h"

#include <algorithm>
#include <cassert>

namespace lintel::detail {

void RegionLattice::prepare(uint32_t cell_count, uint32_t max_polygons) {
  assert(max_polygons >= 1 && max_polygons <= kMaxRegionPolygonsLimit);
  max_polygons_ = max_polygons;
  stamp_ = 1;
  used_ = 0;
  compactions_ = 0;
  cells_.assign(cell_count, CellRegion{});
  slots_.assign(size_t(cell_count) * max_polygons, Slot{});
  // Every slot full, plus one polygon: the one being written while its slot still counts as live
  // (write_rect), so a compacted arena always has room for the next polygon.
  const size_t capacity = (slots_.size() + 1) * kMaxRegionPolygonVertices;
  assert(capacity <= UINT32_MAX);
  vertices_.assign(capacity, glm::vec2(0.0f));
  touched_.clear();
  touched_.reserve(cell_count);
  live_.clear();
  live_.reserve(slots_.size());
}

void RegionLattice::reset() {
  touched_.clear();
  used_ = 0;
  if (++stamp_ == 0) {  // wrapped: no stale stamp may equal the new one
    for (CellRegion& c : cells_) c.stamp = 0;
    stamp_ = 1;
  }
}

void RegionLattice::prefetch_heads() const {
  prefetch_write(slots_.data(), 4 * kCacheLine);
  prefetch_write(vertices_.data(), 4 * kCacheLine);
  prefetch_write(touched_.data(), kCacheLine);
}

void RegionLattice::prefetch_cell(uint32_t cell) const { prefetch_write(&cells_[cell]); }

void RegionLattice::touch(uint32_t cell) {
  assert(cell < cells_.size());
  CellRegion& region = cells_[cell];
  if (region.stamp == stamp_) return;
  assert(touched_.size() < touched_.capacity());  // reserved in prepare(): no allocation here
  region = CellRegion{stamp_, static_cast<uint32_t>(touched_.size() * max_polygons_), 0, false, NdcRect{}, NodeState{}};
  touched_.push_back(cell);
}

uint32_t RegionLattice::allocate(uint32_t n) {
  if (vertices_.size() - used_ < n) compact();
  assert(vertices_.size() - used_ >= n);
  const uint32_t first = used_;
  used_ += n;
  return first;
}

void RegionLattice::compact() {
  // Slide the live polygons down in arena order: each moves to or below where it was, so the
  // copies never overwrite a polygon not yet moved.
  ++compactions_;
  live_.clear();
  for (uint32_t cell : touched_) {
    const CellRegion& region = cells_[cell];
    for (uint32_t i = 0; i < region.polygon_count; ++i) {
      const size_t slot = size_t(region.first_slot) + i;
      live_.push_back(uint64_t(slots_[slot].first) << 32 | slot);
    }
  }
  std::sort(live_.begin(), live_.end());
  uint32_t to = 0;
  for (const uint64_t key : live_) {
    Slot& slot = slots_[size_t(key & 0xffffffffu)];
    std::copy_n(vertices_.data() + slot.first, slot.vertex_count, vertices_.data() + to);
    slot.first = to;
    to += slot.vertex_count;
  }
  used_ = to;
}

std::span<const glm::vec2> RegionLattice::polygon(uint32_t cell, uint32_t i) const {
  assert(i < polygon_count(cell));
  const Slot& slot = slots_[slot_index(cell, i)];
  return {vertices_.data() + slot.first, slot.vertex_count};
}

void RegionLattice::write_slot(uint32_t cell, uint32_t i, std::span<const glm::vec2> poly, const NdcRect& rect) {
  assert(poly.size() >= 3 && poly.size() <= kMaxRegionPolygonVertices);
  assert(rect == bounds_of(poly));
  const uint32_t n = static_cast<uint32_t>(poly.size());
  const uint32_t first = allocate(n);  // may compact: slot indices stay, offsets change
  std::copy(poly.begin(), poly.end(), vertices_.data() + first);
  slots_[slot_index(cell, i)] = Slot{first, static_cast<uint8_t>(n), true, rect};
}

void RegionLattice::write_rect(uint32_t cell, const NdcRect& rect) {
  assert(!rect.empty());
  // Canonical order: counter-clockwise from the lexicographically smallest corner.
  const glm::vec2 corners[4] = {rect.min, {rect.max.x, rect.min.y}, rect.max, {rect.min.x, rect.max.y}};
  CellRegion& region = cells_[cell];
  write_slot(cell, 0, corners, rect);  // the corners' bounds are the rect itself
  region.polygon_count = 1;
  region.rect_mode = true;
  region.rect = rect;
}

void RegionLattice::set_full_screen(uint32_t cell) {
  touch(cell);
  assert(polygon_count(cell) == 0);
  const NdcRect screen = full_screen_rect();
  const glm::vec2 corners[4] = {screen.min, {screen.max.x, screen.min.y}, screen.max, {screen.min.x, screen.max.y}};
  write_slot(cell, 0, corners, screen);
  cells_[cell].polygon_count = 1;
  cells_[cell].rect = screen;
}

RegionAdd RegionLattice::add(uint32_t cell, std::span<const glm::vec2> poly_ccw) {
  return add(cell, poly_ccw, bounds_of(poly_ccw));
}

RegionAdd RegionLattice::add(uint32_t cell, std::span<const glm::vec2> poly_ccw, const NdcRect& poly_rect) {
  assert(poly_ccw.size() >= 3 && poly_ccw.size() <= kMaxRegionPolygonVertices);
  assert(poly_rect == bounds_of(poly_ccw));
  touch(cell);
  CellRegion& region = cells_[cell];

  if (region.rect_mode) {
    if (region.rect.contains(poly_rect)) return RegionAdd::Skipped;
    NdcRect grown = region.rect;
    grown.extend(poly_rect);
    write_rect(cell, grown);
    return RegionAdd::RectGrew;
  }

  // Dedup: skip when an existing polygon already covers it. Equal polygons are contained too.
  // (The bounds tests are exact: a polygon holds a vertex only if its bounds do.)
  if (region.rect.contains(poly_rect))
    for (uint32_t i = 0; i < region.polygon_count; ++i)
      if (slots_[slot_index(cell, i)].rect.contains(poly_rect) && convex_contains_convex(polygon(cell, i), poly_ccw))
        return RegionAdd::Skipped;

  // Drop polygons the new one covers: the union is unchanged and the region stays small.
  uint32_t kept = 0;
  for (uint32_t i = 0; i < region.polygon_count; ++i) {
    if (poly_rect.contains(slots_[slot_index(cell, i)].rect) && convex_contains_convex(poly_ccw, polygon(cell, i)))
      continue;
    if (kept != i) slots_[slot_index(cell, kept)] = slots_[slot_index(cell, i)];  // its vertices stay where they are
    ++kept;
  }
  region.polygon_count = static_cast<uint8_t>(kept);

  NdcRect grown = region.rect;
  grown.extend(poly_rect);
  if (kept == max_polygons_) {
    // Polygon limit: the bounding rect of everything, the new polygon included.
    write_rect(cell, grown);
    return RegionAdd::Collapsed;
  }
  write_slot(cell, kept, poly_ccw, poly_rect);
  region.polygon_count = static_cast<uint8_t>(kept + 1);
  region.rect = grown;
  return RegionAdd::Added;
}

bool RegionLattice::covers(uint32_t cell, std::span<const glm::dvec2> piece) const {
  if (polygon_count(cell) == 0 || piece.empty()) return false;
  const CellRegion& region = cells_[cell];
  glm::dvec2 lo = piece[0], hi = piece[0];
  for (const glm::dvec2& v : piece) {
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  auto rect_holds = [&](const NdcRect& r) {
    return double(r.min.x) <= lo.x && double(r.min.y) <= lo.y && hi.x <= double(r.max.x) && hi.y <= double(r.max.y);
  };
  if (!rect_holds(region.rect)) return false;
  if (region.rect_mode) return true;
  for (uint32_t i = 0; i < region.polygon_count; ++i)
    if (rect_holds(slots_[slot_index(cell, i)].rect) && convex_contains_points(polygon(cell, i), piece)) return true;
  return false;
}

void RegionLattice::collapse_to_rect(uint32_t cell) {
  assert(has_region(cell));  // fresh: touched since reset()
  write_rect(cell, cells_[cell].rect);
}

}  // namespace lintel::detail
