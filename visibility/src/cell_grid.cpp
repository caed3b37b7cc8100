// The cell grid of cell_locate.h: an index over the cells' volume boxes for locate_cell.
#include <lintel/cell_locate.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace lintel {
namespace {

// A cell's volume box in world space, widened past every rounding between its frames.
Aabb widened_world_box(const Cell& cell) {
  Aabb box = transform_aabb(cell.cell_to_world, cell.volume_box_cell);
  if (box.empty()) return box;
  const glm::vec3 extent = box.max - box.min;
  const float scale = std::max({std::abs(box.min.x), std::abs(box.min.y), std::abs(box.min.z), std::abs(box.max.x),
                                std::abs(box.max.y), std::abs(box.max.z), extent.x, extent.y, extent.z});
  const float slack = 1e-5f * scale + 1e-6f;
  box.min -= slack;
  box.max += slack;
  return box;
}

}  // namespace

void CellGrid::build(const World& world) {
  std::vector<Aabb>& boxes = boxes_;
  boxes.assign(world.cells.size(), Aabb{});
  Aabb all;
  std::vector<double> sizes;
  for (size_t c = 0; c < world.cells.size(); ++c) {
    boxes[c] = widened_world_box(world.cells[c]);
    if (boxes[c].empty()) continue;
    all.extend(boxes[c]);
    const glm::vec3 e = boxes[c].max - boxes[c].min;
    sizes.push_back(double(std::max({e.x, e.y, e.z})));
  }
  begin_.assign(1, 0);
  cells_.clear();
  dims_ = glm::ivec3(0);
  if (all.empty()) return;
  // Buckets about one typical cell across, at most ~4 per cell (a bucket size doubled until so).
  std::nth_element(sizes.begin(), sizes.begin() + std::ptrdiff_t(sizes.size() / 2), sizes.end());
  bucket_m_ = std::max(sizes[sizes.size() / 2], 1e-6);
  origin_ = glm::dvec3(all.min);
  const glm::dvec3 extent = glm::dvec3(all.max) - origin_;
  const double limit = 4.0 * double(world.cells.size()) + 64.0;
  for (;;) {
    const glm::dvec3 d = glm::max(glm::ceil(extent / bucket_m_), glm::dvec3(1.0));
    if (d.x * d.y * d.z <= limit) {
      dims_ = glm::ivec3(d);
      break;
    }
    bucket_m_ *= 2.0;
  }
  auto bucket_of = [&](const glm::dvec3& p) {
    return glm::clamp(glm::ivec3(glm::floor((p - origin_) / bucket_m_)), glm::ivec3(0), dims_ - 1);
  };
  const size_t buckets = size_t(dims_.x) * size_t(dims_.y) * size_t(dims_.z);
  std::vector<uint32_t> count(buckets + 1, 0);
  auto for_each_bucket = [&](const Aabb& box, auto&& f) {
    const glm::ivec3 lo = bucket_of(glm::dvec3(box.min)), hi = bucket_of(glm::dvec3(box.max));
    for (int z = lo.z; z <= hi.z; ++z)
      for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x) f((size_t(z) * size_t(dims_.y) + size_t(y)) * size_t(dims_.x) + size_t(x));
  };
  for (size_t c = 0; c < boxes.size(); ++c)
    if (!boxes[c].empty()) for_each_bucket(boxes[c], [&](size_t b) { ++count[b + 1]; });
  for (size_t b = 0; b < buckets; ++b) count[b + 1] += count[b];
  begin_ = count;
  cells_.assign(begin_.back(), 0);
  std::vector<uint32_t> next(begin_.begin(), begin_.end() - 1);
  for (size_t c = 0; c < boxes.size(); ++c)  // ascending c: every bucket's list stays ascending
    if (!boxes[c].empty()) for_each_bucket(boxes[c], [&](size_t b) { cells_[next[b]++] = uint32_t(c); });
}

std::span<const uint32_t> CellGrid::candidates(const glm::dvec3& p) const {
  if (dims_.x == 0) return {};
  glm::dvec3 q = glm::floor((p - origin_) / bucket_m_);
  // Outside the grid (or not finite): no widened box holds p, so no volume does. On the grid's far
  // faces (q == dims) p is in the last bucket, as build() files the boxes that reach them.
  if (!(q.x >= 0.0 && q.y >= 0.0 && q.z >= 0.0 && q.x <= dims_.x && q.y <= dims_.y && q.z <= dims_.z)) return {};
  q = glm::min(q, glm::dvec3(dims_ - 1));
  const size_t b = (size_t(q.z) * size_t(dims_.y) + size_t(q.y)) * size_t(dims_.x) + size_t(q.x);
  return {cells_.data() + begin_[b], begin_[b + 1] - begin_[b]};
}

double CellGrid::box_distance_m(uint32_t cell, const glm::dvec3& p) const {
  const Aabb& box = boxes_[cell];
  if (box.empty()) return std::numeric_limits<double>::infinity();
  const glm::dvec3 outside = glm::max(glm::max(glm::dvec3(box.min) - p, p - glm::dvec3(box.max)), glm::dvec3(0.0));
  return glm::length(outside);
}

bool contained_cell(const World& world, const CellGrid& grid, const glm::dvec3& p_world,
                    std::span<const double> volumes_m3, uint32_t& cell) {
  assert(volumes_m3.size() == world.cells.size());
  bool found = false;
  for (uint32_t c : grid.candidates(p_world)) {  // ascending, as locate_cell's own loop
    if (!cell_volume_contains(world, c, p_world)) continue;
    if (!found || volumes_m3[c] < volumes_m3[cell]) {
      found = true;
      cell = c;
    }
  }
  return found;
}

CellLocation locate_cell(const World& world, const CellGrid& grid, const glm::dvec3& p_world,
                         std::span<const double> volumes_m3) {
  uint32_t cell = 0;
  if (contained_cell(world, grid, p_world, volumes_m3, cell)) return {cell, LocateReason::Containment, 0.0};
  // No volume holds p (the candidates hold every one that can): the nearest, lowest index on a tie.
  // The cell with the nearest box first gives a tight bound; a cell whose box is farther than the
  // best distance so far cannot beat or tie it.
  const uint32_t n = uint32_t(world.cells.size());
  uint32_t first = 0;
  double first_box = std::numeric_limits<double>::infinity();
  for (uint32_t c = 0; c < n; ++c)
    if (const double b = grid.box_distance_m(c, p_world); b < first_box) {
      first_box = b;
      first = c;
    }
  CellLocation best{first, LocateReason::Nearest, cell_volume_distance_m(world, first, p_world)};
  for (uint32_t c = 0; c < n; ++c) {
    if (c == first || grid.box_distance_m(c, p_world) > best.distance_m) continue;
    const double d = cell_volume_distance_m(world, c, p_world);
    if (d < best.distance_m || (d == best.distance_m && c < best.cell)) best = {c, LocateReason::Nearest, d};
  }
  return best;
}

}  // namespace lintel
