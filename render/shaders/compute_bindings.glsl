// The one descriptor set every renderer compute pass binds (set 0): each pass reads the bindings
// it needs. One layout keeps the C++ side to one set, one pipeline layout and one update.
#ifndef LINTEL_COMPUTE_BINDINGS_GLSL
#define LINTEL_COMPUTE_BINDINGS_GLSL
#include "lintel/render/render_shared.h"

layout(std430, set = 0, binding = 0) readonly buffer Lights { GpuLight lights[]; };
// Per active light: x = light index, y = its first shadow-atlas slot this frame or kNoShadowSlot.
layout(std430, set = 0, binding = 1) readonly buffer ActiveLights { uvec2 active_lights[]; };
layout(std430, set = 0, binding = 2) readonly buffer ShadowViews { mat4 shadow_views[]; };
layout(std430, set = 0, binding = 3) readonly buffer LightMasks { uint light_masks[]; };
layout(set = 0, binding = 4) uniform sampler2DArray shadow_atlas;  // D32, read with texelFetch
layout(std430, set = 0, binding = 5) readonly buffer CellProbes { GpuCellProbes cell_probes[]; };
layout(std430, set = 0, binding = 6) buffer Probes { GpuProbe probes[]; };
layout(std430, set = 0, binding = 7) readonly buffer Surfels { GpuSurfel surfels[]; };
layout(std430, set = 0, binding = 8) buffer SurfelRadiance { vec4 surfel_radiance[]; };
layout(std430, set = 0, binding = 9) readonly buffer ActiveCells { uint active_cells[]; };
layout(set = 0, binding = 10, rgba8) uniform image2D gbuffer_albedo;
layout(set = 0, binding = 11, rgba16f) uniform image2D gbuffer_normal;
layout(set = 0, binding = 12, r32ui) uniform uimage2D gbuffer_cell;
layout(set = 0, binding = 13) uniform sampler2D gbuffer_depth;     // D32, read with texelFetch
layout(set = 0, binding = 14, r32f) uniform image2D ao_image;
layout(set = 0, binding = 15, rgba32f) uniform image2D hdr_image;
layout(set = 0, binding = 16, rgba8) uniform image2D ldr_image;
layout(std430, set = 0, binding = 17) buffer Exposure { float exposure_value[]; };  // [0]: this frame's

#endif
