#version 330 core
// One unit-sphere mesh drawn once per sphere (instanced): world = centre + radius * vertex.
layout(location = 0) in vec3 unit_position;
layout(location = 1) in vec4 centre_radius;  // per instance
layout(location = 2) in vec3 colour;         // per instance, 0..1
uniform mat4 view_projection;
out vec3 world_normal;
out vec3 base_colour;
void main() {
  world_normal = unit_position;
  base_colour = colour;
  gl_Position = view_projection * vec4(centre_radius.xyz + centre_radius.w * unit_position, 1.0);
}
