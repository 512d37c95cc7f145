#include "raycam/camera2d.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>
#include <stdexcept>

#include "core/primary_ray.h"
#include "raycam/limits.h"
#include "raycam/transform.h"
#include "core/validation.h"

namespace raycam {

namespace detail {
thread_local long long placements_built = 0;
}
long long placements_built_on_this_thread() { return detail::placements_built; }

glm::dvec2 polar_direction(double theta) { return {std::cos(theta), std::sin(theta)}; }

glm::dvec2 orbit_screen_centre(const Orbit2D& orbit) {
  return orbit.target + orbit.d * polar_direction(orbit.theta);
}

double field_of_view(double df) { return 2.0 * std::atan(1.0 / df); }

glm::dvec2 eye_of(const glm::dmat3& world_from_camera) {
  return transform_point(world_from_camera, kCanonicalEye2D);
}

std::array<glm::dvec2, 2> screen_corners_of(const glm::dmat3& world_from_camera) {
  return {transform_point(world_from_camera, {-1.0, 0.0}), transform_point(world_from_camera, {1.0, 0.0})};
}

Placement2D placement_matrix(const Orbit2D& orbit, const ClassicMistakes& mistakes) {
  detail::require_coordinate(orbit.target.x, "target.x");
  detail::require_coordinate(orbit.target.y, "target.y");
  detail::require_positive(orbit.d, "d");
  detail::require_angle(orbit.theta, "theta");
  detail::require_focal_distance(orbit.df, "df");

  // Classic mistake: the file's degrees handed to cos/sin as they are (the whole placement uses them).
  const double theta = mistakes.degrees_as_radians ? glm::degrees(orbit.theta) : orbit.theta;
  const glm::dvec2 position = orbit.target + orbit.d * polar_direction(theta);  // step 2
  Placement2D placement;
  placement.scale = scaling_2d(1.0, mistakes.no_focal_scale ? 1.0 : orbit.df);
  // R(α) must turn u0 = (0,-1), at angle -π/2, onto v = PC/|PC|, at angle θ + π: α = θ - π/2 (mod 2π).
  // The handout prints α = φ_v - π/2 with φ_v the angle of v itself; that is θ + π/2, which turns u0 onto
  // -v: the camera looks away from its target (kept as a classic mistake).
  const double view_angle = mistakes.printed_rotation_sign ? theta + glm::pi<double>() : theta;
  placement.alpha = view_angle - glm::half_pi<double>();
  placement.rotation = rotation_2d(placement.alpha);
  placement.translation = translation_2d(position);
  placement.world_from_camera = construction_step(placement, kConstructionSteps2D);
  ++detail::placements_built;
  return placement;
}

glm::dmat3 construction_step(const Placement2D& placement, int step) {
  detail::require_int_range(step, 0, kConstructionSteps2D, "construction step");
  const glm::dmat3 factors[] = {placement.scale, placement.rotation, placement.translation};
  return compose_first(factors, step);
}

double polar_angle(glm::dvec2 v, AngleRoute route) {
  if (route == AngleRoute::stable) return std::atan2(v.y, v.x);
  // The handout's route: φ_v = ±arccos(x_v) on the normalised vector, + when y_v ≥ 0.
  const glm::dvec2 unit = v / std::hypot(v.x, v.y);
  const double angle = std::acos(std::clamp(unit.x, -1.0, 1.0));
  return unit.y >= 0.0 ? angle : -angle;
}

Orbit2D free_orbit(glm::dvec2 position, glm::dvec2 target, double df, AngleRoute route) {
  detail::require_coordinate(position.x, "position.x");
  detail::require_coordinate(position.y, "position.y");
  const glm::dvec2 target_to_position = position - target;
  const double d = std::hypot(target_to_position.x, target_to_position.y);
  if (!(d > 0.0))
    throw std::invalid_argument("position: the camera sits on its target (P = C); expected P != C");
  return Orbit2D{target, d, polar_angle(target_to_position, route), df};
}

Camera2D::Camera2D(int max_pixels, const Orbit2D& orbit, const ClassicMistakes& mistakes)
    : max_pixels_(max_pixels), orbit_(orbit), mistakes_(mistakes) {
  detail::require_int_range(max_pixels, 1, kMaxPixels2D, "size (N)");
  pixel_count_ = max_pixels_;
  placement_ = placement_matrix(orbit_, mistakes_);
}

void Camera2D::set_res(double res) {
  detail::require_res(res, "res");
  res_ = res;
  pixel_count_ = detail::useful_size(res, max_pixels_, mistakes_.res_truncated);  // exercise 1, step 3
}

void Camera2D::set_mistakes(const ClassicMistakes& mistakes) {
  placement_ = placement_matrix(orbit_, mistakes);
  mistakes_ = mistakes;
  set_res(res_);  // res_truncated changes n
}

glm::dvec2 Camera2D::screen_centre() const {
  return transform_point(world_from_camera(), kCanonicalScreenCentre2D);
}
glm::dvec2 Camera2D::eye() const { return eye_of(world_from_camera()); }
glm::dvec2 Camera2D::view_direction() const {
  return glm::normalize(transform_vector(world_from_camera(), kCanonicalView2D));
}
glm::dvec2 Camera2D::image_right() const {
  return glm::normalize(transform_vector(world_from_camera(), {-1.0, 0.0}));  // column 0 is canonical +x
}

double Camera2D::canonical_x(int k) const {
  if (mistakes_.mirrored) k = pixel_count_ - 1 - k;  // classic mistake: pixel k stored at n-1-k
  // Exercise 2: the handout prints -1 + 2k/n, the LEFT EDGE of pixel k; the centre is half a pixel on.
  return screen_from_raster(mistakes_.pixel_edges ? k : k + 0.5);
}

glm::dvec2 Camera2D::canonical_pixel(int k) const {
  assert(k >= 0 && k < pixel_count_ && "pixel index out of range");
  return {canonical_x(k), 0.0};
}

Ray2D Camera2D::primary_ray(int k) const {
  Ray2D ray;
  primary_rays(k, k, &ray);
  return ray;
}

void Camera2D::primary_rays(int first, int last, Ray2D* rays) const {
  assert(first >= 0 && last < pixel_count_ && "pixel index out of range");
  // P^0 = (x, 0, 1) and P^0 - E0 = (x, -1, 0): the line's part is M2 (the translation) and -M1.
  const glm::dmat3& m = world_from_camera();
  // Classic mistake direction_translated: u_k moved as a point, so T(OP) = M2 is added to it.
  const glm::dvec2 direction_base =
      mistakes_.direction_translated ? glm::dvec2(m[2]) - glm::dvec2(m[1]) : -glm::dvec2(m[1]);
  detail::rays_along_line(
      glm::dvec2(m[2]), direction_base, glm::dvec2(m[0]), [this](int k) { return canonical_x(k); }, first,
      last, !mistakes_.skip_renormalise, rays);
  if (mistakes_.eye_origin)  // classic mistake: every ray starts at the eye M_d·E0 = M2 + M1
    for (int k = first; k <= last; ++k) rays[k - first].origin = glm::dvec2(m[2]) + glm::dvec2(m[1]);
}

}  // namespace raycam
