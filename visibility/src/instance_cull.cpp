// Instance culling against portal clip regions, over structure-of-arrays bounds.
// Learns from: filament's Culler (SoA batches, conservative box tests) and the Lintel lessons
// (cull bounds from the real mesh extent; a unit box culls identity-transform meshes whose extent
// is baked into their vertices). The near-plane handling mirrors portal_clip.cpp: clip the box's
// edges in homogeneous space before the divide, so a box around or beside the eye keeps a finite,
// faithful screen rect.
#include <lintel/instance_cull.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace lintel {

void CullData::prepare(const World& world) {
  const size_t cells = world.cells.size();
  const size_t n = world.instances.size();
  cell_begin.assign(cells + 1, 0);
  for (const Instance& inst : world.instances) {
    assert(inst.cell < cells);
    ++cell_begin[inst.cell + 1];
  }
  for (size_t c = 0; c < cells; ++c) cell_begin[c + 1] += cell_begin[c];
  for (auto* v : {&min_x, &min_y, &min_z, &max_x, &max_y, &max_z}) v->assign(n, 0.0f);
  instance.assign(n, 0);
  std::vector<uint32_t> next(cell_begin.begin(), cell_begin.end() - 1);
  for (uint32_t i = 0; i < n; ++i) {  // ascending i: each cell's slots stay sorted by instance
    const Instance& inst = world.instances[i];
    const uint32_t slot = next[inst.cell]++;
    min_x[slot] = inst.bounds_world.min.x;
    min_y[slot] = inst.bounds_world.min.y;
    min_z[slot] = inst.bounds_world.min.z;
    max_x[slot] = inst.bounds_world.max.x;
    max_y[slot] = inst.bounds_world.max.y;
    max_z[slot] = inst.bounds_world.max.z;
    instance[slot] = i;
  }
}

ProjectedBox project_aabb(const glm::dmat4& view_proj, const glm::dvec3& eye_world, const glm::dvec3& box_min,
                          const glm::dvec3& box_max) {
  ProjectedBox out;
  if (box_min.x > box_max.x || box_min.y > box_max.y || box_min.z > box_max.z) return out;
  out.contains_eye = glm::all(glm::lessThanEqual(box_min, eye_world)) && glm::all(glm::lessThanEqual(eye_world, box_max));
  glm::dvec4 corner[8];
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 p((i & 1) ? box_max.x : box_min.x, (i & 2) ? box_max.y : box_min.y,
                       (i & 4) ? box_max.z : box_min.z);
    corner[i] = view_proj * glm::dvec4(p, 1.0);
  }
  // Vertices of box ∩ slab lie on box edges (corners inside, or an edge crossing a slab plane):
  // clip the 12 edges to 0 <= z <= w (Liang-Barsky in homogeneous space) and bound the ends.
  static constexpr int kEdges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                        {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
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
    for (const double t : {t0, t1}) {
      const glm::dvec4 c = a + (b - a) * t;
      // On the slab w >= near > 0; guard the division against rounding at w ~ 0 anyway.
      if (!(c.w > 0.0)) continue;
      out.in_slab = true;
      out.rect_ndc.extend(glm::vec2(float(c.x / c.w), float(c.y / c.w)));
    }
  }
  // Rounding to float could shrink the rect by half an ulp: widen it by one ulp each way.
  if (out.in_slab) {
    constexpr float kInf = std::numeric_limits<float>::infinity();
    NdcRect& r = out.rect_ndc;
    r.min = glm::vec2(std::nextafter(r.min.x, -kInf), std::nextafter(r.min.y, -kInf));
    r.max = glm::vec2(std::nextafter(r.max.x, kInf), std::nextafter(r.max.y, kInf));
  }
  return out;
}

bool box_visible_in_region(const ProjectedBox& box, const ClipRegionView& region) {
  if (box.contains_eye) return true;
  return box.in_slab && region.overlaps(box.rect_ndc);
}

void cull_instances(const CullData& data, const glm::dmat4& view_proj, const glm::dvec3& eye_world,
                    VisibleSet& visible) {
  assert(data.cell_begin.size() == visible.slot_of_cell.size() + 1);
  const size_t first = visible.instances.size();
  for (const VisibleCell& vc : visible.cells) {
    const ClipRegionView region = visible.region(vc);
    for (uint32_t s = data.cell_begin[vc.cell]; s < data.cell_begin[vc.cell + 1]; ++s) {
      ++visible.stats.instances_tested;
      const ProjectedBox box =
          project_aabb(view_proj, eye_world, {data.min_x[s], data.min_y[s], data.min_z[s]},
                       {data.max_x[s], data.max_y[s], data.max_z[s]});
      if (box_visible_in_region(box, region)) visible.instances.push_back(data.instance[s]);
    }
  }
  std::sort(visible.instances.begin() + std::ptrdiff_t(first), visible.instances.end());
}

}  // namespace lintel
