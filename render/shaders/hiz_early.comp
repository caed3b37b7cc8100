#version 460
#extension GL_GOOGLE_include_directive : require
// Two-phase hierarchical-Z occlusion, one stage: ids drawn last frame -> phase-1 ids (hiz.glsl).
#include "hiz.glsl"

void main() { hiz_early_stage(); }
