// Raster test: draws each instance's mesh at its own screen slot, reading the instance id the
// cull wrote at gl_InstanceIndex (which includes the command's firstInstance), as a renderer does.
#version 460

layout(std430, set = 0, binding = 0) readonly buffer InstanceIds { uint instance_ids[]; };
layout(std430, set = 0, binding = 1) readonly buffer Offsets { vec4 offsets_ndc[]; };  // per instance

layout(location = 0) in vec3 position;
layout(location = 0) flat out uint v_instance;

void main() {
  uint id = instance_ids[gl_InstanceIndex];
  v_instance = id;
  gl_Position = vec4(position.xy + offsets_ndc[id].xy, 0.5, 1.0);
}
