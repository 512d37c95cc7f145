// The handout's 3D camera (exercise 3).
//
// World: right-handed, z up (the handout's spherical coordinates take z as the polar axis).
// Canonical camera: screen square (-1,-1,0)–(+1,+1,0), eye E0 = (0,0,1), view u0 = (0,0,-1); canonical +x
// is the image's right and +y its up (as an OpenGL camera looking down -z).
// Pixel centres: column c ↦ x = -1 + (2c+1)/nbc, row r ↦ y = +1 - (2r+1)/nbl; row 0 is the top.
//
// Orbit placement: P = C + d·(cos θ sin φ, sin θ sin φ, cos φ) and the camera looks from P at C:
//   M_d = T(OP) · R_z(θ) · R_y(φ) · R_z(ψ0) · H(1, 1, d_f),  ψ0 = +π/2,
// with (θ, φ) the spherical angles of CP (those of PC make the camera look away). ψ0 = +π/2 makes the
// image's up R·(0,1,0) = (-cos θ cos φ, -sin θ cos φ, sin φ): world +z is up for 0 < φ < π. The formula is
// smooth in (θ, φ), so nothing flips when φ crosses a pole or θ wraps.
#pragma once

#include <array>
#include <glm/gtc/constants.hpp>
#include <glm/mat4x4.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "raycam/camera2d.h"  // AngleRoute, ClassicMistakes, the per-axis pixel <-> screen pair

namespace raycam {

// ---- the canonical 3D camera (handout, exercise 3) ----
inline constexpr glm::dvec3 kCanonicalScreenCentre3D{0.0, 0.0, 0.0};  // Ω
inline constexpr glm::dvec3 kCanonicalEye3D{0.0, 0.0, 1.0};           // E0
inline constexpr glm::dvec3 kCanonicalView3D{0.0, 0.0, -1.0};         // u0
// The screen's corners in image order: top-left, top-right, bottom-right, bottom-left.
inline constexpr std::array<glm::dvec3, 4> kCanonicalScreenCorners3D{
    glm::dvec3{-1.0, 1.0, 0.0}, glm::dvec3{1.0, 1.0, 0.0}, glm::dvec3{1.0, -1.0, 0.0},
    glm::dvec3{-1.0, -1.0, 0.0}};

inline constexpr double kRollPsi0 = glm::half_pi<double>();  // +π/2 radians (see header comment)

// Angles in radians.
struct Orbit3D {
  glm::dvec3 target{0.0};
  double d = 8.0;
  double theta = glm::radians(30.0);
  double phi = glm::radians(60.0);
  double df = 2.0;
};

// Unit vector of spherical angles θ (azimuth) and φ (polar, from +z), radians: CP's direction for an orbit.
glm::dvec3 spherical_direction(double theta, double phi);
// Step 4's translation: the screen centre P = C + d·(cos θ sin φ, sin θ sin φ, cos φ) of an orbit.
glm::dvec3 orbit_screen_centre(const Orbit3D& orbit);

// The factors of M_d, kept one by one for display (handout steps 1–4, in the order they apply).
struct Placement3D {
  glm::dmat4 scale{1.0};              // step 1: H(1, 1, d_f)
  glm::dmat4 roll{1.0};               // step 2: R_z(ψ0)
  glm::dmat4 polar{1.0};              // step 3a: R_y(φ), puts u0 in the plane y = 0
  glm::dmat4 azimuth{1.0};            // step 3b: R_z(θ), makes u0 collinear with v
  glm::dmat4 translation{1.0};        // step 4: T(OP)
  double theta = 0.0, phi = 0.0;      // the angles actually used (differ from the orbit's under the mistake)
  glm::dmat4 world_from_camera{1.0};  // T · R_z(θ) · R_y(φ) · R_z(ψ0) · H
};

// The product of the first `step` factors in the order they apply: 0: identity, 1: H, 2: R_z(ψ0)·H,
// 3: R_y(φ)·…, 4: R_z(θ)·…, 5: T·… = world_from_camera. Throws outside [0, 5].
inline constexpr int kConstructionSteps3D = 5;
glm::dmat4 construction_step(const Placement3D& placement, int step);

// The only place the 3D M_d is composed (through construction_step). Throws std::invalid_argument on d ≤ 0,
// d_f ≤ 0, non-finite input. The mistakes that change M_d (printed_rotation_sign, upside_down,
// degrees_as_radians, no_focal_scale, theta_phi_swapped) are applied here.
Placement3D placement_matrix(const Orbit3D& orbit, const ClassicMistakes& mistakes);
inline Placement3D placement_matrix(const Orbit3D& orbit, bool printed_rotation_sign = false) {
  return placement_matrix(orbit, rotation_mistake_only(printed_rotation_sign));
}

struct SphericalAngles {
  double theta = 0.0;  // azimuth, radians, in (-π, π]; 0 at the poles, where it is undefined
  double phi = 0.0;    // polar angle from +z, radians, in [0, π]
};
// Spherical angles of a non-zero vector. handout_arccos: φ = arccos(z/|v|), θ = ±arccos(x/(|v| sin φ)).
SphericalAngles spherical_angles(glm::dvec3 v, AngleRoute route);
// Free placement (the handout's second route): the orbit with screen centre `position` and target C
// (P ≠ C), its angles by `route`. Throws std::invalid_argument when P = C or a coordinate is out of range.
Orbit3D free_orbit(glm::dvec3 position, glm::dvec3 target, double df, AngleRoute route);

// Camera facts of any placement matrix (the final M_d or a construction step's product), in the world.
glm::dvec3 eye_of(const glm::dmat4& world_from_camera);  // M·E0
std::array<glm::dvec3, 4> screen_corners_of(
    const glm::dmat4& world_from_camera);  // M·kCanonicalScreenCorners3D

struct Ray3D {
  glm::dvec3 origin{0.0};
  glm::dvec3 direction{0.0};  // unit unless ClassicMistakes::skip_renormalise
};

class Camera3D {
 public:
  // Maximum columns × rows, each in [1, kMaxSide3D], product ≤ kMaxPixels3D; res = 1. M_d is built once,
  // for this orbit and these mistakes.
  explicit Camera3D(int max_columns = 256, int max_rows = 256, const Orbit3D& orbit = {},
                    const ClassicMistakes& mistakes = {});

