// The game's depth-only draw of Lintel's cull output: instance i of a command is the id at
// ids[gl_InstanceIndex] (firstInstance = the group's base in the id buffer).
#version 460

layout(location = 0) in vec3 position_mesh;

layout(std430, set = 0, binding = 0) readonly buffer InstanceIds { uint ids[]; };
layout(std430, set = 0, binding = 1) readonly buffer MeshToWorld { mat4 mesh_to_world[]; };

layout(push_constant) uniform Camera { mat4 world_to_clip; };

void main() {
  gl_Position = world_to_clip * (mesh_to_world[ids[gl_InstanceIndex]] * vec4(position_mesh, 1.0));
}
