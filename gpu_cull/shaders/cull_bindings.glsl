// Descriptor set 0 and push constants shared by cull.comp and finalize.comp (one pipeline layout).
// Binding numbers must match cull_pass.cpp's kBinding* constants.
#ifndef LINTEL_CULL_BINDINGS_GLSL
#define LINTEL_CULL_BINDINGS_GLSL

#include "lintel/gpu/cull_shared.h"

// This dispatch's window of the instance array, in cell order (a dynamic offset selects the window).
layout(std430, set = 0, binding = 0) readonly buffer Instances { GpuInstance instances[]; };
layout(std430, set = 0, binding = 1) readonly buffer Groups { GpuDrawGroup groups[]; };
layout(std430, set = 0, binding = 2) readonly buffer CellRegions { uint cell_region[]; };
layout(std430, set = 0, binding = 3) readonly buffer Regions { GpuRegion regions[]; };
layout(std430, set = 0, binding = 4) readonly buffer Polygons { GpuPolygon polygons[]; };
// Per polygon vertex: the line of its edge to the next vertex (CullFrame::edges_ndc).
layout(std430, set = 0, binding = 5) readonly buffer Edges { vec4 edges_ndc[]; };
layout(std430, set = 0, binding = 6) coherent buffer Counters {
  GpuCullStats stats;
  uint group_counts[];  // survivors per group, before clamping to capacity
};
layout(std430, set = 0, binding = 7) writeonly buffer InstanceIds { uint instance_ids[]; };
layout(std430, set = 0, binding = 8) writeonly buffer Commands { DrawIndexedCommand commands[]; };
layout(std430, set = 0, binding = 9) writeonly buffer CompactCommands { DrawIndexedCommand compact_commands[]; };
layout(std430, set = 0, binding = 10) writeonly buffer CompactGroups { uint compact_groups[]; };
// Reach lists of instances whose bounds reach several cells (GpuInstance::cell with kReachListBit).
layout(std430, set = 0, binding = 11) readonly buffer Reach { uint reach_cells[]; };
// The instance id (World index) of each position of the cell-ordered instance buffer (whole).
layout(std430, set = 0, binding = 12) readonly buffer PositionIds { uint id_of_position[]; };
// This frame's work items (GpuCullWork), grouped by window, and its moved list {position in the
// window, home cell}.
layout(std430, set = 0, binding = 13) readonly buffer Work { GpuCullWork work[]; };
layout(std430, set = 0, binding = 14) readonly buffer Moved { uvec2 moved[]; };
// Boxes straddling the near or far plane, left by a cell dispatch to the straddler pipeline
// (CullPassOptions::defer_straddlers): {position in the window, region}; the header is also the
// VkDispatchIndirectCommand of that pipeline.
layout(std430, set = 0, binding = 15) buffer Straddlers {
  GpuStraddleHeader straddle;
  uvec2 straddlers[];
};

layout(push_constant) uniform Constants { GpuCullConstants pc; };

#endif