  int max_columns() const { return max_columns_; }
  int max_rows() const { return max_rows_; }
  void set_res(double res) { set_res(res, res); }
  void set_res(double res_columns, double res_rows);  // each in ]0, 1]
  double res_columns() const { return res_columns_; }
  double res_rows() const { return res_rows_; }
  int columns() const { return columns_; }  // nbc
  int rows() const { return rows_; }        // nbl

  void set_orbit(const Orbit3D& orbit) {
    placement_ = placement_matrix(orbit, mistakes_);  // throws before anything changes
    orbit_ = orbit;
  }
  // Free placement (the handout's second route): screen centre P, target C (P ≠ C).
  void set_free(glm::dvec3 position, glm::dvec3 target, double df, AngleRoute route = AngleRoute::stable) {
    set_orbit(free_orbit(position, target, df, route));
  }
  const Orbit3D& orbit() const { return orbit_; }

  void set_mistakes(const ClassicMistakes& mistakes);  // rebuilds M_d (once)
  const ClassicMistakes& mistakes() const { return mistakes_; }

  const Placement3D& placement() const { return placement_; }
  const glm::dmat4& world_from_camera() const { return placement_.world_from_camera; }
  glm::dvec3 screen_centre() const;   // P = M_d·Ω
  glm::dvec3 eye() const;             // M_d·E0 = P - d_f·v
  glm::dvec3 view_direction() const;  // unit M_d·u0
  glm::dvec3 image_up() const;        // R·(0,1,0), unit
  glm::dvec3 image_right() const;     // R·(1,0,0), unit
  // Full field of view (radians), the same across and down: the canonical screen is a square.
  double field_of_view() const { return raycam::field_of_view(orbit_.df); }
  std::array<glm::dvec3, 4> screen_corners() const { return screen_corners_of(world_from_camera()); }

  // The pixel <-> canonical-screen pair (pbrt's screenFromRaster / rasterFromScreen): continuous pixel
  // coordinates (column, row), row 0 at the top, pixel (r, c) covering [c, c+1] × [r, r+1], to the
  // canonical (x, y) with y up, and back.
  glm::dvec2 screen_from_raster(glm::dvec2 raster) const {
    return {raycam::screen_from_raster(raster.x, columns_), -raycam::screen_from_raster(raster.y, rows_)};
  }
  glm::dvec2 raster_from_screen(glm::dvec2 screen) const {
    return {raycam::raster_from_screen(screen.x, columns_), raycam::raster_from_screen(-screen.y, rows_)};
  }

  glm::dvec3 canonical_pixel(int row, int column) const;
  Ray3D primary_ray(int row, int column) const;
  // The rays of pixels first_column…last_column of one row into rays[0…], each exactly primary_ray's.
  void primary_rays(int row, int first_column, int last_column, Ray3D* rays) const;
  // A row's rays as a line (what primary_rays computes once per row): column c's ray starts at
  // origin_base + x·axis with direction direction_base + x·axis (renormalised), x = canonical_x(c).
  struct RayLine {
    glm::dvec3 origin_base, direction_base, axis;
  };
  RayLine ray_line(int row) const;
  double canonical_x(int column) const;  // the pixel centre's canonical x (y), with the pixel mistakes
  double canonical_y(int row) const;

 private:

  int max_columns_, max_rows_;
  double res_columns_ = 1.0, res_rows_ = 1.0;
  int columns_, rows_;
  Orbit3D orbit_;
  ClassicMistakes mistakes_;
  Placement3D placement_;
};

}  // namespace raycam
