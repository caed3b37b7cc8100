#version 460
#extension GL_GOOGLE_include_directive : require
// G-buffer: albedo, a normal facing the viewer (single-sided surfaces show their front faces
// only, glTF's default; double-sided ones both), the surface's cell (the
// lighting passes use only that cell's probes and the lights that reach it). With
// kCountFragments (tests), every fragment also counts itself for its drawable.
#include "render_bindings.h"

layout(constant_id = 0) const bool kCountFragments = false;
layout(location = 0) in vec3 in_position_world;
layout(location = 1) in vec3 in_normal_world;
layout(location = 2) flat in vec4 in_albedo;
layout(location = 3) flat in uint in_drawable;
layout(location = 4) in vec2 in_uv;
layout(location = 5) flat in uint in_texture;
layout(location = 6) flat in uint in_faces;
layout(std430, set = 0, binding = kDrawBindCounts) buffer Counts { uint fragment_counts[]; };
// Every base-colour texture, one layer each, R8G8B8A8_SRGB: decoded to linear before the
// bilinear filter, REPEAT wrap (the scene format's rule, lintel/world.h).
layout(set = 0, binding = kDrawBindTextures) uniform sampler2DArray base_color_textures;
layout(push_constant) uniform Push { GBufferPush pc; };

layout(location = 0) out vec4 out_albedo;
layout(location = 1) out vec4 out_normal;
layout(location = 2) out uint out_cell;

void main() {
  // glTF doubleSided false: back faces are culled. Draws of both kinds share one indirect
  // multi-draw (the cull's commands), so the cull happens here rather than in the rasterizer state.
  // Front = counter-clockwise in glTF; the negative viewport height keeps that orientation, and a
  // mirroring transform reverses it.
  bool front = gl_FrontFacing != ((in_faces & kFaceMirrored) != 0u);
  bool double_sided = (in_faces & kFaceDoubleSided) != 0u;
  if (!double_sided && !front) discard;
  vec3 n = normalize(in_normal_world);
  // The side the eye sees is the side that is lit: a double-sided surface seen from behind turns
  // its normal to the eye (and a front face whose file normal disagrees with its winding too).
  if (dot(n, pc.eye_world.xyz - in_position_world) < 0.0) n = -n;
  vec3 albedo = in_albedo.rgb;
  if (in_texture != kNoTexture) albedo *= texture(base_color_textures, vec3(in_uv, float(in_texture))).rgb;
  out_albedo = vec4(albedo, 1.0);
  out_normal = vec4(n, 0.0);
  out_cell = floatBitsToUint(in_albedo.w);
  if (kCountFragments) atomicAdd(fragment_counts[in_drawable], 1u);
}
