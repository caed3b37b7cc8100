#version 460
#extension GL_GOOGLE_include_directive : require
// Depth-aware upsample of the half-resolution GTAO: each full-resolution pixel blends the (up to)
// four half-resolution samples around it with bilinear weights times a depth weight (samples whose
// view depth is far from the pixel's count for nothing) and only samples of the pixel's own cell,
// so occlusion neither bleeds across silhouettes nor across cells. A pixel with no agreeing sample
// (a thin sliver at an edge) takes no occlusion (1.0): AO only darkens indirect light, and the
// conservative choice is to not invent occlusion.
#include "compute_bindings.glsl"

layout(local_size_x = kTileSize, local_size_y = kTileSize) in;
layout(push_constant) uniform Push { AoUpsamplePush pc; };

float view_depth(ivec2 q) {
  float d = texelFetch(gbuffer_depth, q, 0).r;
  float n = pc.projection.z, f = pc.projection.w;
  return n * f / (f - d * (f - n));  // perspectiveRH_ZO: distance along -Z
}

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(uvec2(px), pc.size.xy))) return;
  uint cell = imageLoad(gbuffer_cell, px).r;
  if (cell == kNoCell) {
    imageStore(ao_image, px, vec4(1.0));
    return;
  }
  float z = view_depth(px);
  // Half-resolution sample h sits at full-resolution pixel 2h; its neighbours around px:
  ivec2 base = px >> 1;
  ivec2 dir = ivec2(px.x & 1, px.y & 1);  // odd pixels lie between sample h and h+1
  // Always the four samples, those not around px weighted 0 (the same sums, in the same order, as
  // visiting only those around it): a loop whose length differs between neighbouring pixels costs
  // its longest on lavapipe, and a fixed one unrolls.
  float sum = 0.0, weight = 0.0;
  for (int k = 0; k < 4; ++k) {
    ivec2 o = ivec2(k & 1, k >> 1);
    ivec2 h = min(base + o, ivec2(pc.size.zw) - 1);
    vec4 s = imageLoad(ao_half_image, h);  // visibility, view depth, cell (gtao.comp)
    bool around = all(lessThanEqual(o, dir)) && floatBitsToUint(s.z) == cell;
    float dz = abs(s.y - z) / max(z, 1e-4);
    float w = around ? max(0.0, 1.0 - dz / pc.params.x) : 0.0;
    sum += w * s.x;
    weight += w;
  }
  imageStore(ao_image, px, vec4(weight > 1e-4 ? sum / weight : 1.0));
}
