#version 460
#extension GL_GOOGLE_include_directive : require
// G-buffer: albedo, a normal facing the viewer (single-sided surfaces show their front faces
// only, glTF's default; double-sided ones both), the surface's cell (the
// lighting passes use only that cell's probes and the lights that reach it). With
// kCountFragments (tests), every fragment also counts itself for its drawable.
#include "render_bindings.h"

layout(constant_id = 0) const bool kCountFragments = false;
// Whether this pipeline keeps fragments by the linked views' pyramids (GpuLinkClip). The plain
// view of a frame with no mirror or teleport in sight draws with a pipeline without them:
// lavapipe would run the pyramid tests for every fragment even where no view has one.
layout(constant_id = 1) const bool kLinkClip = true;
// Whether this pipeline culls back faces here, per drawable. The plain view of a frame whose
// drawables are all single-sided and unmirrored lets the rasterizer cull them instead: without a
// discard, lavapipe tests depth before the shader runs rather than after.
layout(constant_id = 2) const bool kFaceTest = true;
// Whether this pipeline drops the uncovered points of cut-outs (glTF alphaMode MASK) and the
// screen-door holes of see-through surfaces (BLEND): only where the scene has some, since a
// discard makes lavapipe test depth after the shader.
layout(constant_id = 3) const bool kAlphaTest = true;
// Whether this pipeline writes what surfaces give off by themselves (Mesh::emissive): only where
// the scene has some, since lavapipe would sample the emissive texture for every fragment.
layout(constant_id = 4) const bool kEmission = true;
layout(location = 0) in vec3 in_position_world;
layout(location = 1) in vec3 in_normal_world;
layout(location = 2) flat in vec4 in_albedo;
layout(location = 3) flat in uint in_drawable;
layout(location = 4) in vec2 in_uv;
layout(location = 5) flat in uint in_texture;
layout(location = 6) flat in uint in_faces;
layout(location = 7) flat in uint in_sampler;
layout(location = 8) in vec4 in_color;  // COLOR_0, interpolated (white without it)
layout(location = 9) flat in vec4 in_emission;  // rgb = Mesh::emissive; w = emissive texture layer (bits)
layout(std430, set = 0, binding = kDrawBindCounts) buffer Counts { uint fragment_counts[]; };
// Every base-colour texture, one layer each with its mip chain, R8G8B8A8_SRGB: decoded to linear
// before filtering; the sampler is trilinear with REPEAT (texture_upload.h). Read in base_color.glsl.
layout(set = 0, binding = kDrawBindTextures) uniform sampler2DArray base_color_textures;
// Mirrors and teleports: per view, the pyramid it keeps and those it gives up (GpuLinkClip, two
// texels each, kMaxLinkViews of them), then the pyramids' planes, a texel each (texel_view.h
// says why texels).
layout(set = 0, binding = kDrawBindLinkClip) uniform usamplerBuffer link_clip_texels;
vec4 clip_plane(uint k) { return uintBitsToFloat(texelFetch(link_clip_texels, int(2u * kMaxLinkViews + k))); }
layout(push_constant) uniform Push { GBufferPush pc; };

#include "base_color.glsl"

// Whether p lies in the pyramid whose run starts at `first` (header, then its planes).
bool in_pyramid(uint first, vec3 p) {
  uint n = texelFetch(link_clip_texels, int(2u * kMaxLinkViews + first)).x;
  for (uint i = 1u; i <= n; ++i) {
    vec4 plane = clip_plane(first + i);
    if (dot(plane.xyz, p) + plane.w < 0.0) return false;
  }
  return true;
}

// Camera draws only: whether view pc.link.x keeps this fragment (see GpuLinkClip).
bool kept_by_links(vec3 p) {
  GpuLinkClip c;
  c.keep = texelFetch(link_clip_texels, int(2u * pc.link.x));
  c.cut = texelFetch(link_clip_texels, int(2u * pc.link.x + 1u));
  if (c.keep.y != 0u && !in_pyramid(c.keep.x, p)) return false;
  if (pc.link.x != 0u &&
      (any(lessThan(gl_FragCoord.xy, pc.clip_rect_px.xy)) || any(greaterThan(gl_FragCoord.xy, pc.clip_rect_px.zw))))
    return false;
  uint k = c.cut.x;
  for (uint i = 0u; i < c.cut.y; ++i) {
    if (in_pyramid(k, p)) return false;
    k += texelFetch(link_clip_texels, int(2u * kMaxLinkViews + k)).x + 1u;
  }
  return true;
}

layout(location = 0) out vec4 out_albedo;
layout(location = 1) out vec4 out_normal;
layout(location = 2) out uint out_cell;
layout(location = 3) out vec4 out_emission;  // linear radiance the surface gives off (lighting adds it)

void main() {
  // The camera's views through mirrors and teleports (render_shared.h, GBufferPush, GpuLinkClip).
  if (kLinkClip && pc.link.y != 0u && !kept_by_links(in_position_world)) discard;
  // glTF doubleSided false: back faces are culled. Draws of both kinds share one indirect
  // multi-draw (the cull's commands), so the cull happens here rather than in the rasterizer state.
  // Front = counter-clockwise in glTF; the negative viewport height keeps that orientation, and a
  // mirroring transform reverses it.
  bool front = gl_FrontFacing != ((in_faces & kFaceMirrored) != 0u);
  bool double_sided = (in_faces & kFaceDoubleSided) != 0u;
  if (kFaceTest && !double_sided && !front) discard;
  vec4 texel = in_texture != kNoTexture ? sample_base_color(in_uv, float(in_texture), in_sampler) : vec4(1.0);
  if (kAlphaTest && texel.a * in_color.a < cutout_threshold(in_faces, gl_FragCoord.xy)) discard;
  vec3 n = normalize(in_normal_world);
  // The side the eye sees is the side that is lit: a double-sided surface seen from behind turns
  // its normal to the eye (and a front face whose file normal disagrees with its winding too).
  if (dot(n, pc.eye_world.xyz - in_position_world) < 0.0) n = -n;
  vec3 albedo = in_albedo.rgb * in_color.rgb * texel.rgb;
  out_albedo = vec4(albedo, 1.0);
  out_normal = vec4(n, 0.0);
  out_cell = floatBitsToUint(in_albedo.w);
  out_emission = vec4(0.0);
  if (kEmission) {
    // Emissive texels are colours like base colour ones (sRGB in the file, decoded), alpha unused.
    uint layer = floatBitsToUint(in_emission.w);
    vec3 e = layer != kNoTexture ? sample_base_color(in_uv, float(layer), in_sampler >> kSamplerEmissiveShift).rgb
                                 : vec3(1.0);
    out_emission = vec4(in_emission.rgb * e, 0.0);
  }
  if (kCountFragments && pc.link.x == 0u) atomicAdd(fragment_counts[in_drawable], 1u);  // linked ids index records
}
