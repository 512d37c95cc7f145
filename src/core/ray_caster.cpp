#include "raycam/ray_caster.h"

#include <cmath>
#include <utility>
#include <variant>

#include "core/footprint_caster.h"

namespace raycam {

namespace {
// Exercise 2: test every object, keep the nearest. Strict '<' keeps the lower index on a tie. object(i)
// gives object i's centre and radius. The classic mistake no_t_min (any_sign): the smaller root wins
// whatever its sign.
template <class Object, class Ray>
Hit nearest_of(int count, Object object, const Ray& ray, IntersectFormula formula, bool any_sign = false) {
  Hit hit;
  for (int i = 0; i < count; ++i) {
    const auto [centre, radius] = object(i);
    const double t = any_sign ? smaller_root_t(ray.origin, ray.direction, centre, radius, formula)
                              : nearest_hit_t(ray.origin, ray.direction, centre, radius, formula);
    if (t < hit.t) hit = Hit{i, t};
  }
  return hit;
}

template <class Object>
auto object_in(const std::vector<Object>& objects) {
  return [&objects](int i) { return std::make_pair(objects[std::size_t(i)].centre, objects[std::size_t(i)].radius); };
}
auto object_in(const PackedScene3D& scene) {
  return [&scene](int i) { return std::make_pair(scene.centre(i), scene.radius[std::size_t(i)]); };
}

// A ray and a plane: t = (point - origin)·normal / (direction·normal). A ray along the plane (0 below) never
// hits it, as a ray that grazes nothing; t < 0 is behind the eye, refused as for spheres unless any_sign.
double plane_hit_t(const Plane& plane, const Ray3D& ray, bool any_sign) {
  const double along = glm::dot(ray.direction, plane.normal);
  if (along == 0.0) return kNoHit<double>;
  const double t = glm::dot(plane.point - ray.origin, plane.normal) / along;
  return t >= 0.0 || (any_sign && std::isfinite(t)) ? t : kNoHit<double>;
}

// The other kinds after the spheres, by the same rule: strictly nearer wins, so a tie keeps the lower id
// (every sphere's id is lower than every shape's). `first_id` is the spheres' count.
Hit nearer_shape(Hit hit, const std::vector<Shape3D>& shapes, int first_id, const Ray3D& ray, bool any_sign) {
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    const double t = std::visit([&](const Plane& plane) { return plane_hit_t(plane, ray, any_sign); }, shapes[k]);
    if (t < hit.t) hit = Hit{first_id + int(k), t};
  }
  return hit;
}

Rgb8 colour_of(const Shape3D& shape) {
  return std::visit([](const Plane& plane) { return plane.colour; }, shape);
}
}  // namespace

Hit nearest_hit(const std::vector<Circle>& circles, const Ray2D& ray, IntersectFormula formula) {
  return nearest_of(int(circles.size()), object_in(circles), ray, formula);
}

Hit nearest_hit(const std::vector<Sphere>& spheres, const Ray3D& ray, IntersectFormula formula) {
  return nearest_of(int(spheres.size()), object_in(spheres), ray, formula);
}

Hit nearest_hit(const Scene3D& scene, const Ray3D& ray, IntersectFormula formula) {
  return nearer_shape(nearest_hit(scene.spheres, ray, formula), scene.shapes, int(scene.spheres.size()), ray, false);
}

namespace {
// The accelerated casters assume the camera's rays are the right ones: pixel centres, unit directions from
// the screen, t ≥ 0. The classic mistakes that change that are on-screen lessons: the plain loop. Those that
// only build another M_d or n keep the accelerated casters (tests/core/test_classic_mistakes.cpp).
bool plain_only(const ClassicMistakes& mistakes) { return !mistakes_change_only_placement(mistakes); }
}  // namespace

