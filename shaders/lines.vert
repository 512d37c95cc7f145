#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec4 colour;
uniform mat4 view_projection;
out vec4 line_colour;
void main() {
  line_colour = colour;
  gl_Position = view_projection * vec4(position, 1.0);
}
