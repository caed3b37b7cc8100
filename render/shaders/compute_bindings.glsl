// The one descriptor set every renderer compute pass binds (set 0): each pass reads the bindings
// it needs. One layout keeps the C++ side to one set per frame slot and one pipeline layout;
// the numbers are named in render_bindings.h (shared with the C++ set layout).
#ifndef LINTEL_COMPUTE_BINDINGS_GLSL
#define LINTEL_COMPUTE_BINDINGS_GLSL
#include "render_bindings.h"

// Read-only data as rgba32ui texels (render_bindings.h says why); the loaders below rebuild the
// structs of render_shared.h from them, field by field in declaration order.
layout(set = 0, binding = kBindLights) uniform usamplerBuffer light_texels;
// Per-cell light lists, host-written per frame slot: entries [0, cells) are each cell's list
// (x = first entry, y = count; 0 0 for an inactive cell); each list entry is x = light index,
// y = its first shadow-atlas slot this frame or kNoShadowSlot, in the frame's light order.
layout(set = 0, binding = kBindActiveLights) uniform usamplerBuffer active_light_texels;  // uvec2 texels
layout(set = 0, binding = kBindShadowViews) uniform usamplerBuffer shadow_view_texels;
layout(std430, set = 0, binding = kBindLightMasks) readonly buffer LightMasks { uint light_masks[]; };
layout(set = 0, binding = kBindShadowAtlas) uniform sampler2DArray shadow_atlas;  // D32, read with texelFetch
layout(set = 0, binding = kBindCellProbes) uniform usamplerBuffer cell_probe_texels;
layout(std430, set = 0, binding = kBindProbes) buffer Probes { GpuProbe probes[]; };  // written by the GI gather
layout(set = 0, binding = kBindProbeTexels) uniform usamplerBuffer probe_texels;      // the same, for reading
layout(set = 0, binding = kBindSurfels) uniform usamplerBuffer surfel_texels;
layout(std430, set = 0, binding = kBindSurfelRadiance) buffer SurfelRadiance { vec4 surfel_radiance[]; };  // written
layout(set = 0, binding = kBindSurfelRadianceTexels) uniform usamplerBuffer surfel_radiance_texels;  // read
layout(set = 0, binding = kBindProbeVisibility) uniform usamplerBuffer probe_visibility_texels;
// Per cell 1 = active (drawn or a portal neighbour of a drawn cell); then, from entry `cells`, two
// per portal: 1 = open from -> to, 1 = open to -> from (GpuSurfel::portal.z points at one).
layout(std430, set = 0, binding = kBindActiveCells) readonly buffer ActiveCells { uint active_cells[]; };
layout(set = 0, binding = kBindAlbedo, rgba8) uniform image2D gbuffer_albedo;
layout(set = 0, binding = kBindNormal, rgba16f) uniform image2D gbuffer_normal;
layout(set = 0, binding = kBindCell, r32ui) uniform uimage2D gbuffer_cell;
layout(set = 0, binding = kBindEmission, rgba16f) uniform image2D gbuffer_emission;
layout(set = 0, binding = kBindDepth) uniform sampler2D gbuffer_depth;     // D32, read with texelFetch
layout(set = 0, binding = kBindAo, r32f) uniform image2D ao_image;
// GTAO at half resolution, (w+1)/2 x (h+1)/2: x = visibility, y = the sample's view depth, z = its
// cell (uint bits): what the upsample weighs it by, in one load instead of three.
layout(set = 0, binding = kBindAoHalf, rgba32f) uniform image2D ao_half_image;
layout(set = 0, binding = kBindHdr, rgba32f) uniform image2D hdr_image;
layout(set = 0, binding = kBindLdr, rgba8) uniform image2D ldr_image;
layout(std430, set = 0, binding = kBindExposure) buffer Exposure { float exposure_value[]; };  // [0]: this frame's
// Per linked view of the frame (index = the transform in the g-buffer cell id, kCellLinkShift).
layout(set = 0, binding = kBindLinkViews) uniform usamplerBuffer link_view_texels;

vec4 texel_vec4(usamplerBuffer b, uint i) { return uintBitsToFloat(texelFetch(b, int(i))); }
mat4 texel_mat4(usamplerBuffer b, uint i) {
  return mat4(texel_vec4(b, i), texel_vec4(b, i + 1u), texel_vec4(b, i + 2u), texel_vec4(b, i + 3u));
}

GpuLight load_light(uint l) {
  uint t = 5u * l;
  GpuLight g;
  g.position_type = texel_vec4(light_texels, t);
  g.direction_range = texel_vec4(light_texels, t + 1u);
  g.color = texel_vec4(light_texels, t + 2u);
  g.cone = texel_vec4(light_texels, t + 3u);
  uvec4 u = texelFetch(light_texels, int(t + 4u));
  g.shadow_view = u.x;
  g.shadow_view_count = u.y;
  g.mask_offset = u.z;
  g.unused = u.w;
  return g;
}

uvec2 active_light(uint i) { return texelFetch(active_light_texels, int(i)).xy; }

mat4 load_shadow_view(uint v) { return texel_mat4(shadow_view_texels, 4u * v); }

GpuCellProbes load_cell_probes(uint cell) {
  uint t = 8u * cell;
  GpuCellProbes c;
  c.world_to_grid = texel_mat4(cell_probe_texels, t);
  c.origin_grid = texel_vec4(cell_probe_texels, t + 4u);
  c.step_grid = texel_vec4(cell_probe_texels, t + 5u);
  c.dims = texelFetch(cell_probe_texels, int(t + 6u));
  c.surfels = texelFetch(cell_probe_texels, int(t + 7u));
  return c;
}

// Probe p's four radiance SH coefficients (GpuProbe: position, then the three packed texels).
void load_probe_sh(uint p, out vec3 c0, out vec3 c1, out vec3 c2, out vec3 c3) {
  vec4 a = texel_vec4(probe_texels, 5u * p + 1u), b = texel_vec4(probe_texels, 5u * p + 2u),
       c = texel_vec4(probe_texels, 5u * p + 3u);
  c0 = a.rgb;
  c1 = b.rgb;
  c2 = c.rgb;
  c3 = vec3(a.w, b.w, c.w);
}

GpuSurfel load_surfel(uint i) {
  GpuSurfel s;
  uint t = kSurfelTexels * i;
  s.position_cell = texel_vec4(surfel_texels, t);
  s.normal_area = texel_vec4(surfel_texels, t + 1u);
  s.albedo = texel_vec4(surfel_texels, t + 2u);
  s.portal = texelFetch(surfel_texels, int(t + 3u));
  s.emission = texel_vec4(surfel_texels, t + 4u);
  return s;
}

mat4 load_link_view(uint t) { return texel_mat4(link_view_texels, 4u * t); }

#endif
