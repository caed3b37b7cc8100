// Two-phase hierarchical-Z occlusion culling of the camera's draws (CameraCull::PortalHiz), the
// scheme of niagara (Kapoulkine): the g-buffer first draws what passed last frame's test (and the
// portal cull now), the depth pyramid is built from that depth, every draw of the portal cull is
// tested against it, and what passes and was not drawn yet is drawn second. Four stages, each its
// own shader (hiz_*.comp) so that each declares only the buffers it touches, which is what the
// render graph's declarations and synchronization validation see (render/src/passes/hiz_pass.h):
//   0 early:    per id slot of the portal cull's output: ids visible last frame, and every shell
//               (walls are the main occluders and almost never hidden) -> phase-1 ids
//   1 commands: per draw group: the phase's command (the cull's, with the phase's count and ids)
//   2 pyramid:  per texel of one pyramid level: the max of its 2 x 2 texels below (level 0: of
//               the depth image, texelFetch: no depth filtering, which lavapipe lacks)
//   3 late:     per id slot: the box against the pyramid; visibility for the next frame; ids that
//               pass and were not drawn first -> phase-2 ids
// Depth is Vulkan's [0, 1], 1 = far, cleared to 1: an uncovered pixel never hides anything.
#include "lintel/gpu/cull_shared.h"  // GpuInstance, DrawIndexedCommand
#include "render_bindings.h"           // kHizBind*, and render_shared.h's HizPush

layout(local_size_x = 64) in;

layout(set = 0, binding = kHizBindCullCommands, std430) readonly buffer CullCommands {
  DrawIndexedCommand cull_commands[];
};
layout(set = 0, binding = kHizBindCullIds, std430) readonly buffer CullIds { uint cull_ids[]; };
layout(set = 0, binding = kHizBindCommands, std430) buffer HizCommands { DrawIndexedCommand hiz_commands[]; };
layout(set = 0, binding = kHizBindIds, std430) buffer HizIds { uint hiz_ids[]; };
layout(set = 0, binding = kHizBindCounters, std430) buffer Counters { uint counters[]; };
layout(set = 0, binding = kHizBindVisibility, std430) buffer Visibility { uint visible_last_frame[]; };
layout(set = 0, binding = kHizBindPyramid, std430) buffer Pyramid { float pyramid[]; };
layout(set = 0, binding = kHizBindInstances, std430) readonly buffer Instances { GpuInstance instances[]; };
layout(set = 0, binding = kHizBindSlotGroups, std430) readonly buffer SlotGroups { uint slot_group[]; };
layout(set = 0, binding = kHizBindDepth) uniform sampler2D depth_image;

layout(push_constant) uniform Push { HizPush pc; };  // render_shared.h

// Level l's size and first texel in `pyramid`: level 0 is the depth image halved (rounded up).
uvec2 level_size(uint l) { return (uvec2(pc.image.xy) + (2u << l) - 1u) >> (l + 1u); }
uint level_offset(uint l) {
  uint offset = 0u;
  for (uint k = 0u; k < l; ++k) {
    const uvec2 s = level_size(k);
    offset += s.x * s.y;
  }
  return offset;
}

