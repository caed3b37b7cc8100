#version 460
#extension GL_GOOGLE_include_directive : require
// Shadow maps of a scene with cut-outs (glTF alphaMode MASK) or see-through surfaces (BLEND): depth
// only, but a cut-out's uncovered points cast no shadow, as the camera sees through them
// (gbuffer.frag), and a see-through surface casts its shadow through the same screen-door dither
// (the shadow filter averages it to a partial shadow). Scenes without either render their shadow
// maps with no fragment shader at all.
#include "render_bindings.h"

layout(location = 4) in vec2 in_uv;
layout(location = 5) flat in uint in_texture;
layout(location = 6) flat in uint in_faces;
layout(location = 7) flat in uint in_sampler;
layout(location = 8) in vec4 in_color;  // COLOR_0: its alpha multiplies the coverage
layout(set = 0, binding = kDrawBindTextures) uniform sampler2DArray base_color_textures;

#include "base_color.glsl"

void main() {
  float alpha = in_texture != kNoTexture ? sample_base_color(in_uv, float(in_texture), in_sampler).a : 1.0;
  if (alpha * in_color.a < cutout_threshold(in_faces, gl_FragCoord.xy)) discard;
}
