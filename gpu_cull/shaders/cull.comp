// The cull: one workgroup per work item, one thread per instance. The CPU lists work items only
// for the ranges of visible cells (instances are stored cell by cell, and by draw group within a
// cell), so an invisible cell costs nothing; an item's instances share one cell and so one clip
// region. Visible when the box passes cull_math.glsl's test against that region (contains the eye,
// or its near/far-clipped NDC rect touches the region) -- the CPU reference's rule,
// lintel::cull_instances. Two pipelines of this one shader (kOwnRegions):
//   * cell items: every thread tests its box against the item's region (no per-instance cell or
//     reach-list lookups: on lavapipe, which runs both sides of every branch, that code would
//     cost every instance);
//   * own regions: the "loose" range (instances reaching several cells, tested each by its own
//     reach list) and the moved list (instances moved out of their range since set_scene).
// A survivor appends its id at group.base + slot, written only while below the group's capacity
// (finalize.comp counts the rest as overflow). How it takes its slot is kAppend's choice: one
// atomicAdd, one per group per subgroup (one atomic each where the subgroup has few survivors),
// or one per group per workgroup (docs/perf.md measures all three; a region copied into shared
// memory per workgroup was measured too, and was slower).
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_ballot : require

#include "cull_bindings.glsl"
#include "cull_math.glsl"

layout(local_size_x = kCullWorkgroupSize) in;
// Variants (specialization constants, set by cull_pass.cpp):
layout(constant_id = 1) const bool kTestRegions = true;  // false: visible cell + frustum only
// How survivors take their slots: kAppendAtomic (one atomicAdd each), kAppendSubgroup (one per
// group per subgroup, needs ballot) or kAppendWorkgroup (one per group per workgroup, through
// shared memory).
layout(constant_id = 2) const uint kAppend = kAppendWorkgroup;
layout(constant_id = 3) const bool kOwnRegions = false;  // the loose range and the moved list
// Cell items leave boxes that straddle the near or far plane to the straddler list, which the
// kStraddlers pipeline tests after each cell dispatch (CPU devices: lavapipe runs the clipping
// code for every box otherwise, though few boxes need it).
layout(constant_id = 4) const bool kDeferStraddlers = false;
layout(constant_id = 5) const bool kStraddlers = false;  // the pipeline that tests the straddler list

// ---- own regions (loose range, moved list) ----------------------------------------------------------

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
                          true, rect);
  if (kind != kBoxProjected) return kind == kBoxHoldsEye;
  for (uint k = 0u; k < n; ++k) {
    uint c = reach_cells[at + 1u + k];
    if (c >= pc.cell_count) continue;
    uint r = cell_region[c];
    if (r != kNoRegion && rect_visible_in_region(rect, r, kTestRegions)) return true;
  }
  return false;
}

// An instance tested by its own record: its cell's region, or its reach list. One call site of
// the box test: lavapipe runs both sides of every branch.
bool own_visible(GpuInstance inst) {
  if (inst.cell == kNoRegion) return false;  // empty bounds
  if ((inst.cell & kReachListBit) != 0u) return reach_visible(inst);
  uint region = inst.cell < pc.cell_count ? cell_region[inst.cell] : kNoRegion;
  if (region == kNoRegion) return false;
  return box_visible(inst.bounds_min_world, inst.bounds_max_world, pc.view_proj_rel, pc.far_row_rel, pc.eye_world.xyz,
                     region, kTestRegions);
}

// ---- slots ----------------------------------------------------------------------------------------

