// What the cull pass uploads, packed on the CPU in the GPU layout of cull_shared.h: the scene
// (instances and draw groups, once per World) and the frame (camera and per-cell clip regions).
#pragma once

#include <lintel/clip_region.h>
#include <lintel/gpu/cull_shared.h>
#include <lintel/status.h>
#include <lintel/view.h>
#include <lintel/visible_set.h>
#include <lintel/world.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace lintel::gpu {

// Where a mesh's triangles lie in the renderer's shared index/vertex buffers.
struct MeshRange {
  uint32_t index_count = 0;
  uint32_t first_index = 0;
  int32_t vertex_offset = 0;
};

// Meshes concatenated in World order (indices, then positions): the layout pack_scene assumes when
// the renderer gives no ranges of its own, and the one the raster test builds its buffers with.
std::vector<MeshRange> concatenated_mesh_ranges(const World& world);

struct CullScene {
  std::vector<GpuInstance> instances;  // [i] is World::instances[i]; its id in the output is i
  std::vector<GpuDrawGroup> groups;    // [g] is World::groups[g]
  // Reach lists {count, own cell, other cells ascending} of the instances whose bounds reach
  // several cells (lintel::InstanceReach); their GpuInstance::cell is kReachListBit | offset.
  std::vector<uint32_t> reach;
  uint32_t cell_count = 0;
  uint32_t id_capacity = 0;  // sum of group capacities: the id buffer's length
};

// Packs `world` for the GPU: each instance's bounds_world (the mesh's real extent transformed,
// the box the CPU reference tests), its cell and group; each group's geometry from
// `mesh_ranges` (indexed by mesh; empty: concatenated_mesh_ranges(world)) and its id range,
// base = sum of the capacities before it, capacity = its instance count. An instance with empty
// bounds is packed with cell = kNoRegion and never drawn; one whose bounds reach several cells
// through portals (instance_reach.h) gets a reach list, so it is drawn once when any of them
// passes, as the CPU reference lists it.
// Errors: counts over kMaxInstances/kMaxDrawGroups/kMaxCells, an instance whose group does not
// list it, a mesh index without a range; Unsupported: an instance reaching over kMaxReachCells.
Status pack_scene(const World& world, std::span<const MeshRange> mesh_ranges, CullScene& out);

// One frame: the camera and the clip region of every visible cell. Reused across frames (clear()
// keeps capacity), so packing does not allocate after warm-up.
struct CullFrame {
  // The camera, eye-relative (GpuCullConstants): set by clear() from the double matrix.
  glm::mat4 view_proj_rel{1.0f};
  glm::vec4 far_row_rel{0.0f, 0.0f, -1.0f, 1.0f};
  glm::vec3 eye_world{0.0f};
  std::vector<uint32_t> cell_region;  // per cell: index into regions, or kNoRegion
  std::vector<GpuRegion> regions;
  std::vector<GpuPolygon> polygons;
  std::vector<glm::vec2> vertices_ndc;
  // Per vertex, the line of the polygon edge from it to the next one, (nx, ny, c, 0): inside
  // (left of a counter-clockwise edge) where nx x + ny y + c > 0. Taken in double from the
  // vertices, so the shader tests an edge with one fused multiply-add pair; what the GPU reads.
  std::vector<glm::vec4> edges_ndc;
  // Regions uploaded as their rect alone because they had more than kMaxRegionPolygons polygons
  // or a polygon with more than kMaxPolygonVertices vertices (conservative: more is drawn).
  uint32_t rect_fallbacks = 0;

  // Starts a frame for a scene of `cell_count` cells, none visible, seen through `world_to_clip`
  // (view_projection_d(view): the double matrix, so the far row is exact before its rounding).
  void clear(uint32_t cell_count, const glm::dmat4& world_to_clip, const glm::vec3& eye = glm::vec3(0.0f));
  // Makes `cell` visible with region `rect_ndc` (min x, min y, max x, max y) and `polygons_ndc`
  // (convex, counter-clockwise, inside the rect; may be empty: the rect alone). Over the limits,
  // the rect alone (counted in rect_fallbacks). Precondition: cell < cell_count, not yet added.
  void add_region(uint32_t cell, const glm::vec4& rect_ndc, std::span<const std::vector<glm::vec2>> polygons_ndc);
  // The same for a VisibleSet's region (which always fits: the limits are the visibility core's).
  void add_region(uint32_t cell, const ClipRegionView& region);
  // Whether a region with these polygons fits the GPU limits (else it falls back to its rect).
  static bool fits_limits(std::span<const std::vector<glm::vec2>> polygons_ndc);

 private:
  void push_polygon(std::span<const glm::vec2> poly_ndc);
};

// The frame of a visibility query: every visible cell of `visible` (built from `view`) with its
// region, for a scene of `cell_count` cells. Precondition: validate_view(view).ok().
void pack_visible_set(const VisibleSet& visible, const View& view, uint32_t cell_count, CullFrame& out);

}  // namespace lintel::gpu
