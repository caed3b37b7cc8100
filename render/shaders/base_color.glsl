// The base colour texture as the g-buffer and the shadow maps read it: the glTF sampler on top of
// the trilinear REPEAT sampler, rgb and alpha (alpha for cut-outs: kFaceAlphaMask). Needs
// `base_color_textures` (every base-colour texture, one layer each with its mip chain,
// R8G8B8A8_SRGB: decoded to linear before filtering; alpha is linear) declared before it.

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
vec4 sample_level(vec2 uv, float layer, uint bits, int level, bool nearest) {
  vec2 texels = vec2(textureSize(base_color_textures, level).xy);
  uv = vec2(wrap_axis(uv.x, (bits >> kSamplerWrapSShift) & 3u, texels.x),
            wrap_axis(uv.y, (bits >> kSamplerWrapTShift) & 3u, texels.y));
  if (nearest) uv = (floor(uv * texels) + 0.5) / texels;
  return textureLod(base_color_textures, vec3(uv, layer), float(level));
}

// The glTF sampler (kSampler* bits) on top of the trilinear REPEAT sampler: the level(s) from the
// LOD the hardware would use (magnification: LOD <= 0, the mag filter at level 0; minification:
// the min filter and mip mode), then one or two lookups. The default (repeat, trilinear) comes out
// as the sampler's own trilinear filter. One path for every sampler, no early return: lavapipe
// runs both sides of every branch, so a fast path for the default would cost more, not less.
vec4 sample_base_color(vec2 uv, float layer, uint bits) {
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

// The 4 x 4 ordered (Bayer) dither at a pixel: 16 thresholds (k + 0.5) / 16, each once per tile.
float dither_4x4(vec2 frag_coord) {
  uvec2 p = uvec2(frag_coord) & 3u;
  uint k = ((p.x ^ p.y) & 1u) << 3 | (p.y & 1u) << 2 | ((p.x ^ p.y) & 2u) | (p.y & 2u) >> 1;
  return (float(k) + 0.5) / 16.0;
}

// The alpha below which a drawable with face bits `faces` has no surface at pixel `frag_coord`:
// for a cut-out (kFaceAlphaMask), its cutoff over its base colour's alpha, a half float from bit
// kFaceAlphaThresholdShift (render_scene.cpp); for a see-through surface (kFaceAlphaBlend), the
// pixel's dither over its base colour's alpha (screen-door transparency); -1 (nothing is cut
// away) otherwise. Compared with the texture's alpha (1 without a texture) times the
// interpolated COLOR_0 alpha.
float cutout_threshold(uint faces, vec2 frag_coord) {
  if ((faces & (kFaceAlphaMask | kFaceAlphaBlend)) == 0u) return -1.0;
  float t = unpackHalf2x16(faces >> kFaceAlphaThresholdShift).x;
  return (faces & kFaceAlphaBlend) != 0u ? t * dither_4x4(frag_coord) : t;
}
