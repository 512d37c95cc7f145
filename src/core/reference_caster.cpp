// The configurable caster (see the header). Sections: the primary ray in scalar T; the nearest hit in T;
// the 2D and 3D loops; dispatch and names.
#include "raycam/reference_caster.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <stdexcept>
#include <vector>

namespace raycam {

namespace {

template <int D, class T>
glm::vec<D, T> rounded(const glm::vec<D, double>& v) {
  return glm::vec<D, T>(v);
}

// Objects rounded to T once per frame: centres in world coordinates or relative to the eye (the
// subtraction done in long double from the double inputs, then rounded, so only one rounding happens).
template <int D, class T, class Object>
struct RoundedObjects {
  std::vector<glm::vec<D, T>> centres;
  std::vector<T> radii;
  RoundedObjects(const std::vector<Object>& objects, bool camera_relative, const glm::vec<D, double>& eye) {
    centres.reserve(objects.size());
    radii.reserve(objects.size());
    for (const Object& object : objects) {
      if (camera_relative) {
        glm::vec<D, T> relative;
        for (int i = 0; i < D; ++i) relative[i] = T((long double)object.centre[i] - (long double)eye[i]);
        centres.push_back(relative);
      } else {
        centres.push_back(rounded<D, T>(object.centre));
      }
      radii.push_back(T(object.radius));
    }
  }
};

// Exercise 2 in scalar T: P_k = M_d·P_k^0 (world) or L·(P_k^0 - E0) (relative to the eye); u_k normalised.
// For T = double in world coordinates these are exactly the core's operations (transform_point/_vector).
template <int D, class T, class Matrix>
void primary_ray(const Matrix& world_from_camera, const glm::vec<D, T>& canonical_pixel,
                 const glm::vec<D, T>& canonical_eye, bool camera_relative, glm::vec<D, T>& origin,
                 glm::vec<D, T>& direction) {
  using Homogeneous = glm::vec<D + 1, T>;
  const glm::vec<D, T> towards_pixel = canonical_pixel - canonical_eye;
  if (camera_relative) {
    origin = glm::vec<D, T>(world_from_camera * Homogeneous(towards_pixel, T(0)));
    direction = glm::normalize(origin);
  } else {
    origin = glm::vec<D, T>(world_from_camera * Homogeneous(canonical_pixel, T(1)));
    direction = glm::normalize(glm::vec<D, T>(world_from_camera * Homogeneous(towards_pixel, T(0))));
  }
}

template <int D, class T, class Object>
int nearest_id(const RoundedObjects<D, T, Object>& objects, const glm::vec<D, T>& origin,
               const glm::vec<D, T>& direction, IntersectFormula formula) {
  int id = -1;
  T best = kNoHit<T>;
  for (std::size_t i = 0; i < objects.centres.size(); ++i) {
    const T t = nearest_hit_t<D, T>(origin, direction, objects.centres[i], objects.radii[i], formula);
    if (t < best) {  // strict: ties keep the lower index, as the plain caster
      best = t;
      id = int(i);
    }
  }
  return id;
}

template <class Object>
glm::dvec3 colour_of(int id, const std::vector<Object>& objects, Rgb8 background) {
  return to_dvec3(id < 0 ? background : objects[std::size_t(id)].colour);
}

void require_samples(int spp) {
  if (spp < 1 || spp > kMaxSamplesPerPixel)
    throw std::invalid_argument("samples_per_pixel must be in [1, " + std::to_string(kMaxSamplesPerPixel) +
                                "], got " + std::to_string(spp));
}

int grid_side(int spp) {
  require_samples(spp);
  const int side = int(std::lround(std::sqrt(double(spp))));
  if (side * side != spp)
    throw std::invalid_argument("samples_per_pixel in 3D must be a perfect square (1, 4, 9, 16, ...), got " +
                                std::to_string(spp));
  return side;
}

}  // namespace

template <class T>
CoverageImage reference_cast_as(const Camera2D& camera, const Scene2D& scene,
                                const ReferenceOptions& options) {
  require_samples(options.samples_per_pixel);
  const int n = camera.pixel_count();
  const int spp = options.samples_per_pixel;
  const glm::mat<3, 3, T> m(camera.world_from_camera());
  const glm::vec<2, T> canonical_eye(T(0), T(1));
  const RoundedObjects<2, T, Circle> objects(scene.circles, options.camera_relative, camera.eye());
  // An odd count of strata puts the middle sample exactly on the pixel centre; reuse it for the id.
  const bool centre_is_a_sample = spp % 2 == 1;

  CoverageImage image;
  image.width = n;
  image.height = 1;
  image.ids.assign(std::size_t(n), -1);
  image.colours.assign(std::size_t(n), glm::dvec3(0.0));
  auto id_at = [&](double x) {
    glm::vec<2, T> origin, direction;
    primary_ray<2, T>(m, glm::vec<2, T>(T(x), T(0)), canonical_eye, options.camera_relative, origin,
                      direction);
    return nearest_id(objects, origin, direction, options.formula);
  };
  for (int k = 0; k < n; ++k) {
    const std::size_t column = std::size_t(camera.column_of_pixel(k));
    glm::dvec3 sum(0.0);
    for (int j = 0; j < spp; ++j) {
      // Stratum j of pixel k, sampled at its centre; for spp = 1 this is the core's -1 + (2k+1)/n exactly.
      const double x = -1.0 + (2.0 * k + double(2 * j + 1) / spp) / n;
      const int id = id_at(x);
      sum += colour_of(id, scene.circles, scene.background);
      if (centre_is_a_sample && 2 * j + 1 == spp) image.ids[column] = id;
    }
    image.colours[column] = sum / double(spp);
    if (!centre_is_a_sample) image.ids[column] = id_at(-1.0 + (2.0 * k + 1.0) / n);
  }
  return image;
}

template <class T>
CoverageImage reference_cast_as(const Camera3D& camera, const Scene3D& scene,
                                const ReferenceOptions& options) {
  const int side = grid_side(options.samples_per_pixel);
  const int columns = camera.columns(), rows = camera.rows();
  const glm::mat<4, 4, T> m(camera.world_from_camera());
  const glm::vec<3, T> canonical_eye(T(0), T(0), T(1));
  const RoundedObjects<3, T, Sphere> objects(scene.spheres, options.camera_relative, camera.eye());
  const bool centre_is_a_sample = side % 2 == 1;

  CoverageImage image;
  image.width = columns;
  image.height = rows;
  image.ids.assign(std::size_t(columns) * rows, -1);
  image.colours.assign(std::size_t(columns) * rows, glm::dvec3(0.0));
  auto id_at = [&](double x, double y) {
    glm::vec<3, T> origin, direction;
    primary_ray<3, T>(m, glm::vec<3, T>(T(x), T(y), T(0)), canonical_eye, options.camera_relative, origin,
                      direction);
    return nearest_id(objects, origin, direction, options.formula);
  };
  for (int row = 0; row < rows; ++row) {
    for (int column = 0; column < columns; ++column) {
      const std::size_t index = std::size_t(row) * columns + column;
      glm::dvec3 sum(0.0);
      for (int j = 0; j < side; ++j) {
        const double y = 1.0 - (2.0 * row + double(2 * j + 1) / side) / rows;  // row 0 at the top
        for (int i = 0; i < side; ++i) {
          const double x = -1.0 + (2.0 * column + double(2 * i + 1) / side) / columns;
          const int id = id_at(x, y);
          sum += colour_of(id, scene.spheres, scene.background);
          if (centre_is_a_sample && 2 * i + 1 == side && 2 * j + 1 == side) image.ids[index] = id;
        }
      }
      image.colours[index] = sum / double(side * side);
      if (!centre_is_a_sample)
        image.ids[index] = id_at(-1.0 + (2.0 * column + 1.0) / columns, 1.0 - (2.0 * row + 1.0) / rows);
    }
  }
  return image;
}

template CoverageImage reference_cast_as<float>(const Camera2D&, const Scene2D&, const ReferenceOptions&);
template CoverageImage reference_cast_as<double>(const Camera2D&, const Scene2D&, const ReferenceOptions&);
template CoverageImage reference_cast_as<long double>(const Camera2D&, const Scene2D&,
                                                      const ReferenceOptions&);
template CoverageImage reference_cast_as<float>(const Camera3D&, const Scene3D&, const ReferenceOptions&);
template CoverageImage reference_cast_as<double>(const Camera3D&, const Scene3D&, const ReferenceOptions&);
template CoverageImage reference_cast_as<long double>(const Camera3D&, const Scene3D&,
                                                      const ReferenceOptions&);

namespace {
template <class Camera, class Scene>
CoverageImage dispatch(const Camera& camera, const Scene& scene, const ReferenceOptions& options) {
  switch (options.scalar) {
    case Scalar::float32:
      return reference_cast_as<float>(camera, scene, options);
    case Scalar::float64:
      return reference_cast_as<double>(camera, scene, options);
    case Scalar::extended:
      return reference_cast_as<long double>(camera, scene, options);
  }
  throw std::invalid_argument("scalar: unknown value");
}
}  // namespace

bool needs_reference_caster(const ReferenceOptions& options, bool exact_bar) {
  return options.scalar != Scalar::float64 || options.samples_per_pixel != 1 || options.camera_relative ||
         exact_bar;
}

CoverageImage reference_cast(const Camera2D& camera, const Scene2D& scene, const ReferenceOptions& options) {
  return dispatch(camera, scene, options);
}
CoverageImage reference_cast(const Camera3D& camera, const Scene3D& scene, const ReferenceOptions& options) {
  return dispatch(camera, scene, options);
}

const char* scalar_name(Scalar scalar) {
  switch (scalar) {
    case Scalar::float32:
      return "float";
    case Scalar::float64:
      return "double";
    case Scalar::extended:
      return "long-double";
  }
  return "?";
}

const char* formula_name(IntersectFormula formula) {
  return formula == IntersectFormula::naive ? "naive" : "stable";
}

}  // namespace raycam
