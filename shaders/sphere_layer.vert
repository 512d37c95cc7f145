#version 330 core
// One triangle over the whole target (no vertex buffer): the CPU-cast sphere layer (gl/sphere_layer.h).
void main() {
  vec2 corner = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
  gl_Position = vec4(corner, 0.0, 1.0);
}
