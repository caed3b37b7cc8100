// The cull: one workgroup per work item, one thread per instance. The CPU lists work items only
// for the ranges of visible cells (instances are stored cell by cell), so an invisible cell costs
// nothing; an item's instances share one cell and so one clip region. Visible when the box passes
// cull_math.glsl's test against that region (contains the eye, or its near/far-clipped NDC rect
// touches the region) -- the CPU reference's rule, lintel::cull_instances. Instances reaching
// several cells (reach lists) sit in a "loose" range tested each by its own list, and instances
// moved out of their range since set_scene come through the moved list. A survivor appends its id
// at group.base + atomicAdd(count[group], 1), written only while below the group's capacity
// (finalize.comp counts the rest as overflow).
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

// An instance tested against `region` (its work item's, one per workgroup), or with `own` by its
// own record (loose range, moved list): its cell's region, or its reach list. One call site of
// the box test: lavapipe runs both sides of every branch.
bool instance_visible(GpuInstance inst, bool own, uint region) {
  if (own) {
    if (inst.cell == kNoRegion) return false;  // empty bounds
    if ((inst.cell & kReachListBit) != 0u) return reach_visible(inst);
    region = inst.cell < pc.cell_count ? cell_region[inst.cell] : kNoRegion;
  }
  if (region == kNoRegion) return false;
  return box_visible(inst.bounds_min_world, inst.bounds_max_world, pc.view_proj_rel, pc.far_row_rel, pc.eye_world.xyz,
                     region, kTestRegions);
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
  uint position;     // in the window
  bool own = true;   // tested by its own cell or reach list
  uint region = kNoRegion;
  bool pending_test;
  if (pc.work_kind == kWorkMoved) {
    uint e = pc.work_first + gl_GlobalInvocationID.x;
    pending_test = gl_GlobalInvocationID.x < pc.work_count;
    uvec2 entry = pending_test ? moved[e] : uvec2(0u, kNoRegion);
    position = entry.x;
    // Back in its home cell: its home range's items test it, not this list.
    pending_test = pending_test && instances[position].cell != entry.y;
  } else {
    GpuCullWork item = work[pc.work_first + gl_WorkGroupID.x];
    pending_test = gl_LocalInvocationID.x < item.count;
    position = item.first + gl_LocalInvocationID.x;
    if (item.cell != kLooseWork) {
      own = false;
      region = item.region;
      // Moved out since set_scene: the moved list tests it.
      pending_test = pending_test && instances[position].cell == item.cell;
    }
  }
  if (!pending_test) return;
  GpuInstance inst = instances[position];
  if (!instance_visible(inst, own, region)) return;
  uint slot = append_slot(inst.group);
  GpuDrawGroup group = groups[inst.group];
  if (slot < group.capacity) instance_ids[group.base + slot] = id_of_position[pc.window_first + position];
}
