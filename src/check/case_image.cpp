#include "case_image.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <stdexcept>

#include "raycam/camera2d.h"
#include "raycam/camera3d.h"

namespace raycam::check {

namespace {
const CameraPreset& complete_camera(const SceneFile& file) {
  const CameraPreset& c = file.camera;
  const bool complete = c.target && c.d && c.theta_deg && c.df && c.res && c.size && (file.dimension == 2 || c.phi_deg);
  if (!complete) throw std::invalid_argument("camera: a check case needs target, d, theta, (phi), df, res and size");
  return c;
}

// What one centre ray sees, and whether double rounding could change it (kAmbiguityTolerance).
struct Verdict {
  int id = -1;
  bool ambiguous = false;
};

template <class Object, class Ray>
Verdict classify(const std::vector<Object>& objects, const Ray& ray, bool any_sign, IntersectFormula formula) {
  constexpr double tol = kAmbiguityTolerance;
  Verdict verdict;
  double best_t = kNoHit<double>, second_t = kNoHit<double>;
  double best_scale = 0, second_scale = 0;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const auto f = ray.origin - objects[i].centre;
    const double r = objects[i].radius;
    const double b = glm::dot(f, ray.direction), ff = glm::dot(f, f), c = ff - r * r;
    const double disc = formula == IntersectFormula::naive
                            ? b * b - c
                            : r * r - glm::dot(f - b * ray.direction, f - b * ray.direction);
    if (std::abs(disc) <= tol * (b * b + std::abs(c) + r * r)) verdict.ambiguous = true;  // grazing
    if (disc >= 0 && std::abs(c) <= tol * (ff + r * r)) verdict.ambiguous = true;         // starts on it
    const double t = any_sign ? smaller_root_t(ray.origin, ray.direction, objects[i].centre, r, formula)
                              : nearest_hit_t(ray.origin, ray.direction, objects[i].centre, r, formula);
    if (!(t < kNoHit<double>)) continue;
    const double scale = std::abs(t) + std::sqrt(ff) + r;
    if (t < best_t) {
      second_t = best_t;
      second_scale = best_scale;
      best_t = t;
      best_scale = scale;
      verdict.id = int(i);
    } else if (t < second_t) {
      second_t = t;
      second_scale = scale;
    }
  }
  if (second_t < kNoHit<double> && second_t - best_t <= tol * (best_scale + second_scale)) verdict.ambiguous = true;
  return verdict;
}

template <int N, class Matrix>
std::vector<double> row_major(const Matrix& m) {
  std::vector<double> out(static_cast<std::size_t>(N * N));
  for (int row = 0; row < N; ++row)
    for (int column = 0; column < N; ++column) out[std::size_t(row) * N + column] = m[column][row];
  return out;
}
}  // namespace

int object_count(const SceneFile& file) {
  return int(file.dimension == 2 ? file.scene2d.circles.size() : file.scene3d.spheres.size());
}

CaseImage render_case(const SceneFile& file, const ClassicMistakes& mistakes, IntersectFormula formula) {
  const CameraPreset& preset = complete_camera(file);
  const std::vector<double>& target = *preset.target;
  CaseImage image;
  image.dimension = file.dimension;
  if (file.dimension == 2) {
    if (target.size() != 2) throw std::invalid_argument("camera.target: expected 2 components in 2D");
    Camera2D camera((*preset.size).at(0));
    camera.set_res(*preset.res);
    camera.set_orbit({{target[0], target[1]}, *preset.d, glm::radians(*preset.theta_deg), *preset.df});
    camera.set_mistakes(mistakes);
    image.columns = camera.pixel_count();
    for (int k = 0; k < image.columns; ++k) {
      const Verdict v = classify(file.scene2d.circles, camera.primary_ray(k), mistakes.no_t_min, formula);
      image.ids.push_back(v.id);
      image.ambiguous.push_back(v.ambiguous);
    }
    image.md = row_major<3>(camera.world_from_camera());
    return image;
  }
  if (target.size() != 3 || preset.size->size() != 2)
    throw std::invalid_argument("camera: expected a 3-component target and size [columns, rows] in 3D");
  Camera3D camera((*preset.size)[0], (*preset.size)[1]);
  camera.set_res(*preset.res);
  camera.set_orbit({{target[0], target[1], target[2]},
                    *preset.d,
                    glm::radians(*preset.theta_deg),
                    glm::radians(*preset.phi_deg),
                    *preset.df});
  camera.set_mistakes(mistakes);
  image.rows = camera.rows();
  image.columns = camera.columns();
  for (int row = 0; row < image.rows; ++row)
    for (int column = 0; column < image.columns; ++column) {
      const Verdict v =
          classify(file.scene3d.spheres, camera.primary_ray(row, column), mistakes.no_t_min, formula);
      image.ids.push_back(v.id);
      image.ambiguous.push_back(v.ambiguous);
    }
  image.md = row_major<4>(camera.world_from_camera());
  return image;
}

}  // namespace raycam::check
