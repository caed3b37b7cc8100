// Per-cell regions on the snap lattice: dedup by containment, a polygon limit, and the rect
// fallback that keeps every point it was given.
// Learns from: Descent / Tomb Raider 2 (integer screen rects that only grow terminate a portal
// flood by construction) and Luebke & Georges 1995 (a cell may be entered through several portals;
// its view is the union of what each gives it).
#include "region_lattice.h"

#include <algorithm>
#include <cassert>

namespace lintel::detail {

void RegionLattice::prepare(uint32_t cell_count, uint32_t max_polygons) {
  assert(max_polygons >= 1 && max_polygons <= kMaxRegionPolygonsLimit);
  max_polygons_ = max_polygons;
  cells_.assign(cell_count, CellRegion{});
  slots_.assign(size_t(cell_count) * max_polygons, Slot{});
  vertices_.assign(slots_.size() * kMaxRegionPolygonVertices, glm::vec2(0.0f));
  touched_.clear();
  touched_.reserve(cell_count);
}

void RegionLattice::reset() {
  for (uint32_t cell : touched_) {
    cells_[cell] = CellRegion{};
    for (uint32_t i = 0; i < max_polygons_; ++i) slots_[slot_index(cell, i)] = Slot{};
  }
  touched_.clear();
}

void RegionLattice::touch(uint32_t cell) {
  assert(cell < cells_.size());
  if (cells_[cell].touched) return;
  cells_[cell].touched = true;
  assert(touched_.size() < touched_.capacity());  // reserved in prepare(): no allocation here
  touched_.push_back(cell);
}

std::span<const glm::vec2> RegionLattice::polygon(uint32_t cell, uint32_t i) const {
  assert(i < cells_[cell].polygon_count);
  const size_t slot = slot_index(cell, i);
  return {vertices_.data() + slot * kMaxRegionPolygonVertices, slots_[slot].vertex_count};
}

void RegionLattice::write_slot(uint32_t cell, uint32_t i, std::span<const glm::vec2> poly, const NdcRect& rect) {
  assert(poly.size() >= 3 && poly.size() <= kMaxRegionPolygonVertices);
  assert(rect == bounds_of(poly));
  const size_t slot = slot_index(cell, i);
  std::copy(poly.begin(), poly.end(), slot_vertices(slot));
  slots_[slot] = Slot{static_cast<uint8_t>(poly.size()), true, rect};
}

void RegionLattice::write_rect(uint32_t cell, const NdcRect& rect) {
  assert(!rect.empty());
  // Canonical order: counter-clockwise from the lexicographically smallest corner.
  const glm::vec2 corners[4] = {rect.min, {rect.max.x, rect.min.y}, rect.max, {rect.min.x, rect.max.y}};
  CellRegion& region = cells_[cell];
  for (uint32_t i = 1; i < region.polygon_count; ++i) slots_[slot_index(cell, i)] = Slot{};
  write_slot(cell, 0, corners, rect);  // the corners' bounds are the rect itself
  region.polygon_count = 1;
  region.rect_mode = true;
  region.rect = rect;
}

void RegionLattice::set_full_screen(uint32_t cell) {
  touch(cell);
  assert(cells_[cell].polygon_count == 0);
  const NdcRect screen = full_screen_rect();
  const glm::vec2 corners[4] = {screen.min, {screen.max.x, screen.min.y}, screen.max, {screen.min.x, screen.max.y}};
  write_slot(cell, 0, corners, screen);
  cells_[cell].polygon_count = 1;
  cells_[cell].rect = screen;
}

RegionAdd RegionLattice::add(uint32_t cell, std::span<const glm::vec2> poly_ccw) {
  assert(poly_ccw.size() >= 3 && poly_ccw.size() <= kMaxRegionPolygonVertices);
  touch(cell);
  CellRegion& region = cells_[cell];
  const NdcRect poly_rect = bounds_of(poly_ccw);

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
    if (kept != i) {
      const size_t from = slot_index(cell, i), to = slot_index(cell, kept);
      std::copy_n(slot_vertices(from), slots_[from].vertex_count, slot_vertices(to));
      slots_[to] = slots_[from];
    }
    ++kept;
  }
  for (uint32_t i = kept; i < region.polygon_count; ++i) slots_[slot_index(cell, i)] = Slot{};
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
  const CellRegion& region = cells_[cell];
  if (region.polygon_count == 0 || piece.empty()) return false;
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
  assert(has_region(cell));
  write_rect(cell, cells_[cell].rect);
}

}  // namespace lintel::detail
