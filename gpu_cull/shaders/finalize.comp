// Finalize: one thread per draw group turns its survivor count into the group's
// VkDrawIndexedIndirectCommand (firstInstance = base), clamped to the group's capacity so a draw
// never reads past its id range, counts overflow, and appends non-empty groups to the compacted
// list that vkCmdDrawIndexedIndirectCount draws.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "cull_bindings.glsl"

layout(local_size_x = kFinalizeWorkgroupSize) in;

void main() {
  uint g = gl_GlobalInvocationID.x;
  if (g >= pc.group_count) return;
  GpuDrawGroup group = groups[g];
  uint count = group_counts[g];
  if (count > group.capacity) {
    atomicAdd(stats.overflow_instances, count - group.capacity);
    atomicAdd(stats.overflow_groups, 1u);
    count = group.capacity;
  }
  DrawIndexedCommand cmd = DrawIndexedCommand(group.index_count, count, group.first_index, group.vertex_offset, group.base);
  commands[g] = cmd;
  if (count > 0u) {
    atomicAdd(stats.visible_instances, count);
    uint slot = atomicAdd(stats.draw_count, 1u);
    compact_commands[slot] = cmd;
    compact_groups[slot] = g;
  }
}
