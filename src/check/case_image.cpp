#include "check/case_image.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <type_traits>

#include "raycam/camera2d.h"
#include "raycam/camera3d.h"
#include "raycam/view_setup.h"

namespace raycam::check {

namespace {
// The case's camera in each dimension, from its preset: a case has every field (3D's also phi).
bool has_common_fields(const CameraPreset& c) { return c.target && c.d && c.theta_deg && c.df && c.res && c.size; }
const char* const kIncompleteCamera = "camera: a check case needs target, d, theta, (phi), df, res and size";

Camera2D case_camera(const CameraPreset& c, const Scene2D&) {
  if (!has_common_fields(c)) throw std::invalid_argument(kIncompleteCamera);
  if (c.target->size() != 2) throw std::invalid_argument("camera.target: expected 2 components in 2D");
  return camera2d_from_preset(c);
}
Camera3D case_camera(const CameraPreset& c, const Scene3D&) {
  if (!has_common_fields(c) || !c.phi_deg) throw std::invalid_argument(kIncompleteCamera);
  if (c.target->size() != 3 || c.size->size() != 2)
    throw std::invalid_argument("camera: expected a 3-component target and size [columns, rows] in 3D");
  return camera3d_from_preset(c);
}

// The centre ray of a pixel given by its protocol index.
Ray2D ray_at(const Camera2D& camera, std::size_t index) { return camera.primary_ray(int(index)); }
Ray3D ray_at(const Camera3D& camera, std::size_t index) {
  const std::size_t columns = std::size_t(camera.columns());
  return camera.primary_ray(int(index / columns), int(index % columns));
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
  return visit_scene(file, [](const auto& scene) { return int(objects_of(scene).size()); });
}

namespace {
// The case's camera with the mistakes on, and what one pixel (protocol index) sees, over the case's scene.
template <class Scene>
class CaseCamera {
 public:
  CaseCamera(const Scene& scene, const CameraPreset& preset, const ClassicMistakes& mistakes, IntersectFormula formula)
      : scene_(scene), camera_(case_camera(preset, scene)), any_sign_(mistakes.no_t_min), formula_(formula) {
    camera_.set_mistakes(mistakes);
    const auto& m = camera_.world_from_camera();
    md_ = row_major<std::decay_t<decltype(m)>::length()>(m);
  }
  int rows() const { return image_rows(camera_); }
  int columns() const { return image_columns(camera_); }
  const std::vector<double>& md() const { return md_; }
  Verdict at(std::size_t index) const { return classify(objects_of(scene_), ray_at(camera_, index), any_sign_, formula_); }

 private:
  const Scene& scene_;
  decltype(case_camera(CameraPreset{}, Scene{})) camera_;
  bool any_sign_;
  IntersectFormula formula_;
  std::vector<double> md_;
};
}  // namespace

CaseImage render_case(const SceneFile& file, const ClassicMistakes& mistakes, IntersectFormula formula) {
  return visit_scene(file, [&](const auto& scene) {
    const CaseCamera camera(scene, file.camera, mistakes, formula);
    CaseImage image;
    image.dimension = file.dimension;
    image.rows = camera.rows();
    image.columns = camera.columns();
    image.md = camera.md();
    const std::size_t pixels = std::size_t(image.rows) * std::size_t(image.columns);
    for (std::size_t i = 0; i < pixels; ++i) {
      const Verdict v = camera.at(i);
      image.ids.push_back(v.id);
      image.ambiguous.push_back(v.ambiguous);
    }
    return image;
  });
}

bool case_reproduces(const SceneFile& file, const ClassicMistakes& mistakes, IntersectFormula formula,
                     int rows, int columns, const std::vector<int>& ids, const std::vector<double>* md) {
  return visit_scene(file, [&](const auto& scene) {
    const CaseCamera camera(scene, file.camera, mistakes, formula);
    if (camera.rows() != rows || camera.columns() != columns) return false;
    if (md && !md_matches(*md, camera.md())) return false;
    // Pixels in a scattered order (a stride prime to their count): a wrong candidate usually fails within a
    // few pixels, instead of after a whole background row.
    const std::size_t pixels = std::size_t(rows) * std::size_t(columns);
    const std::size_t stride = pixels % 7919 != 0 ? 7919 : 1;
    for (std::size_t n = 0, i = 0; n < pixels; ++n, i = (i + stride) % pixels) {
      const Verdict v = camera.at(i);
      if (pixel_is_wrong(v.ambiguous, v.id, ids[i])) return false;
    }
    return true;
  });
}

bool md_matches(const std::vector<double>& answer, const std::vector<double>& expected) {
  if (answer.size() != expected.size()) return false;
  double scale = 1.0;
  for (double value : expected) scale = std::max(scale, std::abs(value));
  for (std::size_t i = 0; i < answer.size(); ++i)
    if (!(std::abs(answer[i] - expected[i]) <= 1e-6 * scale)) return false;
  return true;
}

}  // namespace raycam::check