// Whether every pixel the box can cover already holds something nearer than the box's nearest
// point (then the g-buffer's LESS test would reject every fragment of it).
bool occluded(GpuInstance inst) {
  vec2 lo = vec2(1e30), hi = vec2(-1e30);
  float zmin = 1.0;
  for (uint c = 0u; c < 8u; ++c) {
    const vec3 p = vec3((c & 1u) != 0u ? inst.bounds_max_world.x : inst.bounds_min_world.x,
                        (c & 2u) != 0u ? inst.bounds_max_world.y : inst.bounds_min_world.y,
                        (c & 4u) != 0u ? inst.bounds_max_world.z : inst.bounds_min_world.z);
    const vec4 clip = pc.view_proj * vec4(p, 1.0);
    if (clip.w <= 1e-6 || clip.z <= 0.0) return false;  // reaches the near plane
    const vec3 ndc = clip.xyz / clip.w;
    lo = min(lo, ndc.xy);
    hi = max(hi, ndc.xy);
    zmin = min(zmin, ndc.z);
  }
  // Pixel rect (row 0 at the top: the renderer flips y), one pixel of slack for rounding.
  const vec2 size = vec2(pc.image.xy);
  const vec2 p0 = vec2(lo.x * 0.5 + 0.5, 0.5 - hi.y * 0.5) * size - 1.0;
  const vec2 p1 = vec2(hi.x * 0.5 + 0.5, 0.5 - lo.y * 0.5) * size + 1.0;
  if (p1.x < 0.0 || p1.y < 0.0 || p0.x > size.x || p0.y > size.y) return false;  // off screen: the cull's call
  const ivec2 last = ivec2(pc.image.xy) - 1;
  const ivec2 a = clamp(ivec2(floor(p0)), ivec2(0), last), b = clamp(ivec2(floor(p1)), ivec2(0), last);
  // The finest level where the rect spans at most 2 x 2 texels (a level-l texel is 2^(l+1) pixels).
  uint l = 0u;
  while (l + 1u < pc.counts.w && (((b.x >> (l + 1u)) - (a.x >> (l + 1u))) > 1 || ((b.y >> (l + 1u)) - (a.y >> (l + 1u))) > 1))
    ++l;
  const uvec2 s = level_size(l);
  const uint offset = level_offset(l);
  const ivec2 t0 = a >> (l + 1u), t1 = b >> (l + 1u);
  float deepest = 0.0;
  for (int y = t0.y; y <= t1.y; ++y)
    for (int x = t0.x; x <= t1.x; ++x) deepest = max(deepest, pyramid[offset + uint(y) * s.x + uint(x)]);
  return zmin > deepest + 1e-6;
}

void hiz_commands_stage() {
  const uint t = gl_GlobalInvocationID.x;
  const uint capacity = pc.counts.x, groups = pc.counts.y;
  if (t >= groups) return;
  const uint phase = pc.counts.z;
  DrawIndexedCommand c = cull_commands[t];
  c.instance_count = counters[phase * groups + t];
  c.first_instance += phase * capacity;
  hiz_commands[phase * groups + t] = c;
}

void hiz_pyramid_stage() {
  const uint t = gl_GlobalInvocationID.x;
  const uint l = pc.image.z;
  const uvec2 s = level_size(l);
  if (t >= s.x * s.y) return;
  const uvec2 xy = uvec2(t % s.x, t / s.x);
  float m = 0.0;
  if (l == 0u) {
    const ivec2 last = ivec2(pc.image.xy) - 1;
    for (uint k = 0u; k < 4u; ++k)
      m = max(m, texelFetch(depth_image, min(ivec2(2u * xy + uvec2(k & 1u, k >> 1u)), last), 0).r);
  } else {
    const uvec2 below = level_size(l - 1u);
    const uint from = level_offset(l - 1u);
    for (uint k = 0u; k < 4u; ++k) {
      const uvec2 c = min(2u * xy + uvec2(k & 1u, k >> 1u), below - 1u);
      m = max(m, pyramid[from + c.y * below.x + c.x]);
    }
  }
  pyramid[level_offset(l) + xy.y * s.x + xy.x] = m;
}

// Stages early and late: one id slot of the portal cull's output each. False for a slot the cull
// left empty. Touches only the cull's buffers: each stage then declares exactly what it uses.
bool cull_slot(uint t, out uint g, out DrawIndexedCommand c, out uint id) {
  if (t >= pc.counts.x) return false;
  g = slot_group[t];
  c = cull_commands[g];
  if (t - c.first_instance >= c.instance_count) return false;
  id = cull_ids[t];
  return true;
}

void hiz_early_stage() {
  uint g, id;
  DrawIndexedCommand c;
  if (!cull_slot(gl_GlobalInvocationID.x, g, c, id)) return;
  // Shells (walls) always go first: the main occluders, almost never hidden.
  if (visible_last_frame[id] != 0u || id >= pc.image.w) hiz_ids[c.first_instance + atomicAdd(counters[g], 1u)] = id;
}

void hiz_late_stage() {
  uint g, id;
  DrawIndexedCommand c;
  if (!cull_slot(gl_GlobalInvocationID.x, g, c, id)) return;
  const bool visible = !occluded(instances[id]);
  const bool drawn = visible_last_frame[id] != 0u || id >= pc.image.w;
  atomicAdd(counters[2u * pc.counts.y], 1u);
  if (visible) atomicAdd(counters[2u * pc.counts.y + 1u], 1u);
  visible_last_frame[id] = visible ? 1u : 0u;
  if (visible && !drawn) hiz_ids[pc.counts.x + c.first_instance + atomicAdd(counters[pc.counts.y + g], 1u)] = id;
}
