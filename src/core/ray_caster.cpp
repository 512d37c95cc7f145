#include "raycam/ray_caster.h"

#include <utility>

#include "footprint_caster.h"

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
}  // namespace

Hit nearest_hit(const std::vector<Circle>& circles, const Ray2D& ray, IntersectFormula formula) {
  return nearest_of(int(circles.size()), object_in(circles), ray, formula);
}

Hit nearest_hit(const std::vector<Sphere>& spheres, const Ray3D& ray, IntersectFormula formula) {
  return nearest_of(int(spheres.size()), object_in(spheres), ray, formula);
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
  if (options.method != CastMethod::plain && !plain_only(camera.mistakes())) {
    detail::cast_accelerated(camera, scene, out, options, work);
  } else {
    for (int row = 0; row < camera.rows(); ++row)
      for (int column = 0; column < camera.columns(); ++column) {
        const Hit hit = nearest_of(scene.size(), object_in(scene), camera.primary_ray(row, column),
                                   options.formula, camera.mistakes().no_t_min);
        const std::size_t index = out.index(row, column);
        out.ids[index] = hit.id;
        out.colours[index] = hit.id < 0 ? scene.background : scene.colour[std::size_t(hit.id)];
      }
    const long long rays = static_cast<long long>(camera.rows()) * camera.columns();
    work = CastStats{rays, rays * static_cast<long long>(scene.size()), 0, 0, 1};
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