// Slot of this survivor in its group: survivors of one subgroup often share a group, so the
// subgroup variant serves one group per loop turn with a single atomicAdd for all its survivors.
uint subgroup_slot(uint group) {
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

shared uint s_survivors;                            // survivors listed so far in this workgroup
shared uint s_survivor_group[kCullWorkgroupSize];   // their groups, in listing order
shared uint s_group_base[kCullWorkgroupSize];       // at a group's first listing: its first slot

// The workgroup variant: survivors list their groups in shared memory; the first listing of each
// group takes the slots of all its listings with one atomicAdd; each survivor's slot is that base
// plus the number of earlier listings of its group. Every thread calls this (it has barriers).
// s_survivors must be 0 and visible to all threads at entry.
uint workgroup_slot(bool visible, uint group) {
  uint k = 0u;
  if (visible) {
    k = atomicAdd(s_survivors, 1u);
    s_survivor_group[k] = group;
  }
  barrier();
  uint first = k, rank = 0u;
  if (visible) {
    uint n = s_survivors, same = 0u;
    first = kCullWorkgroupSize;
    for (uint j = 0u; j < n; ++j) {
      if (s_survivor_group[j] != group) continue;
      first = min(first, j);
      rank += j < k ? 1u : 0u;
      ++same;
    }
    if (first == k) s_group_base[k] = atomicAdd(group_counts[group], same);
  }
  barrier();
  return visible ? s_group_base[first] + rank : 0u;
}

void append(uint position, uint group, uint slot) {
  GpuDrawGroup g = groups[group];
  if (slot < g.capacity) instance_ids[g.base + slot] = id_of_position[pc.window_first + position];
}

// ---- the two entry shapes -------------------------------------------------------------------------

void cull_cell_item() {
  const uint t = gl_LocalInvocationID.x;
  GpuCullWork item = work[pc.work_first + gl_WorkGroupID.x];
  uint position = item.first + t;
  bool in_item = t < item.count;
  GpuInstance inst = GpuInstance(vec3(0.0), kNoRegion, vec3(0.0), 0u);
  if (in_item) inst = instances[position];
  if (kAppend == kAppendWorkgroup) {
    if (t == 0u) s_survivors = 0u;
    barrier();
  }
  // Moved out since set_scene: the moved list tests it.
  bool visible = false;
  if (in_item && inst.cell == item.cell) {
    vec4 rect;
    uint kind = project_box(inst.bounds_min_world, inst.bounds_max_world, pc.view_proj_rel, pc.far_row_rel,
                            pc.eye_world.xyz, !kDeferStraddlers, rect);
    visible = kind == kBoxHoldsEye || (kind == kBoxProjected && rect_visible_in_region(rect, item.region, kTestRegions));
    if (kDeferStraddlers && kind == kBoxStraddles) {
      // One more entry; an entry that starts a workgroup adds one to the indirect dispatch.
      uint k = atomicAdd(straddle.count, 1u);
      if (k % kCullWorkgroupSize == 0u) atomicAdd(straddle.dispatch_x, 1u);
      straddlers[k] = uvec2(position, item.region);
    }
  }
  if (kAppend == kAppendWorkgroup) {
    uint slot = workgroup_slot(visible, inst.group);
    if (visible) append(position, inst.group, slot);
    return;
  }
  if (kAppend == kAppendSubgroup) {
    // Counted while every thread of the subgroup is still here: a subgroup with few survivors
    // (a quarter of its lanes or fewer) takes one atomic each, which beats the loop's ballots at
    // two or three survivors; a dense one shares its atomics by group (docs/perf.md, "Append
    // mode on the H100"). Either path gives every survivor its own slot, whatever the count.
    uint survivors = subgroupBallotBitCount(subgroupBallot(visible));
    if (!visible) return;
    append(position, inst.group,
           survivors * 4u <= gl_SubgroupSize ? atomicAdd(group_counts[inst.group], 1u) : subgroup_slot(inst.group));
    return;
  }
  if (!visible) return;
  append(position, inst.group, atomicAdd(group_counts[inst.group], 1u));
}

void cull_own() {
  uint position;
  bool pending_test;
  if (pc.work_kind == kWorkMoved) {
    uint e = pc.work_first + gl_GlobalInvocationID.x;
    pending_test = gl_GlobalInvocationID.x < pc.work_count;
    uvec2 entry = pending_test ? moved[e] : uvec2(0u, kNoRegion);
    position = entry.x;
    // Back in its home cell: its home range's items test it, not this list.
    pending_test = pending_test && instances[position].cell != entry.y;
  } else {  // loose items
    GpuCullWork item = work[pc.work_first + gl_WorkGroupID.x];
    pending_test = gl_LocalInvocationID.x < item.count;
    position = item.first + gl_LocalInvocationID.x;
  }
  if (!pending_test) return;
  GpuInstance inst = instances[position];
  if (!own_visible(inst)) return;
  // No workgroup-wide slots here: threads returned above (these lists are short). cull_pass.cpp
  // gives this pipeline kAppendSubgroup where the device has ballot, else kAppendAtomic.
  append(position, inst.group,
         kAppend == kAppendSubgroup ? subgroup_slot(inst.group) : atomicAdd(group_counts[inst.group], 1u));
}

// The straddler list of the cell dispatch just before (same window): each entry's box with the
// clipping path, against the region of its item.
void cull_straddlers() {
  if (gl_GlobalInvocationID.x >= straddle.count) return;
  uvec2 entry = straddlers[gl_GlobalInvocationID.x];
  GpuInstance inst = instances[entry.x];
  if (!box_visible(inst.bounds_min_world, inst.bounds_max_world, pc.view_proj_rel, pc.far_row_rel, pc.eye_world.xyz,
                   entry.y, kTestRegions))
    return;
  append(entry.x, inst.group, atomicAdd(group_counts[inst.group], 1u));
}

void main() {
  if (kStraddlers) {
    cull_straddlers();
  } else if (kOwnRegions) {
    cull_own();
  } else {
    cull_cell_item();
  }
}
