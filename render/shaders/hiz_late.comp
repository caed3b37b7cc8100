#version 460
#extension GL_GOOGLE_include_directive : require
// Two-phase hierarchical-Z occlusion, one stage: the occlusion test -> phase-2 ids, next frame's visibility (hiz.glsl).
#include "hiz.glsl"

void main() { hiz_late_stage(); }
