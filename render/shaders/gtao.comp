#version 460
#extension GL_GOOGLE_include_directive : require
// Ground-truth ambient occlusion in the XeGTAO formulation (Jimenez et al. 2016, "Practical
// Realtime Strategies for Accurate Indirect Occlusion"; Intel's XeGTAO reference): per pixel,
// `slices` screen-space directions; along each, the highest horizon on both sides within a world
// radius (with a distance falloff); then the cosine-weighted visible arc between the two
// horizons, integrated analytically around the normal projected into the slice plane.
// Output: visibility in [0, 1], a multiplier on indirect light only. At half resolution
// (size.z = 2) one invocation computes the top-left pixel of each 2x2 block from the full-resolution
// depth and normals into ao_half_image, and ao_upsample.comp brings it back to full resolution.
#include "compute_bindings.glsl"

layout(local_size_x = kTileSize, local_size_y = kTileSize) in;
layout(push_constant) uniform Push { GtaoPush pc; };

const float kPi = 3.14159265358979;
const float kHalfPi = 1.57079632679490;

// View-space position of pixel `q` (clamped to the image) from the depth buffer.
vec3 view_position(ivec2 q) {
  q = clamp(q, ivec2(0), ivec2(pc.size.xy) - 1);
  float d = texelFetch(gbuffer_depth, q, 0).r;
  float n = pc.projection.z, f = pc.projection.w;
  float z = n * f / (f - d * (f - n));  // perspectiveRH_ZO: distance along -Z
  vec2 ndc = vec2((float(q.x) + 0.5) / float(pc.size.x) * 2.0 - 1.0, 1.0 - (float(q.y) + 0.5) / float(pc.size.y) * 2.0);
  return vec3(ndc * pc.projection.xy * z, -z);
}

// Interleaved gradient noise (Jimenez 2014): decorrelates slices between neighbouring pixels.
float ign(ivec2 p) { return fract(52.9829189 * fract(0.06711056 * float(p.x) + 0.00583715 * float(p.y))); }

// At half resolution the sample's view depth and cell go with it, for the upsample.
void store(ivec2 out_px, float visibility, float view_depth, uint cell) {
  if (pc.size.z == 2u)
    imageStore(ao_half_image, out_px, vec4(visibility, view_depth, uintBitsToFloat(cell), 0.0));
  else
    imageStore(ao_image, out_px, vec4(visibility));
}

void main() {
  ivec2 out_px = ivec2(gl_GlobalInvocationID.xy);
  uvec2 out_size = (pc.size.xy + pc.size.z - 1u) / pc.size.z;
  if (any(greaterThanEqual(uvec2(out_px), out_size))) return;
  ivec2 px = out_px * int(pc.size.z);  // inside the image: out_size rounds up, px = 2 * (out_size - 1) < size
  uint cell = imageLoad(gbuffer_cell, px).r;
  vec3 p = view_position(px);
  if (cell == kNoCell) {
    store(out_px, 1.0, -p.z, cell);
    return;
  }
  vec3 v = normalize(-p);
  vec3 n = normalize(mat3(pc.world_to_view) * imageLoad(gbuffer_normal, px).xyz);
  float radius = pc.params.x;
  uint slices = uint(pc.params.y), steps = uint(pc.params.z);
  float falloff_range = pc.params.w * radius;
  float falloff_from = radius - falloff_range;
  // Screen-space radius in pixels of a `radius`-meter sphere at this depth.
  float pixels_per_meter = 0.5 * float(pc.size.y) / (pc.projection.y * -p.z);
  float screen_radius = radius * pixels_per_meter;
  if (screen_radius < 1.0) {
    store(out_px, 1.0, -p.z, cell);
    return;
  }
  float noise_slice = ign(px), noise_step = fract(ign(px + ivec2(7, 3)) + 0.5);
  float visibility = 0.0;
  // The loops are do-while (the test at the end): lavapipe runs a loop until its last lane leaves,
  // and a test at the top costs one more pass of the body with every lane masked off.
  uint s = 0u;
  if (slices > 0u) do {
    float phi = (float(s) + noise_slice) / float(slices) * kPi;
    vec2 omega = vec2(cos(phi), -sin(phi));  // screen direction (y down in pixels)
    vec3 dir = vec3(omega.x, -omega.y, 0.0); // the same direction in view space (y up)
    vec3 ortho_dir = dir - dot(dir, v) * v;
    vec3 axis = normalize(cross(dir, v));
    vec3 proj_n = n - axis * dot(n, axis);
    float proj_n_len = length(proj_n);
    if (proj_n_len < 1e-4) continue;
    float sign_n = sign(dot(ortho_dir, proj_n));
    float cos_n = clamp(dot(proj_n, v) / proj_n_len, -1.0, 1.0);
    float angle_n = sign_n * acos(cos_n);
    float low0 = cos(angle_n + kHalfPi), low1 = cos(angle_n - kHalfPi);
    float h0c = low0, h1c = low1;
    uint k = 0u;
    if (steps > 0u) do {
      float t = (float(k) + noise_step) / float(steps);
      float offset_px = max(t * t * screen_radius, float(k + 1u));
      ivec2 d = ivec2(round(omega * offset_px));
      vec3 s0 = view_position(px + d) - p;
      vec3 s1 = view_position(px - d) - p;
      float l0 = length(s0), l1 = length(s1);
      float w0 = clamp((radius - l0) / max(falloff_range, 1e-4), 0.0, 1.0);
      float w1 = clamp((radius - l1) / max(falloff_range, 1e-4), 0.0, 1.0);
      if (falloff_from >= radius) { w0 = l0 < radius ? 1.0 : 0.0; w1 = l1 < radius ? 1.0 : 0.0; }
      float c0 = l0 > 1e-5 ? dot(s0 / l0, v) : low0;
      float c1 = l1 > 1e-5 ? dot(s1 / l1, v) : low1;
      h0c = max(h0c, mix(low0, c0, w0));
      h1c = max(h1c, mix(low1, c1, w1));
    } while (++k < steps);
    // XeGTAO names side 0 the +omega side and integrates h0 = -acos(horizon on -omega),
    // h1 = acos(horizon on +omega) around the projected normal's angle.
    float h0 = -acos(clamp(h1c, -1.0, 1.0));
    float h1 = acos(clamp(h0c, -1.0, 1.0));
    h0 = angle_n + clamp(h0 - angle_n, -kHalfPi, kHalfPi);
    h1 = angle_n + clamp(h1 - angle_n, -kHalfPi, kHalfPi);
    float sin_n = sin(angle_n);
    float arc0 = (cos_n + 2.0 * h0 * sin_n - cos(2.0 * h0 - angle_n)) * 0.25;
    float arc1 = (cos_n + 2.0 * h1 * sin_n - cos(2.0 * h1 - angle_n)) * 0.25;
    visibility += proj_n_len * (arc0 + arc1);
  } while (++s < slices);
  visibility = slices > 0u ? clamp(visibility / float(slices), 0.0, 1.0) : 1.0;
  store(out_px, visibility, -p.z, cell);
}
