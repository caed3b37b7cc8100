#version 460
#extension GL_GOOGLE_include_directive : require
// The last pass: the final image (exposure, the Narkowicz ACES fit, sRGB encoding) or a debug
// view of one pass (albedo, normal, depth, shadow, GI, AO), into the 8-bit image the PNG is
// written from.
#include "compute_bindings.glsl"

layout(local_size_x = kTileSize, local_size_y = kTileSize) in;
layout(push_constant) uniform Push { TonemapPush pc; };
// Two pipelines: the final image only (every frame), or any view (debug views). lavapipe runs
// both sides of every branch, so the final image's pipeline must not contain the other views.
layout(constant_id = 0) const bool kAnyView = true;

vec3 aces(vec3 x) {
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

vec3 srgb_encode(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(uvec2(px), pc.size.xy))) return;
  if (!kAnyView) {
    float exposure = pc.size.w != 0u ? exposure_value[0] : pc.params.x;
    imageStore(ldr_image, px, vec4(srgb_encode(aces(imageLoad(hdr_image, px).rgb * exposure)), 1.0));
    return;
  }
  uint view = pc.size.z;
  bool background = imageLoad(gbuffer_cell, px).r == kNoCell;
  vec3 c;
  if (view == kViewAlbedo) {
    c = srgb_encode(imageLoad(gbuffer_albedo, px).rgb);
  } else if (view == kViewNormal) {
    c = background ? vec3(0.0) : imageLoad(gbuffer_normal, px).xyz * 0.5 + 0.5;
  } else if (view == kViewDepth) {
    float d = texelFetch(gbuffer_depth, px, 0).r;
    float n = pc.params.y, f = pc.params.z;
    float z = n * f / (f - d * (f - n));
    c = background ? vec3(0.0) : vec3(1.0 - clamp(z / pc.params.w, 0.0, 1.0));
  } else if (view == kViewShadow || view == kViewAo) {
    c = imageLoad(hdr_image, px).rgb;  // already in [0, 1]
  } else {
    float exposure = pc.size.w != 0u ? exposure_value[0] : pc.params.x;
    c = srgb_encode(aces(imageLoad(hdr_image, px).rgb * exposure));
  }
  imageStore(ldr_image, px, vec4(c, 1.0));
}
