#version 460
#extension GL_GOOGLE_include_directive : require
// Deferred lighting: per pixel, direct light (its cell's light list, shadowed) plus indirect irradiance
// from the pixel's own cell's probes, times GTAO, plus the surface's own emission; writes linear
// radiance to hdr_image. A pixel
// drawn through a linked view (mirror, teleport) is lit in its surface's own place. The debug
// views of shadow, GI and AO are written here too (the tonemap pass shows them as they are).
#include "lighting_common.glsl"

layout(local_size_x = kTileSize, local_size_y = kTileSize) in;
// Whether the scene has emissive surfaces (the g-buffer's emission target is 0 otherwise): lavapipe
// would load the target for every pixel even where nothing emits.
layout(constant_id = 0) const bool kEmission = true;
layout(push_constant) uniform Push { LightingPush pc; };

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(uvec2(px), pc.size.xy))) return;
  uint cell = imageLoad(gbuffer_cell, px).r;
  if (cell == kNoCell) {  // the sky (World::environment), in the final image only
    imageStore(hdr_image, px, vec4(pc.mode.y == kViewFinal ? pc.environment.rgb : vec3(0.0), 1.0));
    return;
  }
  float depth = texelFetch(gbuffer_depth, px, 0).r;
  vec2 ndc = vec2((float(px.x) + 0.5) / float(pc.size.x) * 2.0 - 1.0, 1.0 - (float(px.y) + 0.5) / float(pc.size.y) * 2.0);
  vec4 w = pc.clip_to_world * vec4(ndc, depth, 1.0);
  vec3 p = w.xyz / w.w;
  vec3 n = normalize(imageLoad(gbuffer_normal, px).xyz);
  // Seen through a mirror or teleport: lit where the surface really is, by its own cell's lights,
  // shadows and probes (the view transform is rigid or a reflection, so its 3x3 turns normals).
  uint link = cell >> kCellLinkShift;
  cell &= kCellIdMask;
  if (link != 0u) {
    mat4 back = load_link_view(link);
    p = (back * vec4(p, 1.0)).xyz;
    n = normalize(mat3(back) * n);
  }
  vec3 albedo = imageLoad(gbuffer_albedo, px).rgb;

  float shadowed, unshadowed;
  vec3 direct = direct_irradiance(p, n, cell, shadowed, unshadowed);
  vec3 indirect = pc.size.z != 0u ? probe_irradiance(cell, p, n) : vec3(0.0);
  float ao = pc.size.w != 0u ? imageLoad(ao_image, px).r : 1.0;
  // The sky as ambient light: the irradiance of an unoccluded uniform sky (pi L), times AO; it
  // ignores walls (docs/rendering.md), so it is 0 unless the scene names a sky or has no lights.
  vec3 sky = kPi * pc.environment.rgb;
  // GTAO's visibility counts light that a crease blocks but not light that bounces inside it: on
  // pale surfaces much of it comes back. Jimenez et al.'s multi-bounce fit ("Practical Real-Time
  // Strategies for Accurate Indirect Occlusion", 2016), a cubic in the visibility per albedo.
  vec3 a = 2.0404 * albedo - 0.3324, b = -4.7951 * albedo + 0.6417, c = 2.7552 * albedo + 0.6903;
  vec3 ao_bounced = max(vec3(ao), ((ao * a + b) * ao + c) * ao);
  vec3 radiance = albedo / kPi * (direct + (indirect + sky) * ao_bounced);

  // What the surface gives off by itself, seen as it is: not shadowed, not occluded.
  if (kEmission) radiance += imageLoad(gbuffer_emission, px).rgb;

  uint view = pc.mode.y;
  if (view == kViewShadow) radiance = vec3(unshadowed > 0.0 ? shadowed / unshadowed : 0.0);
  else if (view == kViewGi) radiance = albedo / kPi * (indirect + sky) * ao_bounced;
  else if (view == kViewAo) radiance = vec3(ao);
  imageStore(hdr_image, px, vec4(radiance, 1.0));
}
