#version 460
#extension GL_GOOGLE_include_directive : require
// GI step 2: every probe of an active cell projects the radiance of its own cell's surfels (and
// portal surfels) onto SH L1. Each surfel stands for a disc of its area: its solid angle
// 2 pi (1 - 1 / sqrt(1 + A cos / (pi r^2))) stays bounded however close the probe is.
// A surfel counts only if nothing of the cell lies between it and the probe (the bits computed at
// creation, gi_layout.cpp).
#include "compute_bindings.glsl"

layout(local_size_x = kLinearGroupSize) in;
layout(push_constant) uniform Push { ProbeGatherPush pc; };

void main() {
  uint j = gl_GlobalInvocationID.x;
  if (j >= pc.counts.x) return;
  vec3 x = probes[j].position_world.xyz;
  uint cell = floatBitsToUint(probes[j].position_world.w);
  if (active_cells[cell] == 0u) return;
  GpuCellProbes cp = load_cell_probes(cell);
  vec3 sh0 = vec3(0.0), sh1 = vec3(0.0), sh2 = vec3(0.0), sh3 = vec3(0.0);
  uint first = cp.surfels.x, last = cp.surfels.z + cp.surfels.w;  // surfaces then portals, contiguous
  // The surfels this probe sees, a bit each, 128 to a texel (gi_layout.cpp): furniture, a door
  // leaf or a mirror inside the room hides what lies behind it.
  uint bits_texel = probes[j].visibility.x;
  uint i = first;
  // do-while, the test at the end (lighting_common.glsl says why); a cell has surfels.
  if (i < last) do {
    uvec4 seen = texelFetch(probe_visibility_texels, int(bits_texel++));
    uint chunk_end = min(i + 128u, last);
    do {
      uint k = i - first;
      if (((seen[(k >> 5u) & 3u] >> (k & 31u)) & 1u) == 0u) continue;
      vec3 d = texel_vec4(surfel_texels, kSurfelTexels * i).xyz - x;
      float r2 = max(dot(d, d), 1e-6);
      vec3 w = d * inversesqrt(r2);  // towards the surfel: the direction light arrives from
      vec4 normal_area = texel_vec4(surfel_texels, kSurfelTexels * i + 1u);
      float cos_s = dot(normal_area.xyz, -w);
      if (cos_s <= 0.0) continue;
      float a = normal_area.w * cos_s;
      float omega = 2.0 * 3.14159265 * (1.0 - inversesqrt(1.0 + a / (3.14159265 * r2)));
      vec3 l = texel_vec4(surfel_radiance_texels, i).rgb * omega;
      sh0 += l * 0.282095;
      sh1 += l * (0.488603 * w.y);
      sh2 += l * (0.488603 * w.z);
      sh3 += l * (0.488603 * w.x);
    } while (++i < chunk_end);
  } while (i < last);
  probes[j].sh[0] = vec4(sh0, sh3.x);
  probes[j].sh[1] = vec4(sh1, sh3.y);
  probes[j].sh[2] = vec4(sh2, sh3.z);
}
