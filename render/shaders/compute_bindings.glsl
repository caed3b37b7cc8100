// The one descriptor set every renderer compute pass binds (set 0): each pass reads the bindings
// it needs. One layout keeps the C++ side to one set per frame slot and one pipeline layout;
// the numbers are named in render_bindings.h (shared with the C++ set layout).
#ifndef LINTEL_COMPUTE_BINDINGS_GLSL
#define LINTEL_COMPUTE_BINDINGS_GLSL
#include "render_bindings.h"

layout(std430, set = 0, binding = kBindLights) readonly buffer Lights { GpuLight lights[]; };
// Per-cell light lists, host-written per frame slot: entries [0, cells) are each cell's list
// (x = first entry, y = count; 0 0 for an inactive cell); each list entry is x = light index,
// y = its first shadow-atlas slot this frame or kNoShadowSlot, in the frame's light order.
layout(std430, set = 0, binding = kBindActiveLights) readonly buffer ActiveLights { uvec2 active_lights[]; };
layout(std430, set = 0, binding = kBindShadowViews) readonly buffer ShadowViews { mat4 shadow_views[]; };
layout(std430, set = 0, binding = kBindLightMasks) readonly buffer LightMasks { uint light_masks[]; };
layout(set = 0, binding = kBindShadowAtlas) uniform sampler2DArray shadow_atlas;  // D32, read with texelFetch
layout(std430, set = 0, binding = kBindCellProbes) readonly buffer CellProbes { GpuCellProbes cell_probes[]; };
layout(std430, set = 0, binding = kBindProbes) buffer Probes { GpuProbe probes[]; };
layout(std430, set = 0, binding = kBindSurfels) readonly buffer Surfels { GpuSurfel surfels[]; };
layout(std430, set = 0, binding = kBindSurfelRadiance) buffer SurfelRadiance { vec4 surfel_radiance[]; };
// Per cell 1 = active (drawn or a portal neighbour of a drawn cell); then, from entry `cells`, two
// per portal: 1 = open from -> to, 1 = open to -> from (GpuSurfel::portal.z points at one).
layout(std430, set = 0, binding = kBindActiveCells) readonly buffer ActiveCells { uint active_cells[]; };
layout(set = 0, binding = kBindAlbedo, rgba8) uniform image2D gbuffer_albedo;
layout(set = 0, binding = kBindNormal, rgba16f) uniform image2D gbuffer_normal;
layout(set = 0, binding = kBindCell, r32ui) uniform uimage2D gbuffer_cell;
layout(set = 0, binding = kBindDepth) uniform sampler2D gbuffer_depth;     // D32, read with texelFetch
layout(set = 0, binding = kBindAo, r32f) uniform image2D ao_image;
layout(set = 0, binding = kBindAoHalf, r32f) uniform image2D ao_half_image;  // (w+1)/2 x (h+1)/2
layout(set = 0, binding = kBindHdr, rgba32f) uniform image2D hdr_image;
layout(set = 0, binding = kBindLdr, rgba8) uniform image2D ldr_image;
layout(std430, set = 0, binding = kBindExposure) buffer Exposure { float exposure_value[]; };  // [0]: this frame's
// Per linked view of the frame (index = the transform in the g-buffer cell id, kCellLinkShift).
layout(std430, set = 0, binding = kBindLinkViews) readonly buffer LinkViews { GpuLinkView link_views[]; };

#endif
