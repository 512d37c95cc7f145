#include "raycam/camera3d.h"

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
extern thread_local long long placements_built;  // camera2d.cpp
}

glm::dvec3 spherical_direction(double theta, double phi) {
  return {std::cos(theta) * std::sin(phi), std::sin(theta) * std::sin(phi), std::cos(phi)};
}

glm::dvec3 orbit_screen_centre(const Orbit3D& orbit) {
  return orbit.target + orbit.d * spherical_direction(orbit.theta, orbit.phi);
}

glm::dvec3 eye_of(const glm::dmat4& world_from_camera) {
  return transform_point(world_from_camera, kCanonicalEye3D);
}

std::array<glm::dvec3, 4> screen_corners_of(const glm::dmat4& world_from_camera) {
  std::array<glm::dvec3, 4> corners;
  for (std::size_t i = 0; i < corners.size(); ++i)
    corners[i] = transform_point(world_from_camera, kCanonicalScreenCorners3D[i]);
  return corners;
}

Placement3D placement_matrix(const Orbit3D& orbit, const ClassicMistakes& mistakes) {
  detail::require_coordinate(orbit.target.x, "target.x");
  detail::require_coordinate(orbit.target.y, "target.y");
  detail::require_coordinate(orbit.target.z, "target.z");
  detail::require_positive(orbit.d, "d");
  detail::require_angle(orbit.theta, "theta");
  detail::require_angle(orbit.phi, "phi");
  detail::require_focal_distance(orbit.df, "df");

  // Classic mistakes on the angles: θ and φ swapped, degrees handed to cos/sin as they are.
  double theta = mistakes.theta_phi_swapped ? orbit.phi : orbit.theta;
  double phi = mistakes.theta_phi_swapped ? orbit.theta : orbit.phi;
  if (mistakes.degrees_as_radians) {
    theta = glm::degrees(theta);
    phi = glm::degrees(phi);
  }
  const glm::dvec3 position = orbit.target + orbit.d * spherical_direction(theta, phi);
  Placement3D placement;
  // With (θ, φ) the angles of CP, R_z(θ)·R_y(φ) takes u0 = -z to -CP/|CP| = v. The handout's route takes
  // the angles of v = PC itself, (θ + π, π - φ): the camera then looks away (kept as a classic mistake).
  placement.theta = mistakes.printed_rotation_sign ? theta + glm::pi<double>() : theta;
  placement.phi = mistakes.printed_rotation_sign ? glm::pi<double>() - phi : phi;
  placement.scale = scaling_3d(1.0, 1.0, mistakes.no_focal_scale ? 1.0 : orbit.df);  // step 1
  // Step 2: the handout prints ψ0 = -π/2, which turns the image upside down (classic mistake).
  placement.roll = rotation_z(mistakes.upside_down ? -kRollPsi0 : kRollPsi0);
  placement.polar = rotation_y(placement.phi);       // step 3a
  placement.azimuth = rotation_z(placement.theta);   // step 3b
  placement.translation = translation_3d(position);  // step 4
  placement.world_from_camera = construction_step(placement, kConstructionSteps3D);
  ++detail::placements_built;
  return placement;
}

glm::dmat4 construction_step(const Placement3D& placement, int step) {
  detail::require_int_range(step, 0, kConstructionSteps3D, "construction step");
  const glm::dmat4 factors[] = {placement.scale, placement.roll, placement.polar, placement.azimuth,
                                placement.translation};
  return compose_first(factors, step);
}

SphericalAngles spherical_angles(glm::dvec3 v, AngleRoute route) {
  SphericalAngles angles;
  if (route == AngleRoute::stable) {
    const double horizontal = std::hypot(v.x, v.y);
    angles.phi = std::atan2(horizontal, v.z);
    angles.theta = horizontal > 0.0 ? std::atan2(v.y, v.x) : 0.0;
    return angles;
  }
  // Handout, exercise 3 step 3: φ = arccos(z_v), θ = ±arccos(x_v / sin φ) by the sign of y_v.
  const glm::dvec3 unit = v / glm::length(v);
  angles.phi = std::acos(std::clamp(unit.z, -1.0, 1.0));
  const double sin_phi = std::sin(angles.phi);
  if (sin_phi > 0.0) {
    const double theta = std::acos(std::clamp(unit.x / sin_phi, -1.0, 1.0));
    angles.theta = unit.y >= 0.0 ? theta : -theta;
  }
  return angles;
}

Orbit3D free_orbit(glm::dvec3 position, glm::dvec3 target, double df, AngleRoute route) {
  detail::require_coordinate(position.x, "position.x");
  detail::require_coordinate(position.y, "position.y");
  detail::require_coordinate(position.z, "position.z");
  const glm::dvec3 target_to_position = position - target;
  const double d = glm::length(target_to_position);
  if (!(d > 0.0))
    throw std::invalid_argument("position: the camera sits on its target (P = C); expected P != C");
  const SphericalAngles angles = spherical_angles(target_to_position, route);
  return Orbit3D{target, d, angles.theta, angles.phi, df};
}

