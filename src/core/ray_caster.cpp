#include "raycam/ray_caster.h"

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

template <class Object>
void store(ColourMap& map, std::size_t index, const Hit& hit, const std::vector<Object>& objects) {
  if (hit.id < 0) return;  // the map is pre-filled with the background
  map.ids[index] = hit.id;
  map.colours[index] = objects[std::size_t(hit.id)].colour;
}
}  // namespace

Hit nearest_hit(const std::vector<Circle>& circles, const Ray2D& ray, IntersectFormula formula) {
  return nearest_of(circles, ray, formula);
}

Hit nearest_hit(const std::vector<Sphere>& spheres, const Ray3D& ray, IntersectFormula formula) {
  return nearest_of(spheres, ray, formula);
}

ColourMap cast_primary_rays(const Camera2D& camera, const Scene2D& scene, const CastOptions& options,
                            CastStats* stats) {
  const int n = camera.pixel_count();
  ColourMap map(n, 1, scene.background);
  for (int k = 0; k < n; ++k) {
    const Hit hit = nearest_hit(scene.circles, camera.primary_ray(k), options.formula);
    store(map, map.index(0, camera.column_of_pixel(k)), hit, scene.circles);
  }
  if (stats)
    *stats = CastStats{n, static_cast<long long>(n) * static_cast<long long>(scene.circles.size()), 0};
  return map;
}

ColourMap cast_primary_rays(const Camera3D& camera, const Scene3D& scene, const CastOptions& options,
                            CastStats* stats) {
  ColourMap map(camera.columns(), camera.rows(), scene.background);
  for (int row = 0; row < camera.rows(); ++row) {
    for (int column = 0; column < camera.columns(); ++column) {
      const Hit hit = nearest_hit(scene.spheres, camera.primary_ray(row, column), options.formula);
      store(map, map.index(row, column), hit, scene.spheres);
    }
  }
  if (stats) {
    const long long rays = static_cast<long long>(camera.rows()) * camera.columns();
    *stats = CastStats{rays, rays * static_cast<long long>(scene.spheres.size()), 0};
  }
  return map;
}

}  // namespace raycam
