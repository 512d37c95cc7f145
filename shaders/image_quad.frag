#version 330 core
in vec2 texture_uv;
uniform sampler2D colour_map;
out vec4 fragment;
void main() { fragment = vec4(texture(colour_map, texture_uv).rgb, 1.0); }
