#version 330 core
// The observer's ray through this pixel against the impostor's sphere: the nearest hit in front of the eye
// (the far side when the eye is inside), its depth written for the depth test; Lambert shading as before.
in vec3 world_position;
flat in vec4 sphere;
flat in vec3 base_colour;
uniform mat4 view_projection;
uniform vec3 observer_eye;
uniform vec3 light_direction;
out vec4 fragment;
void main() {
  vec3 direction = normalize(world_position - observer_eye);
  vec3 f = observer_eye - sphere.xyz;
  float b = dot(f, direction);
  // r² − |f − b·direction|² instead of b² − (|f|² − r²): in float the latter cancels at a distance.
  vec3 closest = f - b * direction;
  float discriminant = sphere.w * sphere.w - dot(closest, closest);
  if (discriminant < 0.0) discard;
  float inside = dot(f, f) < sphere.w * sphere.w ? 1.0 : -1.0;
  float t = -b + inside * sqrt(discriminant);
  if (t < 0.0) discard;
  vec3 hit = observer_eye + t * direction;
  vec4 clip = view_projection * vec4(hit, 1.0);
  gl_FragDepth = 0.5 * clip.z / clip.w + 0.5;
  vec3 normal = (hit - sphere.xyz) / sphere.w;
  float lambert = max(dot(normal, light_direction), 0.0);
  fragment = vec4(base_colour * (0.45 + 0.55 * lambert), 1.0);
}
