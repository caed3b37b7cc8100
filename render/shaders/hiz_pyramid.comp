#version 460
#extension GL_GOOGLE_include_directive : require
// Two-phase hierarchical-Z occlusion, one stage: one level of the depth pyramid (hiz.glsl).
#include "hiz.glsl"

void main() { hiz_pyramid_stage(); }
