// Packing a World and a frame's clip regions into the GPU layout (cull_shared.h), with the
// limits checked here, on the CPU, so the shaders never see an index they must distrust.
#include <lintel/gpu/cull_data.h>

#include <lintel/instance_reach.h>

#include <cassert>
#include <limits>
#include <string>

namespace lintel::gpu {

std::vector<MeshRange> concatenated_mesh_ranges(const World& world) {
  std::vector<MeshRange> ranges(world.meshes.size());
  uint32_t first_index = 0;
  int32_t vertex_offset = 0;
  for (size_t m = 0; m < world.meshes.size(); ++m) {
    ranges[m] = {uint32_t(world.meshes[m].indices.size()), first_index, vertex_offset};
    first_index += uint32_t(world.meshes[m].indices.size());
    vertex_offset += int32_t(world.meshes[m].positions.size());
  }
  return ranges;
}

Status pack_scene(const World& world, std::span<const MeshRange> mesh_ranges, CullScene& out) {
  out = CullScene{};
  const std::string where = world.source.empty() ? std::string("scene") : world.source;
  if (world.instances.size() > kMaxInstances)
    return Status::error(where + ": " + std::to_string(world.instances.size()) +
                         " instances exceed the GPU cull's limit of " + std::to_string(kMaxInstances));
  if (world.groups.size() > kMaxDrawGroups)
    return Status::error(where + ": " + std::to_string(world.groups.size()) +
                         " draw groups exceed the GPU cull's limit of " + std::to_string(kMaxDrawGroups));
  if (world.cells.size() > kMaxCells)
    return Status::error(where + ": " + std::to_string(world.cells.size()) + " cells exceed the GPU cull's limit of " +
                         std::to_string(kMaxCells));
  std::vector<MeshRange> own_ranges;
  if (mesh_ranges.empty()) {
    own_ranges = concatenated_mesh_ranges(world);
    mesh_ranges = own_ranges;
  }

  out.cell_count = uint32_t(world.cells.size());
  out.groups.resize(world.groups.size());
  uint32_t base = 0;
  for (size_t g = 0; g < world.groups.size(); ++g) {
    const DrawGroup& group = world.groups[g];
    if (group.mesh >= mesh_ranges.size())
      return Status::error(where + ": draw group " + std::to_string(g) + " uses mesh " + std::to_string(group.mesh) +
                           ", which has no index range");
    const MeshRange& range = mesh_ranges[group.mesh];
    const uint32_t capacity = uint32_t(group.instances.size());
    out.groups[g] = {range.index_count, range.first_index, range.vertex_offset, base, capacity};
    base += capacity;
    for (uint32_t i : group.instances)
      if (i >= world.instances.size() || world.instances[i].group != g)
        return Status::error(where + ": draw group " + std::to_string(g) + " lists instance " + std::to_string(i) +
                             ", which does not belong to it");
  }
  out.id_capacity = base;

  InstanceReach reach;
  reach.compute(world);
  out.instances.resize(world.instances.size());
  std::vector<uint32_t> per_group(world.groups.size(), 0);
  for (size_t i = 0; i < world.instances.size(); ++i) {
    const Instance& inst = world.instances[i];
    if (inst.group >= world.groups.size() || inst.cell >= world.cells.size())
      return Status::error(where + ": instance " + std::to_string(i) + " '" + inst.name + "' has group " +
                           std::to_string(inst.group) + " / cell " + std::to_string(inst.cell) + " out of range");
    if (++per_group[inst.group] > out.groups[inst.group].capacity)
      return Status::error(where + ": instance " + std::to_string(i) + " '" + inst.name +
                           "' is not listed by its draw group " + std::to_string(inst.group));
    GpuInstance& gi = out.instances[i];
    const bool empty = inst.bounds_world.empty();
    gi.bounds_min_world = empty ? glm::vec3(0.0f) : inst.bounds_world.min;
    gi.bounds_max_world = empty ? glm::vec3(0.0f) : inst.bounds_world.max;
    gi.cell = empty ? kNoRegion : inst.cell;
    gi.group = inst.group;
    const uint32_t reached = reach.count(uint32_t(i));
    if (empty || reached == 1) continue;
    if (reached > kMaxReachCells)
      return Status::unsupported(where + ": instance " + std::to_string(i) + " '" + inst.name + "' reaches " +
                                 std::to_string(reached) + " cells, over the GPU cull's limit of " +
                                 std::to_string(kMaxReachCells));
    if (out.reach.size() + reached + 1 >= kReachListBit)
      return Status::unsupported(where + ": reach lists exceed the GPU cull's limit of " +
                                 std::to_string(kReachListBit - 1) + " entries");
    gi.cell = kReachListBit | uint32_t(out.reach.size());
    out.reach.push_back(reached);
    out.reach.insert(out.reach.end(), reach.begin(uint32_t(i)), reach.end(uint32_t(i)));
  }
  return {};
}

void CullFrame::clear(uint32_t cell_count, const glm::dmat4& world_to_clip, const glm::vec3& eye) {
  const glm::dvec4 eye_h(glm::dvec3(eye), 1.0);
  glm::dmat4 rel = world_to_clip;
  rel[3] = world_to_clip * eye_h;  // the translation, folded in double around the eye
  view_proj_rel = glm::mat4(rel);
  const glm::dmat4 rows = glm::transpose(world_to_clip);
  const glm::dvec4 far_row = rows[3] - rows[2];
  far_row_rel = glm::vec4(glm::dvec3(far_row), glm::dot(far_row, eye_h));
  eye_world = eye;
  cell_region.assign(cell_count, kNoRegion);
  regions.clear();
  polygons.clear();
  vertices_ndc.clear();
  edges_ndc.clear();
  rect_fallbacks = 0;
}

// The GPU holds every region the visibility core can produce, so a VisibleSet never falls back.
static_assert(kMaxRegionPolygons >= kMaxRegionPolygonsLimit);
static_assert(kMaxPolygonVertices >= kMaxRegionPolygonVertices);

bool CullFrame::fits_limits(std::span<const std::vector<glm::vec2>> polygons_ndc) {
  if (polygons_ndc.size() > kMaxRegionPolygons) return false;
  for (const std::vector<glm::vec2>& poly : polygons_ndc)
    if (poly.size() > kMaxPolygonVertices) return false;
  return true;
}

void CullFrame::push_polygon(std::span<const glm::vec2> poly_ndc) {
  // The same min/max as lintel::bounds_of, so the GPU's bounds axis is bit-identical to the CPU's.
  glm::vec2 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
  for (const glm::vec2& v : poly_ndc) {
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  polygons.push_back({glm::vec4(lo, hi), uint32_t(vertices_ndc.size()), uint32_t(poly_ndc.size()), 0, 0});
  vertices_ndc.insert(vertices_ndc.end(), poly_ndc.begin(), poly_ndc.end());
  // edge_side(a, b, p) = (b - a) x (p - a) = nx p.x + ny p.y + c, the same value in exact arithmetic.
  for (size_t i = 0; i < poly_ndc.size(); ++i) {
    const glm::dvec2 a(poly_ndc[i]), b(poly_ndc[i + 1 == poly_ndc.size() ? 0 : i + 1]);
    const double nx = -(b.y - a.y), ny = b.x - a.x;
    edges_ndc.emplace_back(float(nx), float(ny), float(-(nx * a.x + ny * a.y)), 0.0f);
  }
}

void CullFrame::add_region(uint32_t cell, const glm::vec4& rect_ndc,
                           std::span<const std::vector<glm::vec2>> polygons_ndc) {
  assert(cell < cell_region.size() && cell_region[cell] == kNoRegion);
  cell_region[cell] = uint32_t(regions.size());
  GpuRegion region{rect_ndc, uint32_t(polygons.size()), 0, 0, 0};
  if (!fits_limits(polygons_ndc)) {
    ++rect_fallbacks;
  } else {
    for (const std::vector<glm::vec2>& poly : polygons_ndc) push_polygon(poly);
    region.polygon_count = uint32_t(polygons_ndc.size());
  }
  regions.push_back(region);
}

void CullFrame::add_region(uint32_t cell, const ClipRegionView& region) {
  assert(cell < cell_region.size() && cell_region[cell] == kNoRegion);
  assert(region.polygons.size() <= kMaxRegionPolygons);
  cell_region[cell] = uint32_t(regions.size());
  regions.push_back({glm::vec4(region.rect_ndc.min, region.rect_ndc.max), uint32_t(polygons.size()),
                     uint32_t(region.polygons.size()), 0, 0});
  for (size_t i = 0; i < region.polygons.size(); ++i) {
    assert(region.polygons[i].vertex_count <= kMaxPolygonVertices);
    push_polygon(region.polygon(i));
  }
}

void pack_visible_set(const VisibleSet& visible, const View& view, uint32_t cell_count, CullFrame& out) {
  out.clear(cell_count, view_projection_d(view), view.eye_world);
  for (const VisibleCell& c : visible.cells) out.add_region(c.cell, visible.region(c));
}

}  // namespace lintel::gpu
