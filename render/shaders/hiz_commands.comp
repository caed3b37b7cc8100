#version 460
#extension GL_GOOGLE_include_directive : require
// Two-phase hierarchical-Z occlusion, one stage: the phase's draw commands (hiz.glsl).
#include "hiz.glsl"

void main() { hiz_commands_stage(); }
