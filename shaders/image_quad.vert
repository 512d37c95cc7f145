#version 330 core
// The camera's colour map drawn on its screen square in the observer view.
layout(location = 0) in vec3 position;
layout(location = 1) in vec2 uv;
uniform mat4 view_projection;
out vec2 texture_uv;
void main() {
  texture_uv = uv;
  gl_Position = view_projection * vec4(position, 1.0);
}
