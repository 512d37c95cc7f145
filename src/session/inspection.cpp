#include "session/inspection.h"

#include <algorithm>

namespace raycam::session {

namespace {
// The object the caster put in this pixel, and t along the ray from the caster's formula. The reference
// caster (accuracy knobs) may round differently: then t can be "no hit" while the id says hit, and the
// views draw the ray to a far point in the object's colour.
template <class Ray, class Objects>
Hit hit_as_cast(const Lesson& state, const CastCache& cast, PixelIndex pixel, const Ray& ray, const Objects& objects) {
  Hit hit;
  if (pixel.row >= cast.map.height || pixel.column >= cast.map.width) return hit;
  hit.id = cast.map.id_at(pixel.row, pixel.column);
  if (hit.id < 0 || std::size_t(hit.id) >= objects.size()) return Hit{};
  const auto& object = objects[std::size_t(hit.id)];
  const IntersectFormula formula = state.accuracy.options.formula;
  // Under the no_t_min mistake the caster keeps the smaller root whatever its sign: a hit behind the origin.
  hit.t = state.mistakes.no_t_min
              ? smaller_root_t(ray.origin, ray.direction, object.centre, object.radius, formula)
              : nearest_hit_t(ray.origin, ray.direction, object.centre, object.radius, formula);
  return hit;
}
}  // namespace

InspectedRay inspect_pixel(const Lesson& state, const CastCache& cast, PixelIndex pixel) {
  InspectedRay out;
  out.pixel = pixel;
  std::visit(overloaded{[&](const View2D& view) {  // a pixel k of the bar, the plane z = 0 of the views
                          const Camera2D& camera = view.camera;
                          out.k = camera.pixel_of_column(pixel.column);
                          const glm::dvec2 p0 = camera.canonical_pixel(out.k);
                          const Ray2D ray = camera.primary_ray(out.k);
                          out.canonical_pixel = {p0, 0.0};
                          out.canonical_direction = {p0 - kCanonicalEye2D, 0.0};  // u_k^0 = P_k^0 - E0
                          out.origin = {ray.origin, 0.0};
                          out.direction = {ray.direction, 0.0};
                          out.hit = hit_as_cast(state, cast, pixel, ray, view.scene.circles);
                        },
                        [&](const View3D& view) {
                          const Camera3D& camera = view.camera;
                          const glm::dvec3 p0 = camera.canonical_pixel(pixel.row, pixel.column);
                          const Ray3D ray = camera.primary_ray(pixel.row, pixel.column);
                          out.canonical_pixel = p0;
                          out.canonical_direction = p0 - kCanonicalEye3D;
                          out.origin = ray.origin;
                          out.direction = ray.direction;
                          out.hit = hit_as_cast(state, cast, pixel, ray, view.scene.spheres);
                        }},
             state.view);
  return out;
}

std::optional<PixelIndex> active_pixel(const Lesson& state, const CastCache& cast) {
  std::optional<PixelIndex> pixel = state.hovered_pixel ? state.hovered_pixel : state.pinned_pixel;
  if (pixel && (pixel->column >= cast.map.width || pixel->row >= cast.map.height)) return std::nullopt;
  return pixel;
}

std::vector<InspectedRay> primary_ray_fan(const Lesson& state, const CastCache& cast, int max_rays) {
  std::vector<InspectedRay> fan;
  const int n = cast.map.width;
  if (n <= 0 || max_rays <= 0) return fan;
  const int stride = std::max(1, (n + max_rays - 1) / max_rays);
  const int row = cast.map.height / 2;
  for (int column = stride / 2; column < n; column += stride)
    fan.push_back(inspect_pixel(state, cast, {row, column}));
  return fan;
}

}  // namespace raycam::session
