#include "case_image.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <optional>
#include <stdexcept>

#include "raycam/camera2d.h"
#include "raycam/camera3d.h"
#include "raycam/view_setup.h"

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

namespace {
// The case's camera with the mistakes on, and what one pixel (protocol index) sees.
class CaseCamera {
 public:
  CaseCamera(const SceneFile& file, const ClassicMistakes& mistakes, IntersectFormula formula)
      : file_(file), any_sign_(mistakes.no_t_min), formula_(formula) {
    const CameraPreset& preset = complete_camera(file);
    const std::vector<double>& target = *preset.target;
    if (file.dimension == 2) {
      if (target.size() != 2) throw std::invalid_argument("camera.target: expected 2 components in 2D");
      camera2d_.emplace(camera2d_from_preset(preset));
      camera2d_->set_mistakes(mistakes);
      columns_ = camera2d_->pixel_count();
      md_ = row_major<3>(camera2d_->world_from_camera());
      return;
    }
    if (target.size() != 3 || preset.size->size() != 2)
      throw std::invalid_argument("camera: expected a 3-component target and size [columns, rows] in 3D");
    camera3d_.emplace(camera3d_from_preset(preset));
    camera3d_->set_mistakes(mistakes);
    rows_ = camera3d_->rows();
    columns_ = camera3d_->columns();
    md_ = row_major<4>(camera3d_->world_from_camera());
  }
  int rows() const { return rows_; }
  int columns() const { return columns_; }
  const std::vector<double>& md() const { return md_; }
  Verdict at(std::size_t index) const {
    if (camera2d_)
      return classify(file_.scene2d.circles, camera2d_->primary_ray(int(index)), any_sign_, formula_);
    return classify(
        file_.scene3d.spheres,
        camera3d_->primary_ray(int(index / std::size_t(columns_)), int(index % std::size_t(columns_))),
        any_sign_, formula_);
  }

 private:
  const SceneFile& file_;
  bool any_sign_;
  IntersectFormula formula_;
  std::optional<Camera2D> camera2d_;
  std::optional<Camera3D> camera3d_;
  int rows_ = 1, columns_ = 0;
  std::vector<double> md_;
};
}  // namespace

CaseImage render_case(const SceneFile& file, const ClassicMistakes& mistakes, IntersectFormula formula) {
  const CaseCamera camera(file, mistakes, formula);
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
}

bool case_reproduces(const SceneFile& file, const ClassicMistakes& mistakes, IntersectFormula formula,
                     int rows, int columns, const std::vector<int>& ids, const std::vector<double>* md) {
  const CaseCamera camera(file, mistakes, formula);
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
