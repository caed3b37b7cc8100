// Direct light as the path-traced reference computes it (pathtrace/include/lintel/reference/path_tracer.h):
// KHR_lights_punctual intensities, the spec's range window and spot falloff, Lambert. Shadows from
// the shadow atlas with a hand-written 3x3 PCF (texelFetch: lavapipe cannot filter depth), over
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
  vec2 t = vec2(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5) * vec2(size.xy);
  ivec2 base = ivec2(floor(t));
  int layer = int(slot + face);
  // The 3 x 3 taps, corners first: where the four corners agree (most pixels: fully lit or fully
  // in shadow) the footprint is taken to be uniform and the other five taps are skipped. A texel
  // of the other kind strictly inside the corners (an occluder edge thinner than two texels) is
  // missed there; on lavapipe, whose SIMD groups skip a branch no lane takes, this halves the
  // shadow cost of the lighting pass.
  float corners = 0.0;
  for (int dy = -1; dy <= 1; dy += 2)
    for (int dx = -1; dx <= 1; dx += 2) {
      ivec2 q = clamp(base + ivec2(dx, dy), ivec2(0), size.xy - 1);
      corners += ndc.z <= texelFetch(shadow_atlas, ivec3(q, layer), 0).r + 1e-4 ? 1.0 : 0.0;
    }
  if (corners == 0.0 || corners == 4.0) return corners * 0.25;
  float lit = corners;
  for (int k = 0; k < 5; ++k) {
    ivec2 d = k == 4 ? ivec2(0) : ivec2(k == 0 ? -1 : k == 1 ? 1 : 0, k == 2 ? -1 : k == 3 ? 1 : 0);
    ivec2 q = clamp(base + d, ivec2(0), size.xy - 1);
    lit += ndc.z <= texelFetch(shadow_atlas, ivec3(q, layer), 0).r + 1e-4 ? 1.0 : 0.0;
  }
  return lit / 9.0;
}

// Direct irradiance at p (normal n) in `cell` (an active cell) from its light list; `shadowed_lum`
// and `unshadowed_lum` (for the shadow debug view) accumulate the luminance with and without shadows.
vec3 direct_irradiance(vec3 p, vec3 n, uint cell, out float shadowed_lum, out float unshadowed_lum) {
  vec3 e = vec3(0.0);
  shadowed_lum = 0.0;
  unshadowed_lum = 0.0;
  uvec2 list = active_lights[cell];  // x = first entry, y = count
  for (uint i = list.x; i < list.x + list.y; ++i) {
    GpuLight l = load_light(active_lights[i].x);
    vec3 to_light;
    float dist;
    vec3 el = light_irradiance(l, p, n, to_light, dist);
    if (all(equal(el, vec3(0.0)))) continue;
    float v = shadow_visibility(l, active_lights[i].y, p, n, dist);
    float lum = dot(el, vec3(0.2126, 0.7152, 0.0722));
    shadowed_lum += lum * v;
    unshadowed_lum += lum;
    e += el * v;
  }
  return e;
}

// ---- probes (SH L1 radiance, world directions) ----

// Irradiance from one probe's radiance SH for normal n (Ramamoorthi & Hanrahan 2001: the cosine
// lobe's band factors pi and 2 pi / 3), clamped at zero (L1 can ring negative).
vec3 probe_irradiance_one(uint probe, vec3 n) {
  const float y0 = 0.282095, y1 = 0.488603;
  vec3 e = kPi * y0 * load_probe_sh(probe, 0u) +
           (2.0 * kPi / 3.0) * y1 * (load_probe_sh(probe, 1u) * n.y + load_probe_sh(probe, 2u) * n.z +
                                     load_probe_sh(probe, 3u) * n.x);
  return max(e, vec3(0.0));
}

// Trilinear over the 8 nearest probes of `cell` (its own grid only: no light crosses cells here).
vec3 probe_irradiance(uint cell, vec3 p_world, vec3 n) {
  GpuCellProbes cp = load_cell_probes(cell);
  vec3 pg = (cp.world_to_grid * vec4(p_world, 1.0)).xyz;
  vec3 g = clamp((pg - cp.origin_grid.xyz) / cp.step_grid.xyz, vec3(0.0), vec3(cp.dims.xyz) - 1.0);
  uvec3 g0 = uvec3(floor(g));
  uvec3 g1 = min(g0 + 1u, cp.dims.xyz - 1u);
  vec3 f = g - vec3(g0);
  vec3 e = vec3(0.0);
  for (uint k = 0u; k < 8u; ++k) {
    uvec3 q = uvec3((k & 1u) != 0u ? g1.x : g0.x, (k & 2u) != 0u ? g1.y : g0.y, (k & 4u) != 0u ? g1.z : g0.z);
    vec3 w3 = mix(1.0 - f, f, vec3((k & 1u) != 0u, (k & 2u) != 0u, (k & 4u) != 0u));
    float w = w3.x * w3.y * w3.z;
    if (w == 0.0) continue;
    uint index = cp.dims.w + q.x + cp.dims.x * (q.y + cp.dims.y * q.z);
    e += w * probe_irradiance_one(index, n);
  }
  return e;
}

#endif
