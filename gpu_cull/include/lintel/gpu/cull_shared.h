// The one header shared by C++ and GLSL (niagara's habit): the structs the cull pass reads and
// writes on the GPU, its push constants and its limits. Layouts are std430 in GLSL; the C++ side
// asserts every size and offset so a reordered field fails to compile instead of culling garbage.
// Each limit says what it costs in memory. docs/gpu_cull.md describes the pass.
#ifndef LINTEL_GPU_CULL_SHARED_H
#define LINTEL_GPU_CULL_SHARED_H

#ifdef __cplusplus
#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
namespace lintel::gpu {
using uint = uint32_t;
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using mat4 = glm::mat4;
#define LINTEL_GPU_LIMIT(name, value) inline constexpr uint32_t name = value
#else
#define LINTEL_GPU_LIMIT(name, value) const uint name = value
#endif

// ---- limits -------------------------------------------------------------------------------------

// Threads per cull workgroup: a multiple of every subgroup size we meet (8 on lavapipe, 32 and
// 64 on GPUs). The shaders' local_size_x.
LINTEL_GPU_LIMIT(kCullWorkgroupSize, 64u);
// Threads per finalize workgroup (one thread per draw group).
LINTEL_GPU_LIMIT(kFinalizeWorkgroupSize, 64u);
// Instances one cull dispatch may test. The pass dispatches only work items of visible cells;
// a dispatch runs the items of one 32 MiB window of the cell-ordered instance buffer (a window's
// items cover disjoint positions), so no dispatch runs long enough to hit an OS GPU timeout: 2^20
// instances, each at most 8 corner transforms + kMaxRegionPolygons x (kMaxPolygonVertices + 1)
// separating-axis tests.
LINTEL_GPU_LIMIT(kMaxInstancesPerDispatch, 1u << 20);
// Work items (workgroups) one cull dispatch may run: 16384 < the 65535 every device has (a window
// with more items, possible when many small cells share it, takes several dispatches).
LINTEL_GPU_LIMIT(kMaxWorkPerDispatch, kMaxInstancesPerDispatch / kCullWorkgroupSize);
// GpuCullWork::cell of an item whose instances are each tested by their own cell or reach list
// (instances reaching several cells, empty ones): the "loose" segment after the cells' ranges.
LINTEL_GPU_LIMIT(kLooseWork, 0xffffffffu);
// Instances that update_instances moved out of the cell whose range holds them (entries of the
// per-frame moved list, 8 B each): 512 KiB per frame slot. Over it, update_instances returns
// Unsupported and the caller calls set_scene, which sorts them into their new cells.
LINTEL_GPU_LIMIT(kMaxMovedInstances, 1u << 16);
// Instances in one scene: instance buffer 32 B each = 512 MiB, id buffer 4 B each = 64 MiB.
LINTEL_GPU_LIMIT(kMaxInstances, 1u << 24);
// Draw groups: 20 B group + 20 B command + 20 B compacted command + 4 B compacted group id + 4 B
// counter = 68 B each, 4.25 MiB at the limit.
LINTEL_GPU_LIMIT(kMaxDrawGroups, 1u << 16);
// Cells: 4 B cell->region entry + at most one 32 B region each = 2.25 MiB at the limit.
LINTEL_GPU_LIMIT(kMaxCells, 1u << 16);
// Convex polygons per visible cell's region: lintel::kMaxRegionPolygonsLimit, the most any
// VisibilityOptions::max_region_polygons can ask for (asserted in cull_data.cpp), so a VisibleSet
// always fits. A hand-made region with more is uploaded as its rect alone (conservative: the rect
// bounds every polygon). 32 B + kMaxPolygonVertices x 8 B = 288 B per polygon, 4.5 KiB per
// region at worst; region buffers grow to what a frame uses.
LINTEL_GPU_LIMIT(kMaxRegionPolygons, 16u);
// Vertices per region polygon: lintel::kMaxRegionPolygonVertices (asserted likewise). A region
// with a larger polygon is uploaded as its rect alone.
LINTEL_GPU_LIMIT(kMaxPolygonVertices, 32u);
// cell_region entry of a cell that is not visible this frame.
LINTEL_GPU_LIMIT(kNoRegion, 0xffffffffu);
// GpuInstance::cell with this bit set (and not kNoRegion): the instance's bounds reach several
// cells (lintel::InstanceReach); the low 31 bits are the offset in the reach buffer of its list
// {count, cell, cell, ...}, its own cell first. Scene memory: 4 B x (count + 1) per such instance.
LINTEL_GPU_LIMIT(kReachListBit, 0x80000000u);
// Cells one instance may reach (a reach list's count): bounds the shader's loop over them. Over
// it, pack_scene refuses the scene (Unsupported) rather than drop cells.
LINTEL_GPU_LIMIT(kMaxReachCells, 1024u);

// ---- per scene ------------------------------------------------------------------------------------

// One object to cull: World::instances[i].bounds_world (the mesh's real extent transformed, the
// same box the CPU reference tests), the cell it sits in (or, with kReachListBit, its reach list)
// and its draw group.
struct GpuInstance {
  vec3 bounds_min_world;
  uint cell;
  vec3 bounds_max_world;
  uint group;
};

// One draw group (one mesh): where its geometry lies in the index/vertex buffers, and where its
// surviving instance ids go: ids[base .. base + capacity). Bases of different groups never
// overlap; base becomes the command's firstInstance.
struct GpuDrawGroup {
  uint index_count;
  uint first_index;
  int vertex_offset;
  uint base;
  uint capacity;
};

// VkDrawIndexedIndirectCommand, field for field (20 B, tightly packed in the command buffers).
struct DrawIndexedCommand {
  uint index_count;
  uint instance_count;
  uint first_index;
  int vertex_offset;
  uint first_instance;
};

// ---- per frame ------------------------------------------------------------------------------------

// A visible cell's clip region in NDC: its rect, and when polygon_count > 0 the union of that
// many convex polygons (all inside the rect). polygon_count == 0: the rect alone.
struct GpuRegion {
  vec4 rect_ndc;  // min x, min y, max x, max y
  uint first_polygon;
  uint polygon_count;
  uint pad0;
  uint pad1;
};

// A convex polygon: vertex_count NDC vertices from first_vertex in the vertex pool (vec2 each),
// counter-clockwise, and their bounds (one of the separating axes, computed once on the CPU).
struct GpuPolygon {
  vec4 bounds_ndc;  // min x, min y, max x, max y
  uint first_vertex;
  uint vertex_count;
  uint pad0;
  uint pad1;
};

// One workgroup's share of the cull: `count` (<= kCullWorkgroupSize) consecutive instances from
// `first` (relative to the dispatch's window of the cell-ordered instance buffer), all from the
// range of `cell`, whose clip region is `region`: one region per workgroup. With cell ==
// kLooseWork, each instance is tested by its own cell or reach list (region unused). Built on the
// CPU from the frame's visible cells (CullPass::set_frame), so invisible cells cost nothing.
struct GpuCullWork {
  uint first;
  uint count;
  uint cell;
  uint region;
};

// The header of the straddler list (CullPassOptions::defer_straddlers): its first three words are
// the VkDispatchIndirectCommand that tests it (one workgroup per kCullWorkgroupSize entries),
// then the entry count. record() resets it to {0, 1, 1, 0} before each cell dispatch.
struct GpuStraddleHeader {
  uint dispatch_x;
  uint dispatch_y;
  uint dispatch_z;
  uint count;
};

// Written by the pass, read back by tests and the CPU side; at offset 0 of the counter buffer so
// that draw_count can feed vkCmdDrawIndexedIndirectCount. Per-group counters follow it.
struct GpuCullStats {
  uint draw_count;          // commands in the compacted list (groups with >= 1 instance)
  uint visible_instances;   // instances drawn, after clamping to capacity
  uint overflow_instances;  // survivors dropped because their group was full (must stay 0)
  uint overflow_groups;     // groups that overflowed
};

// Push constants of both compute shaders (all 128 B that every device offers).
// The camera is eye-relative: clip = view_proj_rel * (p_world - eye_world, 1), the same value as
// view_projection(view) * (p_world, 1) but without float cancelling two large terms when the
// building is far from the origin (the CPU reference works in double and does not need this).
struct GpuCullConstants {
  mat4 view_proj_rel;  // columns 0-2: view_projection's; column 3: view_projection_d(view) * (eye, 1)
  // Distance to the far plane in clip units, w - z, as a row on (p_world - eye_world, 1), taken
  // from rows 3 - 2 of the double matrix: as w - z in float it would cancel catastrophically (both
  // are ~ far, their difference ~ near x depth-to-far / far: float loses millimeters there).
  vec4 far_row_rel;
  vec4 eye_world;   // xyz: the eye (a box containing it is visible wherever its cell is); w: 0
  uint work_first;  // this dispatch's first work item (kWorkItems) or moved-list entry (kWorkMoved)
  uint work_count;  // work items (workgroups) or moved entries (threads) in this dispatch
  uint group_count;
  uint cell_count;
  uint window_first;  // the dispatch's window: position of its first instance in the cell-ordered buffer
  uint work_kind;     // kWorkItems or kWorkMoved
  uint pad0;
  uint pad1;
};
// GpuCullConstants::work_kind: GpuCullWork items, one per workgroup; or the moved list, one entry
// {position in the window, home cell} per thread (an instance whose record now names another
// cell than the range holding it: tested by its own cell, skipped by its home range's items).
LINTEL_GPU_LIMIT(kWorkItems, 0u);
LINTEL_GPU_LIMIT(kWorkMoved, 1u);
// GpuCullConstants::work_kind of the loose range's items (each instance tested by its own cell or
// reach list; dispatched with the own-region pipeline, like the moved list).
LINTEL_GPU_LIMIT(kWorkLoose, 2u);
// How cull.comp's survivors take their slots in their group's id range (specialization constant
// 2): one atomicAdd each; one per group per subgroup (ballot); one per group per workgroup (shared
// memory: global atomics only as many as distinct groups among a workgroup's survivors).
LINTEL_GPU_LIMIT(kAppendAtomic, 0u);
LINTEL_GPU_LIMIT(kAppendSubgroup, 1u);
LINTEL_GPU_LIMIT(kAppendWorkgroup, 2u);

#ifdef __cplusplus
static_assert(sizeof(GpuInstance) == 32 && offsetof(GpuInstance, cell) == 12 &&
              offsetof(GpuInstance, bounds_max_world) == 16 && offsetof(GpuInstance, group) == 28);
static_assert(sizeof(GpuDrawGroup) == 20 && offsetof(GpuDrawGroup, base) == 12 &&
              offsetof(GpuDrawGroup, capacity) == 16);
static_assert(sizeof(DrawIndexedCommand) == 20 && offsetof(DrawIndexedCommand, instance_count) == 4 &&
              offsetof(DrawIndexedCommand, first_instance) == 16);
static_assert(sizeof(GpuRegion) == 32 && offsetof(GpuRegion, first_polygon) == 16 &&
              offsetof(GpuRegion, polygon_count) == 20);
static_assert(sizeof(GpuPolygon) == 32 && offsetof(GpuPolygon, first_vertex) == 16 &&
              offsetof(GpuPolygon, vertex_count) == 20);
static_assert(sizeof(GpuCullStats) == 16 && offsetof(GpuCullStats, draw_count) == 0);
static_assert(sizeof(GpuStraddleHeader) == 16 && offsetof(GpuStraddleHeader, count) == 12);
static_assert(sizeof(GpuCullWork) == 16 && offsetof(GpuCullWork, cell) == 8);
static_assert(sizeof(GpuCullConstants) == 128 && offsetof(GpuCullConstants, far_row_rel) == 64 &&
              offsetof(GpuCullConstants, eye_world) == 80 && offsetof(GpuCullConstants, work_first) == 96 &&
              offsetof(GpuCullConstants, cell_count) == 108 && offsetof(GpuCullConstants, work_kind) == 116);
static_assert(kMaxInstancesPerDispatch % kCullWorkgroupSize == 0);
static_assert(kMaxInstances % kMaxInstancesPerDispatch == 0);
}  // namespace lintel::gpu
#endif

#undef LINTEL_GPU_LIMIT
#endif  // LINTEL_GPU_CULL_SHARED_H
