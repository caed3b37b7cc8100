// The cull: one thread per instance. Visible when its cell is visible this frame and its world
// box passes cull_math.glsl's test (contains the eye, or its near/far-clipped NDC rect touches the
// cell's clip region) -- the CPU reference's rule, lintel::cull_instances. A survivor appends its id at group.base + atomicAdd(count[group], 1), written
// only while below the group's capacity (finalize.comp counts the rest as overflow).
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_ballot : require

#include "cull_bindings.glsl"
#include "cull_math.glsl"

layout(local_size_x = kCullWorkgroupSize) in;
// Variants (specialization constants, set by cull_pass.cpp):
layout(constant_id = 1) const bool kTestRegions = true;         // false: visible cell + frustum only
layout(constant_id = 2) const bool kSubgroupAggregate = false;  // one atomic per group per subgroup

bool instance_visible(GpuInstance inst) {
  if (inst.cell >= pc.cell_count) return false;  // kNoRegion: empty bounds
  uint r = cell_region[inst.cell];
  if (r == kNoRegion) return false;
  return box_visible(inst.bounds_min_world, inst.bounds_max_world, pc.view_proj_rel, pc.far_row_rel, pc.eye_world.xyz, r,
                     kTestRegions);
}

// Slot of this survivor in its group. Survivors of one subgroup often share a group (instances
// of a mesh are usually listed together), so the aggregated variant serves one group per loop
// turn with a single atomicAdd for all its survivors.
uint append_slot(uint group) {
  if (!kSubgroupAggregate) return atomicAdd(group_counts[group], 1u);
  uint slot = 0u;
  bool pending = true;
  while (pending) {
    uint leader_group = subgroupBroadcastFirst(group);
    if (group == leader_group) {
      uvec4 ballot = subgroupBallot(true);
      uint base = 0u;
      if (subgroupElect()) base = atomicAdd(group_counts[group], subgroupBallotBitCount(ballot));
      slot = subgroupBroadcastFirst(base) + subgroupBallotExclusiveBitCount(ballot);
      pending = false;
    }
  }
  return slot;
}

void main() {
  uint local = gl_GlobalInvocationID.x;
  if (local >= pc.instance_count) return;
  GpuInstance inst = instances[local];
  if (!instance_visible(inst)) return;
  uint slot = append_slot(inst.group);
  GpuDrawGroup group = groups[inst.group];
  if (slot < group.capacity) instance_ids[group.base + slot] = pc.first_instance + local;
}
