// The cull: one thread per instance. Visible when its cell (or a cell its bounds reach: reach
// lists) is visible this frame and its world box passes cull_math.glsl's test (contains the eye, or its near/far-clipped NDC rect touches the
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

// An instance whose bounds reach several cells (kReachListBit) is visible when its box passes the
// region of any visible cell of its list: projected once, tested region by region.
bool reach_visible(GpuInstance inst) {
  uint at = inst.cell & ~kReachListBit;
  uint n = min(reach_cells[at], kMaxReachCells);
  bool any_visible = false;
  for (uint k = 0u; k < n; ++k) {
    uint c = reach_cells[at + 1u + k];
    any_visible = any_visible || (c < pc.cell_count && cell_region[c] != kNoRegion);
  }
  if (!any_visible) return false;
  vec4 rect;
  uint kind = project_box(inst.bounds_min_world, inst.bounds_max_world, pc.view_proj_rel, pc.far_row_rel, pc.eye_world.xyz,
                          rect);
  if (kind != kBoxProjected) return kind == kBoxHoldsEye;
  for (uint k = 0u; k < n; ++k) {
    uint c = reach_cells[at + 1u + k];
    if (c >= pc.cell_count) continue;
    uint r = cell_region[c];
    if (r != kNoRegion && rect_visible_in_region(rect, r, kTestRegions)) return true;
  }
  return false;
}

bool instance_visible(GpuInstance inst) {
  if (inst.cell == kNoRegion) return false;  // empty bounds
  if ((inst.cell & kReachListBit) != 0u) return reach_visible(inst);
  if (inst.cell >= pc.cell_count) return false;
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
