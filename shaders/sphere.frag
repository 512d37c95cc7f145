#version 330 core
// Flat colour with a little Lambert shading, so that the observer sees shapes (the camera's image stays flat).
in vec3 world_normal;
in vec3 base_colour;
uniform vec3 light_direction;
out vec4 fragment;
void main() {
  float lambert = max(dot(normalize(world_normal), light_direction), 0.0);
  fragment = vec4(base_colour * (0.45 + 0.55 * lambert), 1.0);
}
