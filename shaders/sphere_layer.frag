#version 330 core
// The CPU-cast spheres, texel for pixel, with their depth: what sphere.frag would have drawn.
uniform sampler2D layer_colour;
uniform sampler2D layer_depth;
out vec4 fragment;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 colour = texelFetch(layer_colour, pixel, 0);
  if (colour.a == 0.0) discard;
  fragment = vec4(colour.rgb, 1.0);
  gl_FragDepth = texelFetch(layer_depth, pixel, 0).r;
}
