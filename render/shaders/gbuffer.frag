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
layout(location = 0) in vec3 in_position_world;
layout(location = 1) in vec3 in_normal_world;
layout(location = 2) flat in vec4 in_albedo;
layout(location = 3) flat in uint in_drawable;
layout(location = 4) in vec2 in_uv;
layout(location = 5) flat in uint in_texture;
layout(location = 6) flat in uint in_faces;
layout(location = 7) flat in uint in_sampler;
layout(location = 8) in vec3 in_color;  // COLOR_0, interpolated (white without it)
layout(std430, set = 0, binding = kDrawBindCounts) buffer Counts { uint fragment_counts[]; };
// Every base-colour texture, one layer each with its mip chain, R8G8B8A8_SRGB: decoded to linear
// before filtering; the sampler is trilinear with REPEAT (texture_upload.h).
layout(set = 0, binding = kDrawBindTextures) uniform sampler2DArray base_color_textures;
// Mirrors and teleports: per view, the pyramid it keeps and those it gives up (GpuLinkClip, two
// texels each, kMaxLinkViews of them), then the pyramids' planes, a texel each (texel_view.h
// says why texels).
layout(set = 0, binding = kDrawBindLinkClip) uniform usamplerBuffer link_clip_texels;
vec4 clip_plane(uint k) { return uintBitsToFloat(texelFetch(link_clip_texels, int(2u * kMaxLinkViews + k))); }
layout(push_constant) uniform Push { GBufferPush pc; };

// One axis of a glTF wrap mode, onto [0, 1] for the REPEAT sampler. Clamp keeps the coordinate
// half a texel (of `texels`) inside, so the bilinear footprint never reaches the other side.
// Mirrored repeat folds u into [0, 1], then clamps the same way: a true mirrored sampler blends
// the edge texel with its own mirror image there, which is the edge texel alone.
float wrap_axis(float u, uint mode, float texels) {
  if (mode == 2u) u = 1.0 - abs(mod(u, 2.0) - 1.0);
  if (mode != 0u) return clamp(u, 0.5 / texels, 1.0 - 0.5 / texels);
  return u;
}

// One mip level, wrapped, and for a nearest filter moved to its texel's centre (where the
// bilinear sample is that texel alone).
vec3 sample_level(vec2 uv, float layer, uint bits, int level, bool nearest) {
  vec2 texels = vec2(textureSize(base_color_textures, level).xy);
  uv = vec2(wrap_axis(uv.x, (bits >> kSamplerWrapSShift) & 3u, texels.x),
            wrap_axis(uv.y, (bits >> kSamplerWrapTShift) & 3u, texels.y));
  if (nearest) uv = (floor(uv * texels) + 0.5) / texels;
  return textureLod(base_color_textures, vec3(uv, layer), float(level)).rgb;
}

// The glTF sampler (kSampler* bits) on top of the trilinear REPEAT sampler: the level(s) from the
// LOD the hardware would use (magnification: LOD <= 0, the mag filter at level 0; minification:
// the min filter and mip mode), then one or two lookups. The default (repeat, trilinear) comes out
// as the sampler's own trilinear filter. One path for every sampler, no early return: lavapipe
// runs both sides of every branch, so a fast path for the default would cost more, not less.
vec3 sample_base_color(vec2 uv, float layer, uint bits) {
  int top = textureQueryLevels(base_color_textures) - 1;
  float lod = textureQueryLod(base_color_textures, uv).y;
  bool magnify = lod <= 0.0;
  bool nearest = (bits & (magnify ? kSamplerMagNearest : kSamplerMinNearest)) != 0u;
  uint mip = magnify ? 0u : (bits >> kSamplerMipShift) & 3u;  // 0 none (level 0), 1 nearest, 2 linear
  float l = clamp(lod, 0.0, float(top));
  int low = mip == 1u ? int(floor(l + 0.5)) : mip == 2u ? int(floor(l)) : 0;
  int high = mip == 2u ? min(low + 1, top) : low;
  float t = mip == 2u ? l - float(low) : 0.0;
  return mix(sample_level(uv, layer, bits, low, nearest), sample_level(uv, layer, bits, high, nearest), t);
}

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
  vec3 n = normalize(in_normal_world);
  // The side the eye sees is the side that is lit: a double-sided surface seen from behind turns
  // its normal to the eye (and a front face whose file normal disagrees with its winding too).
  if (dot(n, pc.eye_world.xyz - in_position_world) < 0.0) n = -n;
  vec3 albedo = in_albedo.rgb * in_color;
  if (in_texture != kNoTexture) albedo *= sample_base_color(in_uv, float(in_texture), in_sampler);
  out_albedo = vec4(albedo, 1.0);
  out_normal = vec4(n, 0.0);
  out_cell = floatBitsToUint(in_albedo.w);
  if (kCountFragments && pc.link.x == 0u) atomicAdd(fragment_counts[in_drawable], 1u);  // linked ids index records
}