Camera3D::Camera3D(int max_columns, int max_rows, const Orbit3D& orbit, const ClassicMistakes& mistakes)
    : max_columns_(max_columns), max_rows_(max_rows), orbit_(orbit), mistakes_(mistakes) {
  detail::require_int_range(max_columns, 1, kMaxSide3D, "size (columns)");
  detail::require_int_range(max_rows, 1, kMaxSide3D, "size (rows)");
  detail::require_int_range(static_cast<long long>(max_columns) * max_rows, 1, kMaxPixels3D,
                            "size (columns x rows)");
  columns_ = max_columns_;
  rows_ = max_rows_;
  placement_ = placement_matrix(orbit_, mistakes_);
}

void Camera3D::set_res(double res_columns, double res_rows) {
  detail::require_res(res_columns, "res (columns)");
  detail::require_res(res_rows, "res (rows)");
  res_columns_ = res_columns;
  res_rows_ = res_rows;
  columns_ = detail::useful_size(res_columns, max_columns_, mistakes_.res_truncated);
  rows_ = detail::useful_size(res_rows, max_rows_, mistakes_.res_truncated);
}

void Camera3D::set_mistakes(const ClassicMistakes& mistakes) {
  placement_ = placement_matrix(orbit_, mistakes);
  mistakes_ = mistakes;
  set_res(res_columns_, res_rows_);  // res_truncated changes the sizes
}

glm::dvec3 Camera3D::screen_centre() const {
  return transform_point(world_from_camera(), kCanonicalScreenCentre3D);
}
glm::dvec3 Camera3D::eye() const { return eye_of(world_from_camera()); }
glm::dvec3 Camera3D::view_direction() const {
  return glm::normalize(transform_vector(world_from_camera(), kCanonicalView3D));
}
glm::dvec3 Camera3D::image_up() const { return transform_vector(world_from_camera(), {0.0, 1.0, 0.0}); }
glm::dvec3 Camera3D::image_right() const { return transform_vector(world_from_camera(), {1.0, 0.0, 0.0}); }

// Pixel centres through the pixel <-> screen pair (the printed 2k/n is a pixel's corner: pixel_edges).
double Camera3D::canonical_x(int column) const {
  if (mistakes_.mirrored) column = columns_ - 1 - column;  // classic mistake: columns reversed
  const double x = raycam::screen_from_raster(mistakes_.pixel_edges ? column : column + 0.5, columns_);
  // Classic mistake: the screen's half-width taken as the image's aspect (Ray Tracing in One Weekend's look-at
  // camera) where the handout's canonical screen is the square [-1, 1]² whatever nbc and nbl (exercise 3).
  return mistakes_.square_pixels ? x * double(columns_) / double(rows_) : x;
}

double Camera3D::canonical_y(int row) const {
  if (mistakes_.rows_flipped) row = rows_ - 1 - row;  // classic mistake: row 0 at the bottom
  return -raycam::screen_from_raster(mistakes_.pixel_edges ? row : row + 0.5, rows_);  // row 0 at the top
}

glm::dvec3 Camera3D::canonical_pixel(int row, int column) const {
  assert(row >= 0 && row < rows_ && column >= 0 && column < columns_ && "pixel index out of range");
  return {canonical_x(column), canonical_y(row), 0.0};
}

Ray3D Camera3D::primary_ray(int row, int column) const {
  Ray3D ray;
  primary_rays(row, column, column, &ray);
  return ray;
}

Camera3D::RayLine Camera3D::ray_line(int row) const {
  // P^0 = (x, y, 0, 1) and P^0 - E0 = (x, y, -1, 0): the row's part is M3 + y·M1 and y·M1 - M2.
  const glm::dmat4& m = world_from_camera();
  const glm::dvec3 right(m[0]), up(m[1]), back(m[2]), position(m[3]);
  const double y = canonical_y(row);
  // Classic mistake direction_translated: u_k moved as a point, so T(OP) = M3 is added to it.
  const glm::dvec3 direction_base =
      mistakes_.direction_translated ? glm::dvec3(position + (y * up - back)) : glm::dvec3(y * up - back);
  return RayLine{glm::dvec3(position + y * up), direction_base, right};
}

void Camera3D::primary_rays(int row, int first_column, int last_column, Ray3D* rays) const {
  assert(row >= 0 && row < rows_ && first_column >= 0 && last_column < columns_ && "pixel index out of range");
  const RayLine line = ray_line(row);
  detail::rays_along_line(
      line.origin_base, line.direction_base, line.axis, [this](int column) { return canonical_x(column); },
      first_column, last_column, !mistakes_.skip_renormalise, rays);
  if (mistakes_.eye_origin) {  // classic mistake: every ray starts at the eye M_d·E0 = M3 + M2
    const glm::dmat4& m = world_from_camera();
    for (int column = first_column; column <= last_column; ++column)
      rays[column - first_column].origin = glm::dvec3(m[3]) + glm::dvec3(m[2]);
  }
}

}  // namespace raycam
