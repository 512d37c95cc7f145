#version 330 core
// Ray-cast impostors: each sphere is one quad (instanced, 4 vertices), facing the observer's eye and just
// large enough to hold the sphere's silhouette; sphere.frag casts the eye's ray through each of its pixels.
// Four vertices a sphere instead of a mesh's hundreds: llvmpipe transforms every vertex on the CPU.
layout(location = 0) in vec2 corner;         // (±1, ±1)
layout(location = 1) in vec4 centre_radius;  // per instance
layout(location = 2) in vec3 colour;         // per instance, 0..1
uniform mat4 view_projection;
uniform mat4 clip_to_world;  // inverse(view_projection)
uniform vec3 observer_eye;
out vec3 world_position;
flat out vec4 sphere;
flat out vec3 base_colour;
void main() {
  sphere = centre_radius;
  base_colour = colour;
  vec3 towards = centre_radius.xyz - observer_eye;
  float distance2 = dot(towards, towards), r2 = centre_radius.w * centre_radius.w;
  if (distance2 <= r2 * 1.0001) {
    // The eye is inside (or on) the sphere: it fills the view; a quad over the whole screen, at the far plane.
    gl_Position = vec4(corner, 0.999999, 1.0);
    vec4 far_point = clip_to_world * vec4(corner, 1.0, 1.0);
    world_position = far_point.xyz / far_point.w;
    return;
  }
  // The tangent cone from the eye meets the plane through the centre, across the view, in a circle of radius
  // r·|towards| / sqrt(|towards|² − r²): the quad's half-width.
  vec3 w = towards * inversesqrt(distance2);
  vec3 u = normalize(cross(abs(w.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0), w));
  vec3 v = cross(w, u);
  float half_width = centre_radius.w * sqrt(distance2 / (distance2 - r2));
  world_position = centre_radius.xyz + half_width * (corner.x * u + corner.y * v);
  gl_Position = view_projection * vec4(world_position, 1.0);
}
