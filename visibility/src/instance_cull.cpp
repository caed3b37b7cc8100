// Instance culling against portal clip regions, over structure-of-arrays bounds.
// Learns from: filament's Culler (SoA batches, conservative box tests) and the Lintel lessons
// (cull bounds from the real mesh extent; a unit box culls identity-transform meshes whose extent
// is baked into their vertices). The near-plane handling mirrors portal_clip.cpp: clip the box's
// edges in homogeneous space before the divide, so a box around or beside the eye keeps a finite,
// faithful screen rect. The per-frame loop rejects most boxes with four planes through the eye
// (the region rect's edges, widened) before projecting any corner; survivors take the projection.
#include <lintel/instance_cull.h>

#include "prefetch.h"

#include <lintel/instance_reach.h>

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <limits>

namespace lintel {

void CullData::prepare(const World& world) {
  InstanceReach reach;
  reach.compute(world);
  const size_t cells = world.cells.size(), instances = world.instances.size();
  cell_begin.assign(cells + 1, 0);
  for (uint32_t i = 0; i < instances; ++i)
    for (const uint32_t* c = reach.begin(i); c != reach.end(i); ++c) {
      assert(*c < cells);
      ++cell_begin[*c + 1];
    }
  for (size_t c = 0; c < cells; ++c) cell_begin[c + 1] += cell_begin[c];
  const size_t n = reach.total();
  slots.assign(n, CullSlot{});
  static_first_.assign(instances + 1, 0);
  static_slot_.assign(n, 0);
  std::vector<uint32_t> next(cell_begin.begin(), cell_begin.end() - 1);
  for (uint32_t i = 0; i < instances; ++i) {  // ascending i: each cell's slots stay sorted
    const Aabb& b = world.instances[i].bounds_world;
    static_first_[i + 1] = static_first_[i] + reach.count(i);
    uint32_t k = static_first_[i];
    for (const uint32_t* c = reach.begin(i); c != reach.end(i); ++c) {
      const uint32_t slot = next[*c]++;
      slots[slot] = CullSlot{b.min, b.max, i, *c};
      static_slot_[k++] = slot;
    }
  }
  movers.clear();
  is_mover_.assign(instances, 0);
  marked_.assign(instances, 0);
}

void CullData::update(const World& world, const InstanceReach& reach, std::span<const uint32_t> moved) {
  assert(is_mover_.size() == world.instances.size() && reach.instance_count() == world.instances.size());
  constexpr float kInf = std::numeric_limits<float>::infinity();
  for (uint32_t i : moved) {
    assert(i < is_mover_.size());
    marked_[i] = 1;
    if (is_mover_[i]) continue;
    is_mover_[i] = 1;
    for (uint32_t k = static_first_[i]; k < static_first_[i + 1]; ++k) {  // empty its per-cell slots
      CullSlot& slot = slots[static_slot_[k]];
      slot.min = glm::vec3(kInf);
      slot.max = glm::vec3(-kInf);
    }
  }
  // Drop the moved instances' old mover slots (stable), then append their new ones.
  size_t kept = 0;
  for (size_t s = 0; s < movers.size(); ++s) {
    if (marked_[movers[s].instance]) continue;
    movers[kept++] = movers[s];
  }
  movers.resize(kept);
  for (uint32_t i : moved) {
    if (!marked_[i]) continue;  // listed twice: already appended
    marked_[i] = 0;
    const Aabb& b = world.instances[i].bounds_world;
    for (const uint32_t* c = reach.begin(i); c != reach.end(i); ++c) movers.push_back(CullSlot{b.min, b.max, i, *c});
  }
}

namespace {

// std::nextafter(x, -inf) and (x, +inf) for non-NaN float x, without the libm call.
float next_down(float x) {
  if (x == 0.0f) return -std::numeric_limits<float>::denorm_min();
  if (x == -std::numeric_limits<float>::infinity()) return x;
  const uint32_t bits = std::bit_cast<uint32_t>(x);
  return std::bit_cast<float>(x > 0.0f ? bits - 1u : bits + 1u);
}
float next_up(float x) {
  if (x == 0.0f) return std::numeric_limits<float>::denorm_min();
  if (x == std::numeric_limits<float>::infinity()) return x;
  const uint32_t bits = std::bit_cast<uint32_t>(x);
  return std::bit_cast<float>(x > 0.0f ? bits + 1u : bits - 1u);
}

constexpr int kEdges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                               {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

// The slab part of project_aabb, from the 8 clip-space corners. Every endpoint below is the value
// the 12-edge Liang-Barsky clip computes (a + (b - a) * t), so the rect is the same bit for bit;
// the shortcuts only skip clips whose outcome is known: all corners outside one plane (every edge
// culled), or all inside both (t0 = 0: the corner a itself; t1 = 1: a + (b - a)).
void project_corners(const glm::dvec4 (&corner)[8], ProjectedBox& out) {
  bool all_behind_near = true, all_beyond_far = true, all_in_slab = true;
  for (const glm::dvec4& c : corner) {
    const double near_d = c.z, far_d = c.w - c.z;
    all_behind_near = all_behind_near && near_d < 0.0;
    all_beyond_far = all_beyond_far && far_d < 0.0;
    all_in_slab = all_in_slab && near_d >= 0.0 && far_d >= 0.0;
  }
  if (all_behind_near || all_beyond_far) return;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  glm::dvec2 lo(kInf), hi(-kInf);
  auto add = [&](const glm::dvec4& c) {
    // On the slab w >= near > 0; guard the division against rounding at w ~ 0 anyway.
    if (!(c.w > 0.0)) return;
    out.in_slab = true;
    const glm::dvec2 p(c.x / c.w, c.y / c.w);
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  };
  if (all_in_slab) {
    for (const glm::dvec4& c : corner) add(c);
    for (const auto& e : kEdges) add(corner[e[0]] + (corner[e[1]] - corner[e[0]]));
  } else {
    // Vertices of box ∩ slab lie on box edges (corners inside, or an edge crossing a slab plane):
    // clip the 12 edges to 0 <= z <= w (Liang-Barsky in homogeneous space) and bound the ends.
    for (const auto& e : kEdges) {
      const glm::dvec4& a = corner[e[0]];
      const glm::dvec4& b = corner[e[1]];
      double t0 = 0.0, t1 = 1.0;
      bool inside = true;
      // Plane distances along the edge: near z, far w - z; both linear in t.
      const double da[2] = {a.z, a.w - a.z};
      const double db[2] = {b.z, b.w - b.z};
      for (int p = 0; p < 2 && inside; ++p) {
        if (da[p] < 0.0 && db[p] < 0.0) {
          inside = false;
        } else if (da[p] < 0.0) {
          t0 = std::max(t0, da[p] / (da[p] - db[p]));
        } else if (db[p] < 0.0) {
          t1 = std::min(t1, da[p] / (da[p] - db[p]));
        }
      }
      if (!inside || t0 > t1) continue;
      add(a + (b - a) * t0);
      add(a + (b - a) * t1);
    }
  }
  if (!out.in_slab) return;
  // Rounding to float is monotonic, so the float bounds are the rounded double bounds; rounding
  // could still shrink the rect by half an ulp: widen it by one ulp each way.
  out.rect_ndc.min = glm::vec2(next_down(float(lo.x)), next_down(float(lo.y)));
  out.rect_ndc.max = glm::vec2(next_up(float(hi.x)), next_up(float(hi.y)));
}

void corners_of(const glm::dmat4& view_proj, const glm::dvec3& box_min, const glm::dvec3& box_max,
                glm::dvec4 (&corner)[8]) {
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 p((i & 1) ? box_max.x : box_min.x, (i & 2) ? box_max.y : box_min.y,
                       (i & 4) ? box_max.z : box_min.z);
    corner[i] = view_proj * glm::dvec4(p, 1.0);
  }
}

// The region rect's four edges as planes through the eye, in world space, each pushed outward by
// kRejectMargin NDC (relative for |x| > 1): a box wholly outside one of them has every slab point
// project at least that far outside the rect, far beyond the float rounding and ulp widening of
// project_aabb (1e-7 relative) and the double error of either computation (1e-16 x the clip
// magnitudes over w >= near), so project_aabb's rect misses the region rect too.
constexpr double kRejectMargin = 1e-5;

struct RectPlanes {
  glm::dvec4 plane[4];  // inside: dot(plane, (p_world, 1)) >= 0
};

RectPlanes rect_planes(const glm::dmat4& view_proj, const NdcRect& r) {
  const glm::dmat4 rows = glm::transpose(view_proj);  // rows[k]: clip component k as a row on (p, 1)
  auto widened = [](double v, double dir) { return v + dir * kRejectMargin * std::max(1.0, std::abs(v)); };
  RectPlanes out;
  out.plane[0] = rows[0] - widened(r.min.x, -1.0) * rows[3];  // x >= min.x w
  out.plane[1] = widened(r.max.x, 1.0) * rows[3] - rows[0];   // x <= max.x w
  out.plane[2] = rows[1] - widened(r.min.y, -1.0) * rows[3];
  out.plane[3] = widened(r.max.y, 1.0) * rows[3] - rows[1];
  return out;
}

// Whether the box lies strictly outside one plane (its corner furthest inside is outside).
bool outside_a_plane(const RectPlanes& planes, const glm::dvec3& lo, const glm::dvec3& hi) {
  for (const glm::dvec4& pl : planes.plane) {
    const double d = pl.x * (pl.x >= 0.0 ? hi.x : lo.x) + pl.y * (pl.y >= 0.0 ? hi.y : lo.y) +
                     pl.z * (pl.z >= 0.0 ? hi.z : lo.z) + pl.w;
    if (d < 0.0) return true;
  }
  return false;
}

}  // namespace

ProjectedBox project_aabb(const glm::dmat4& view_proj, const glm::dvec3& eye_world, const glm::dvec3& box_min,
                          const glm::dvec3& box_max) {
  ProjectedBox out;
  if (box_min.x > box_max.x || box_min.y > box_max.y || box_min.z > box_max.z) return out;
  out.contains_eye =
      glm::all(glm::lessThanEqual(box_min, eye_world)) && glm::all(glm::lessThanEqual(eye_world, box_max));
  glm::dvec4 corner[8];
  corners_of(view_proj, box_min, box_max, corner);
  project_corners(corner, out);
  return out;
}

bool box_visible_in_region(const ProjectedBox& box, const ClipRegionView& region) {
  if (box.contains_eye) return true;
  return box.in_slab && region.overlaps(box.rect_ndc);
}

namespace {

// project_aabb + box_visible_in_region for one slot, in the order that skips the most work.
bool slot_visible(const glm::dvec3& lo, const glm::dvec3& hi, const glm::dmat4& view_proj, const glm::dvec3& eye_world,
                  const ClipRegionView& region, bool region_empty, const RectPlanes& planes) {
  if (lo.x > hi.x || lo.y > hi.y || lo.z > hi.z) return false;  // an empty box is never visible
  if (lo.x <= eye_world.x && lo.y <= eye_world.y && lo.z <= eye_world.z && eye_world.x <= hi.x && eye_world.y <= hi.y &&
      eye_world.z <= hi.z)
    return true;
  if (region_empty || outside_a_plane(planes, lo, hi)) return false;
  glm::dvec4 corner[8];
  corners_of(view_proj, lo, hi, corner);
  ProjectedBox box;
  project_corners(corner, box);
  return box.in_slab && region.overlaps(box.rect_ndc);
}

bool region_is_empty(const ClipRegionView& region) { return region.rect_ndc.empty() || region.polygons.empty(); }

RectPlanes planes_of(const glm::dmat4& view_proj, const ClipRegionView& region) {
  return rect_planes(view_proj, region_is_empty(region) ? NdcRect{glm::vec2(0.0f), glm::vec2(0.0f)} : region.rect_ndc);
}

}  // namespace

void cull_instances(const CullData& data, const glm::dmat4& view_proj, const glm::dvec3& eye_world,
                    VisibleSet& visible) {
  assert(data.cell_begin.size() == visible.slot_of_cell.size() + 1);
  const size_t first = visible.instances.size();
  const CullSlot* const slots = data.slots.data();
  // The visible cells' slots, asked for together (prefetch.h): their offsets first, then the
  // slots themselves, so that a build after a rendered frame waits for memory about twice, not
  // once per cell.
  for (const VisibleCell& vc : visible.cells) detail::prefetch_read(&data.cell_begin[vc.cell], 2 * sizeof(uint32_t));
  for (const VisibleCell& vc : visible.cells) {
    const uint32_t begin = data.cell_begin[vc.cell], end = data.cell_begin[vc.cell + 1];
    detail::prefetch_read(slots + begin, size_t(end - begin) * sizeof(CullSlot));
  }
  for (const VisibleCell& vc : visible.cells) {
    const ClipRegionView region = visible.region(vc);
    const bool region_empty = region_is_empty(region);
    const RectPlanes planes = planes_of(view_proj, region);
    const uint32_t end = data.cell_begin[vc.cell + 1];
    visible.stats.instances_tested += end - data.cell_begin[vc.cell];
    for (uint32_t s = data.cell_begin[vc.cell]; s < end; ++s) {
      const CullSlot& slot = slots[s];
      if (slot_visible(glm::dvec3(slot.min), glm::dvec3(slot.max), view_proj, eye_world, region, region_empty, planes))
        visible.instances.push_back(slot.instance);
    }
  }
  // Movers: the same test against the region of each visible cell they reach.
  for (const CullSlot& slot : data.movers) {
    const int32_t at = visible.slot_of_cell[slot.cell];
    if (at < 0) continue;
    ++visible.stats.instances_tested;
    const ClipRegionView region = visible.region(visible.cells[size_t(at)]);
    if (slot_visible(glm::dvec3(slot.min), glm::dvec3(slot.max), view_proj, eye_world, region, region_is_empty(region),
                     planes_of(view_proj, region)))
      visible.instances.push_back(slot.instance);
  }
  // An instance reaching several visible cells is listed once.
  std::sort(visible.instances.begin() + std::ptrdiff_t(first), visible.instances.end());
  visible.instances.erase(std::unique(visible.instances.begin() + std::ptrdiff_t(first), visible.instances.end()),
                          visible.instances.end());
}

void cull_linked_instances(const CullData& data, const glm::dmat4& view_proj, const glm::dvec3& eye_world,
                           VisibleSet& visible) {
  const size_t first = visible.linked_instances.size();
  uint32_t current = std::numeric_limits<uint32_t>::max();
  glm::dmat4 vp(1.0);
  glm::dvec3 eye(0.0);
  for (const VisibleCell& vc : visible.linked_cells) {
    assert(vc.transform >= 1 && vc.transform < visible.transforms.size());
    if (vc.transform != current) {  // entries are grouped by transform
      current = vc.transform;
      const glm::dmat4& m = visible.transforms[vc.transform].seen_from_world;
      vp = view_proj * m;
      eye = glm::dvec3(glm::inverse(m) * glm::dvec4(eye_world, 1.0));
    }
    const ClipRegionView region = visible.region(vc);
    const bool region_empty = region_is_empty(region);
    const RectPlanes planes = planes_of(vp, region);
    const uint32_t end = data.cell_begin[vc.cell + 1];
    visible.stats.instances_tested += end - data.cell_begin[vc.cell];
    for (uint32_t s = data.cell_begin[vc.cell]; s < end; ++s) {
      const CullSlot& slot = data.slots[s];
      if (slot_visible(glm::dvec3(slot.min), glm::dvec3(slot.max), vp, eye, region, region_empty, planes))
        visible.linked_instances.push_back({vc.transform, slot.instance});
    }
    for (const CullSlot& slot : data.movers) {
      if (slot.cell != vc.cell) continue;
      ++visible.stats.instances_tested;
      if (slot_visible(glm::dvec3(slot.min), glm::dvec3(slot.max), vp, eye, region, region_empty, planes))
        visible.linked_instances.push_back({vc.transform, slot.instance});
    }
  }
  auto less = [](const LinkedInstance& a, const LinkedInstance& b) {
    return a.transform != b.transform ? a.transform < b.transform : a.instance < b.instance;
  };
  std::sort(visible.linked_instances.begin() + std::ptrdiff_t(first), visible.linked_instances.end(), less);
  visible.linked_instances.erase(
      std::unique(visible.linked_instances.begin() + std::ptrdiff_t(first), visible.linked_instances.end()),
      visible.linked_instances.end());
}

}  // namespace lintel
