// The checks of what the cull pass is handed (scene, frame, updated instances) before any of it
// reaches the GPU: the shaders trust these bounds, so every index is proven in range here.
#include "cull_pass_internal.h"

#include <utility>
#include <vector>

namespace lintel::gpu::detail {

namespace {

Status check_reach(const CullScene& scene, size_t i) {
  const uint32_t cell = scene.instances[i].cell;
  if (cell == kNoRegion || !(cell & kReachListBit)) return {};
  const uint64_t at = cell & ~kReachListBit;
  if (at >= scene.reach.size() || scene.reach[at] > kMaxReachCells || at + 1 + scene.reach[at] > scene.reach.size())
    return Status::error("GPU cull: instance " + std::to_string(i) + " has reach list " + std::to_string(at) +
                         " outside the " + std::to_string(scene.reach.size()) +
                         " reach entries or over kMaxReachCells");
  return {};
}

}  // namespace

Status check_scene(const CullScene& scene) {
  if (scene.instances.size() > kMaxInstances)
    return Status::error("GPU cull: " + std::to_string(scene.instances.size()) + " instances exceed kMaxInstances (" +
                         std::to_string(kMaxInstances) + ")");
  if (scene.groups.size() > kMaxDrawGroups)
    return Status::error("GPU cull: " + std::to_string(scene.groups.size()) + " draw groups exceed kMaxDrawGroups (" +
                         std::to_string(kMaxDrawGroups) + ")");
  if (scene.cell_count > kMaxCells)
    return Status::error("GPU cull: " + std::to_string(scene.cell_count) + " cells exceed kMaxCells (" +
                         std::to_string(kMaxCells) + ")");
  // Id ranges inside the id buffer and disjoint, so no group can write into another's.
  std::vector<std::pair<uint32_t, uint32_t>> ranges;
  for (size_t g = 0; g < scene.groups.size(); ++g) {
    const GpuDrawGroup& group = scene.groups[g];
    if (uint64_t(group.base) + group.capacity > scene.id_capacity)
      return Status::error("GPU cull: draw group " + std::to_string(g) + " ids [" + std::to_string(group.base) + ", +" +
                           std::to_string(group.capacity) + ") exceed the id buffer (" +
                           std::to_string(scene.id_capacity) + ")");
    if (group.capacity) ranges.emplace_back(group.base, group.capacity);
  }
  std::sort(ranges.begin(), ranges.end());
  for (size_t i = 1; i < ranges.size(); ++i)
    if (ranges[i - 1].first + ranges[i - 1].second > ranges[i].first)
      return Status::error("GPU cull: draw groups' id ranges overlap at id " + std::to_string(ranges[i].first));
  for (size_t i = 0; i < scene.instances.size(); ++i)
    if (scene.instances[i].group >= scene.groups.size())
      return Status::error("GPU cull: instance " + std::to_string(i) + " has draw group " +
                           std::to_string(scene.instances[i].group) + " of " + std::to_string(scene.groups.size()));
  // Reach lists inside the reach buffer, within kMaxReachCells, so the shader never reads past it.
  for (size_t i = 0; i < scene.instances.size(); ++i)
    if (Status s = check_reach(scene, i); !s) return s;
  return {};
}

Status check_frame(const CullFrame& frame, uint32_t cell_count) {
  if (frame.cell_region.size() != cell_count)
    return Status::error("GPU cull: frame has " + std::to_string(frame.cell_region.size()) + " cells, the scene " +
                         std::to_string(cell_count));
  for (size_t c = 0; c < frame.cell_region.size(); ++c)
    if (frame.cell_region[c] != kNoRegion && frame.cell_region[c] >= frame.regions.size())
      return Status::error("GPU cull: cell " + std::to_string(c) + " has region " +
                           std::to_string(frame.cell_region[c]) + " of " + std::to_string(frame.regions.size()));
  for (size_t r = 0; r < frame.regions.size(); ++r) {
    const GpuRegion& region = frame.regions[r];
    if (region.polygon_count > kMaxRegionPolygons ||
        uint64_t(region.first_polygon) + region.polygon_count > frame.polygons.size())
      return Status::error("GPU cull: region " + std::to_string(r) + " has polygons [" +
                           std::to_string(region.first_polygon) + ", +" + std::to_string(region.polygon_count) +
                           ") of " + std::to_string(frame.polygons.size()) +
                           " (limit kMaxRegionPolygons = " + std::to_string(kMaxRegionPolygons) + ")");
  }
  if (frame.edges_ndc.size() != frame.vertices_ndc.size())
    return Status::error("GPU cull: frame has " + std::to_string(frame.edges_ndc.size()) + " polygon edges for " +
                         std::to_string(frame.vertices_ndc.size()) + " vertices");
  for (size_t p = 0; p < frame.polygons.size(); ++p) {
    const GpuPolygon& poly = frame.polygons[p];
    if (poly.vertex_count > kMaxPolygonVertices ||
        uint64_t(poly.first_vertex) + poly.vertex_count > frame.vertices_ndc.size())
      return Status::error("GPU cull: polygon " + std::to_string(p) + " has vertices [" +
                           std::to_string(poly.first_vertex) + ", +" + std::to_string(poly.vertex_count) + ") of " +
                           std::to_string(frame.vertices_ndc.size()) +
                           " (limit kMaxPolygonVertices = " + std::to_string(kMaxPolygonVertices) + ")");
  }
  return {};
}

Status check_instance(const CullScene& scene, size_t i, uint32_t group_count) {
  if (scene.instances[i].group >= group_count)
    return Status::error("GPU cull: instance " + std::to_string(i) + " has draw group " +
                         std::to_string(scene.instances[i].group) + " of " + std::to_string(group_count));
  return check_reach(scene, i);
}

}  // namespace lintel::gpu::detail