void cast_primary_rays(const Camera2D& camera, const Scene2D& scene, ColourMap& out, const CastOptions& options,
                       CastStats* stats) {
  const int n = camera.pixel_count();
  out.resize(n, 1);
  CastStats work;
  if (options.method != CastMethod::plain && !plain_only(camera.mistakes())) {
    detail::cast_accelerated(camera, scene, out, options, work);
  } else {
    for (int k = 0; k < n; ++k) {
      const Hit hit = nearest_of(int(scene.circles.size()), object_in(scene.circles), camera.primary_ray(k),
                                 options.formula, camera.mistakes().no_t_min);
      const std::size_t index = out.index(0, camera.column_of_pixel(k));
      out.ids[index] = hit.id;
      out.colours[index] = hit.id < 0 ? scene.background : scene.circles[std::size_t(hit.id)].colour;
    }
    work = CastStats{n, static_cast<long long>(n) * static_cast<long long>(scene.circles.size()), 0, 0, 1};
  }
  if (stats) *stats = work;
}

void cast_primary_rays(const Camera3D& camera, const PackedScene3D& scene, ColourMap& out,
                       const CastOptions& options, CastStats* stats) {
  out.resize(camera.columns(), camera.rows());
  CastStats work;
  // The fast casters know spheres only: a scene with another kind of object is the plain loop's.
  if (options.method != CastMethod::plain && !plain_only(camera.mistakes()) && scene.shapes.empty()) {
    detail::cast_accelerated(camera, scene, out, options, work);
  } else {
    const bool any_sign = camera.mistakes().no_t_min;
    for (int row = 0; row < camera.rows(); ++row)
      for (int column = 0; column < camera.columns(); ++column) {
        const Ray3D ray = camera.primary_ray(row, column);
        const Hit hit = nearer_shape(nearest_of(scene.size(), object_in(scene), ray, options.formula, any_sign),
                                     scene.shapes, scene.size(), ray, any_sign);
        const std::size_t index = out.index(row, column);
        out.ids[index] = hit.id;
        out.colours[index] = hit.id < 0                ? scene.background
                             : hit.id < scene.size()   ? scene.colour[std::size_t(hit.id)]
                                                       : colour_of(scene.shapes[std::size_t(hit.id - scene.size())]);
      }
    const long long rays = static_cast<long long>(camera.rows()) * camera.columns();
    work = CastStats{rays, rays * static_cast<long long>(scene.size() + int(scene.shapes.size())), 0, 0, 1};
  }
  if (stats) *stats = work;
}

void cast_primary_rays(const Camera3D& camera, const Scene3D& scene, ColourMap& out, const CastOptions& options,
                       CastStats* stats) {
  thread_local PackedScene3D packed;  // the calling thread's, reused: no allocation when the size is unchanged
  packed.pack(scene);
  cast_primary_rays(camera, packed, out, options, stats);
}

ColourMap cast_primary_rays(const Camera2D& camera, const Scene2D& scene, const CastOptions& options,
                            CastStats* stats) {
  ColourMap map;
  cast_primary_rays(camera, scene, map, options, stats);
  return map;
}

ColourMap cast_primary_rays(const Camera3D& camera, const Scene3D& scene, const CastOptions& options,
                            CastStats* stats) {
  ColourMap map;
  cast_primary_rays(camera, scene, map, options, stats);
  return map;
}

namespace {
constexpr std::pair<CastMethod, const char*> kMethodNames[] = {
    {CastMethod::automatic, "automatic"}, {CastMethod::plain, "plain"},   {CastMethod::culled, "culled"},
    {CastMethod::footprint, "footprint"}, {CastMethod::binned, "binned"},
};
}  // namespace

const char* cast_method_name(CastMethod method) {
  for (const auto& [value, name] : kMethodNames)
    if (value == method) return name;
  return "?";
}

std::optional<CastMethod> cast_method_named(std::string_view name) {
  for (const auto& [value, known] : kMethodNames)
    if (name == known) return value;
  return std::nullopt;
}

int project_spheres_only(const Camera3D& camera, const PackedScene3D& scene, const CastOptions& options) {
  return detail::project_visible(camera, scene, options);
}

}  // namespace raycam
