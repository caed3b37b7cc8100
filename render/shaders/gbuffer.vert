#version 460
#extension GL_GOOGLE_include_directive : require
// G-buffer and shadow vertex shader: the drawable comes from the cull's id buffer at
// gl_InstanceIndex (firstInstance = the draw group's base), so only the survivors are drawn.
#include "render_bindings.h"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv;
layout(location = 3) in vec4 in_color;  // COLOR_0 (white without it): multiplies the base colour and coverage
layout(std430, set = 0, binding = kDrawBindIds) readonly buffer Ids { uint ids[]; };
// GpuDrawInstance as 8 rgba32ui texels (render/src/texel_view.h says why texels).
layout(set = 0, binding = kDrawBindInstances) uniform usamplerBuffer instance_texels;
vec4 instance_texel(uint id, uint k) {
  return uintBitsToFloat(texelFetch(instance_texels, int(kDrawInstanceTexels * id + k)));
}
layout(push_constant) uniform Push { GBufferPush pc; };

layout(location = 0) out vec3 out_position_world;
layout(location = 1) out vec3 out_normal_world;
layout(location = 2) flat out vec4 out_albedo;  // w: the cell's bits
layout(location = 3) flat out uint out_drawable;
layout(location = 4) out vec2 out_uv;
layout(location = 5) flat out uint out_texture;  // layer of the base-colour texture, or kNoTexture
layout(location = 6) flat out uint out_faces;    // kFace* flags
layout(location = 7) flat out uint out_sampler;  // kSampler* bits
layout(location = 8) out vec4 out_color;
layout(location = 9) flat out vec4 out_emission;  // rgb = Mesh::emissive; w = emissive texture layer (bits)

void main() {
  uint id = ids[gl_InstanceIndex];
  GpuDrawInstance d;
  d.mesh_to_world = mat4(instance_texel(id, 0u), instance_texel(id, 1u), instance_texel(id, 2u), instance_texel(id, 3u));
  d.normal_to_world_c0 = instance_texel(id, 4u);
  d.normal_to_world_c1 = instance_texel(id, 5u);
  d.normal_to_world_c2 = instance_texel(id, 6u);
  d.albedo = instance_texel(id, 7u);
  d.emission = instance_texel(id, 8u);
  vec4 p = d.mesh_to_world * vec4(in_position, 1.0);
  out_position_world = p.xyz;
  out_normal_world = mat3(d.normal_to_world_c0.xyz, d.normal_to_world_c1.xyz, d.normal_to_world_c2.xyz) * in_normal;
  out_albedo = d.albedo;
  out_drawable = id;
  out_uv = in_uv;
  out_color = in_color;
  out_texture = floatBitsToUint(d.normal_to_world_c0.w);
  out_faces = floatBitsToUint(d.normal_to_world_c1.w);
  out_sampler = floatBitsToUint(d.normal_to_world_c2.w);
  out_emission = d.emission;
  gl_Position = pc.view_proj * p;
}
