// Direct light as the path-traced reference computes it (pathtrace/include/lintel/reference/path_tracer.h):
// KHR_lights_punctual intensities, the spec's range window and spot falloff, Lambert. Shadows from
// the shadow atlas with a hand-written bilinear PCF (texelFetch: lavapipe cannot filter depth), over
// the surface's cell's light list only (a light is listed in the cells its portal visibility
// reaches through open portals, so no other light is even looked at).
#ifndef LINTEL_LIGHTING_COMMON_GLSL
#define LINTEL_LIGHTING_COMMON_GLSL
#include "compute_bindings.glsl"

const float kPi = 3.14159265358979;

// Irradiance (before shadowing) at p with normal n; `to_light` returns the unit direction.
vec3 light_irradiance(GpuLight l, vec3 p, vec3 n, out vec3 to_light, out float dist) {
  uint type = uint(l.position_type.w);
  if (type == kLightDirectional) {
    to_light = -l.direction_range.xyz;
    dist = 1e30;
    return l.color.rgb * max(dot(n, to_light), 0.0);
  }
  vec3 v = l.position_type.xyz - p;
  dist = max(length(v), 1e-4);
  to_light = v / dist;
  float range = l.direction_range.w;
  float window = 1.0;
  if (range > 0.0) {
    float r = dist / range;
    window = clamp(1.0 - r * r * r * r, 0.0, 1.0);
    window *= window;
  }
  float e = window / (dist * dist) * max(dot(n, to_light), 0.0);
  if (type == kLightSpot) {
    float cd = dot(l.direction_range.xyz, -to_light);
    float a = clamp(cd * l.cone.x + l.cone.y, 0.0, 1.0);
    e *= a * a;
  }
  return l.color.rgb * e;
}

// Which shadow view of the light sees p: cube faces by the major axis (+X,-X,+Y,-Y,+Z,-Z).
uint shadow_face(GpuLight l, vec3 p) {
  if (l.shadow_view_count < 6u) return 0u;
  vec3 d = p - l.position_type.xyz;
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0u : 1u;
  if (a.y >= a.z) return d.y >= 0.0 ? 2u : 3u;
  return d.z >= 0.0 ? 4u : 5u;
}

// Fraction of the light that reaches p (1 lit .. 0 shadowed).
// `slot`: the light's first atlas layer this frame; kNoShadowSlot: no room, lit unshadowed.
float shadow_visibility(GpuLight l, uint slot, vec3 p, vec3 n, float dist) {
  if (slot == kNoShadowSlot) return 1.0;
  uint face = shadow_face(l, p);
  uint view = l.shadow_view + face;
  ivec3 size = textureSize(shadow_atlas, 0);
  bool ortho = uint(l.position_type.w) == kLightDirectional;
  // The sun: its fine view (the sunlit interiors) where it holds the point, else the coarse one.
  if (ortho && l.shadow_view_count == 2u) {
    vec4 c0 = load_shadow_view(view) * vec4(p, 1.0);
    if (any(greaterThan(abs(c0.xy), vec2(1.0 - 4.0 / float(size.x))))) {
      view += 1u;
      face = 1u;
    }
  }
  // Normal offset of about two texels at this distance: l.cone.z is the texel size per meter of
  // distance of a perspective view; an orthographic view's texel is 2 / (size x |row 0|).
  mat4 m = load_shadow_view(view);
  float texel = ortho ? 2.0 / (float(size.x) * length(vec3(m[0][0], m[1][0], m[2][0]))) : l.cone.z * dist;
  vec4 c = m * vec4(p + n * (2.0 * texel), 1.0);
  if (c.w <= 0.0) return 0.0;
  vec3 ndc = c.xyz / c.w;
  if (any(greaterThan(abs(ndc.xy), vec2(1.0))) || ndc.z > 1.0) return ortho ? 1.0 : 0.0;
  // The shadow pass draws with a negative viewport height, like the camera: row 0 is NDC y = +1.
  // Bilinear PCF: the four texels around the point, each compared, weighted by where the point
  // lies between their centres (what a LINEAR depth-compare sampler does in hardware; lavapipe
  // cannot filter depth, so texelFetch). Four fetches, branch-free: on lavapipe every tap of a
  // bigger kernel would be paid on every pixel, taken or not.
  vec2 t = vec2(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5) * vec2(size.xy) - 0.5;
  ivec2 base = ivec2(floor(t));
  vec2 f = t - vec2(base);
  // One gather at the four texels' shared corner reads them all (the sampler clamps to the edge,
  // as texelFetch of clamped coordinates did): x = (base.x, base.y + 1), y = base + 1,
  // z = (base.x + 1, base.y), w = base.
  vec4 d = textureGather(shadow_atlas, vec3((vec2(base) + 1.0) / vec2(size.xy), float(slot + face)), 0);
  vec4 lit = vec4(lessThanEqual(vec4(ndc.z), d + 1e-4));
  return mix(mix(lit.w, lit.z, f.x), mix(lit.x, lit.y, f.x), f.y);
}

