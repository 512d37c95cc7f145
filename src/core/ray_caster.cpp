#include "raycam/ray_caster.h"

#include <stdexcept>
#include <type_traits>
#include <utility>

#include "footprint_caster.h"

namespace raycam {

namespace {
// Exercise 2: test every object, keep the nearest. Strict '<' keeps the lower index on a tie.
template <class Object, class Ray>
Hit nearest_of(const std::vector<Object>& objects, const Ray& ray, IntersectFormula formula) {
  Hit hit;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const double t = nearest_hit_t(ray.origin, ray.direction, objects[i].centre, objects[i].radius, formula);
    if (t < hit.t) hit = Hit{int(i), t};
  }
  return hit;
}

// The classic mistake no_t_min: the smaller root wins whatever its sign.
template <class Object, class Ray>
Hit nearest_of_any_sign(const std::vector<Object>& objects, const Ray& ray, IntersectFormula formula) {
  Hit hit{-1, kNoHit<double>};
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const double t = smaller_root_t(ray.origin, ray.direction, objects[i].centre, objects[i].radius, formula);
    if (t < hit.t) hit = Hit{int(i), t};
  }
  return hit;
}

template <class Object, class Ray>
Hit nearest_for(const ClassicMistakes& mistakes, const std::vector<Object>& objects, const Ray& ray,
                IntersectFormula formula) {
  return mistakes.no_t_min ? nearest_of_any_sign(objects, ray, formula) : nearest_of(objects, ray, formula);
}

template <class Scene>
void store(ColourMap& map, std::size_t index, const Hit& hit, const Scene& scene) {
  map.ids[index] = hit.id;
  if constexpr (std::is_same_v<Scene, Scene2D>)
    map.colours[index] = hit.id < 0 ? scene.background : scene.circles[std::size_t(hit.id)].colour;
  else
    map.colours[index] = hit.id < 0 ? scene.background : scene.spheres[std::size_t(hit.id)].colour;
}
}  // namespace

Hit nearest_hit(const std::vector<Circle>& circles, const Ray2D& ray, IntersectFormula formula) {
  return nearest_of(circles, ray, formula);
}

Hit nearest_hit(const std::vector<Sphere>& spheres, const Ray3D& ray, IntersectFormula formula) {
  return nearest_of(spheres, ray, formula);
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
      const Hit hit = nearest_for(camera.mistakes(), scene.circles, camera.primary_ray(k), options.formula);
      store(out, out.index(0, camera.column_of_pixel(k)), hit, scene);
    }
    work = CastStats{n, static_cast<long long>(n) * static_cast<long long>(scene.circles.size()), 0, 0, 1};
  }
  if (stats) *stats = work;
}

void cast_primary_rays(const Camera3D& camera, const Scene3D& scene, ColourMap& out, const CastOptions& options,
                       CastStats* stats) {
  out.resize(camera.columns(), camera.rows());
  CastStats work;
  if (options.method != CastMethod::plain && !plain_only(camera.mistakes())) {
    detail::cast_accelerated(camera, scene, out, options, work);
  } else {
    for (int row = 0; row < camera.rows(); ++row)
      for (int column = 0; column < camera.columns(); ++column)
        store(out, out.index(row, column),
              nearest_for(camera.mistakes(), scene.spheres, camera.primary_ray(row, column), options.formula),
              scene);
    const long long rays = static_cast<long long>(camera.rows()) * camera.columns();
    work = CastStats{rays, rays * static_cast<long long>(scene.spheres.size()), 0, 0, 1};
  }
  if (stats) *stats = work;
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

int project_spheres_only(const Camera3D& camera, const Scene3D& scene, const CastOptions& options) {
  return detail::project_visible(camera, scene, options);
}

}  // namespace raycam
