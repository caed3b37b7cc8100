#version 460
#extension GL_GOOGLE_include_directive : require
// GI step 1: the outgoing radiance of every surfel of an active cell. A surface surfel reflects
// the direct light on it (same lights, masks and shadows as the pixels) plus, after the first
// bounce, its own cell's probe irradiance. A portal surfel emits what its neighbour's probes see
// looking through the portal (their cosine-weighted mean radiance): the only way light moves
// between cells, and only through an open portal.
#include "lighting_common.glsl"

layout(local_size_x = kLinearGroupSize) in;
layout(push_constant) uniform Push { SurfelLightPush pc; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= pc.counts.x) return;
  GpuSurfel s = load_surfel(i);
  uint cell = floatBitsToUint(s.position_cell.w);
  if (active_cells[cell] == 0u) return;
  vec3 p = s.position_cell.xyz;
  vec3 n = s.normal_area.xyz;
  // A portal surfel looks from the portal into the neighbour: the irradiance for the normal facing
  // it, over pi (a door closed from the neighbour's side, flag at active_cells[portal.z], passes
  // none). A surface surfel: its direct and indirect irradiance times albedo over pi. One probe
  // lookup either way, its cell, point and normal chosen: lavapipe would run both sides.
  bool portal = s.albedo.w == 0.0;
  vec3 q = portal ? p : p + n * 0.01;
  vec3 indirect = pc.counts.z > 0u ? probe_irradiance(portal ? s.portal.x : cell, q, portal ? -n : n) : vec3(0.0);
  vec3 radiance;
  if (portal) {
    bool open = active_cells[s.portal.z] != 0u;
    radiance = open ? indirect / kPi : vec3(0.0);
  } else {
    float shadowed, unshadowed;
    vec3 e = direct_irradiance(q, n, cell, shadowed, unshadowed) + indirect;
    radiance = s.albedo.rgb / kPi * e + s.emission.rgb;  // an emissive surface lights its cell through the probes
  }
  surfel_radiance[i] = vec4(radiance, 1.0);
}