// Direct irradiance at p (normal n) in `cell` (an active cell) from its light list; `shadowed_lum`
// and `unshadowed_lum` (for the shadow debug view) accumulate the luminance with and without shadows.
vec3 direct_irradiance(vec3 p, vec3 n, uint cell, out float shadowed_lum, out float unshadowed_lum) {
  vec3 e = vec3(0.0);
  shadowed_lum = 0.0;
  unshadowed_lum = 0.0;
  uvec2 list = active_light(cell);  // x = first entry, y = count
  // do-while, the test at the end: lavapipe runs a loop until its last lane leaves, and a test at
  // the top costs one more pass of the whole body with every lane masked off.
  if (list.y == 0u) return e;
  uint i = list.x;
  do {
    uvec2 entry = active_light(i);
    GpuLight l = load_light(entry.x);
    vec3 to_light;
    float dist;
    vec3 el = light_irradiance(l, p, n, to_light, dist);
    if (all(equal(el, vec3(0.0)))) continue;
    float v = shadow_visibility(l, entry.y, p, n, dist);
    float lum = dot(el, vec3(0.2126, 0.7152, 0.0722));
    shadowed_lum += lum * v;
    unshadowed_lum += lum;
    e += el * v;
  } while (++i < list.x + list.y);
  return e;
}

// ---- probes (SH L1 radiance, world directions) ----

// Irradiance from one probe's radiance SH for normal n (Ramamoorthi & Hanrahan 2001: the cosine
// lobe's band factors pi and 2 pi / 3), clamped at zero (L1 can ring negative).
vec3 probe_irradiance_one(uint probe, vec3 n) {
  const float y0 = 0.282095, y1 = 0.488603;
  vec3 c0, c1, c2, c3;
  load_probe_sh(probe, c0, c1, c2, c3);
  vec3 e = kPi * y0 * c0 + (2.0 * kPi / 3.0) * y1 * (c1 * n.y + c2 * n.z + c3 * n.x);
  return max(e, vec3(0.0));
}

// Trilinear over the 8 nearest probes of `cell` (its own grid only: no light crosses cells here),
// each weighted down the more it lies behind the surface (DDGI's smooth back-face weight, Majercik
// et al. 2019): a probe under a table top or beyond a thin wall saw another side of the surface.
vec3 probe_irradiance(uint cell, vec3 p_world, vec3 n) {
  GpuCellProbes cp = load_cell_probes(cell);
  vec3 pg = (cp.world_to_grid * vec4(p_world, 1.0)).xyz;
  vec3 ng = mat3(cp.world_to_grid) * n;  // the grid's frame is rigid
  vec3 g = clamp((pg - cp.origin_grid.xyz) / cp.step_grid.xyz, vec3(0.0), vec3(cp.dims.xyz) - 1.0);
  uvec3 g0 = uvec3(floor(g));
  uvec3 g1 = min(g0 + 1u, cp.dims.xyz - 1u);
  vec3 f = g - vec3(g0);
  vec3 e = vec3(0.0);
  float weights = 0.0;
  for (uint k = 0u; k < 8u; ++k) {
    uvec3 q = uvec3((k & 1u) != 0u ? g1.x : g0.x, (k & 2u) != 0u ? g1.y : g0.y, (k & 4u) != 0u ? g1.z : g0.z);
    vec3 w3 = mix(1.0 - f, f, vec3((k & 1u) != 0u, (k & 2u) != 0u, (k & 4u) != 0u));
    vec3 to_probe = cp.origin_grid.xyz + vec3(q) * cp.step_grid.xyz - pg;
    float facing = dot(to_probe, ng) * inversesqrt(max(dot(to_probe, to_probe), 1e-12)) * 0.5 + 0.5;
    float w = w3.x * w3.y * w3.z * (facing * facing + 0.2);
    if (w == 0.0) continue;
    uint index = cp.dims.w + q.x + cp.dims.x * (q.y + cp.dims.y * q.z);
    e += w * probe_irradiance_one(index, n);
    weights += w;
  }
  return weights > 0.0 ? e / weights : e;
}

#endif
