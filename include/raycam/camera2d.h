// The handout's 2D "pseudo camera" (exercises 1 and 2).
//
// World plane: x to the right, y up, angles counter-clockwise from +x, in radians.
// Canonical camera: screen segment (-1,0)–(+1,0) with centre Ω = (0,0); eye E0 = (0,1); view u0 = (0,-1).
// n = res·N useful pixels; canonical centre of pixel k is P_k^0 = (-1 + (2k+1)/n, 0), k = 0…n-1.
//
// Image order: facing -y, the eye's LEFT is +x (v rotated +90°). So the colour bar's column 0 (the eye's
// left) shows pixel k = n-1, and column c shows pixel k = n-1-c. Drawing k left-to-right mirrors the bar.
#pragma once

#include <array>
#include <glm/gtc/constants.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>

#include "raycam/classic_mistakes.h"

namespace raycam {

// ---- the canonical 2D camera (handout, exercise 1) ----
inline constexpr glm::dvec2 kCanonicalScreenCentre2D{0.0, 0.0};  // Ω
inline constexpr glm::dvec2 kCanonicalEye2D{0.0, 1.0};           // E0
inline constexpr glm::dvec2 kCanonicalView2D{0.0, -1.0};         // u0

// The pixel <-> canonical-screen pair along one screen axis of `count` pixels (pbrt's screenFromRaster and
// rasterFromScreen, per axis). Continuous pixel coordinates: pixel i covers [i, i+1], its centre is i + 1/2;
// coordinate 0 is canonical -1 and coordinate count is +1. Written so that a centre gives exactly the
// handout's -1 + (2i+1)/n and an edge its -1 + 2i/n (2·(i + 1/2) = 2i + 1 is exact).
constexpr double screen_from_raster(double raster, int count) { return -1.0 + 2.0 * raster / count; }
constexpr double raster_from_screen(double screen, int count) { return (screen + 1.0) * count / 2.0; }

// How the free placement (P, C) turns the view vector into an angle.
enum class AngleRoute {
  stable,          // atan2: well-conditioned everywhere
  handout_arccos,  // the handout's ±arccos(x_v): an input error ε becomes an angle error ~√(2ε) near ±1
};

// Orbit placement (exercise 1, step 2): target C, distance d > 0 from C to the screen centre, angle θ of
// CP (radians), focal distance d_f > 0.
struct Orbit2D {
  glm::dvec2 target{0.0, 0.0};
  double d = 6.0;
  double theta = glm::half_pi<double>();  // above the target, looking down -y like the canonical camera
  double df = 1.5;
};

// Unit vector at angle θ (radians) from +x: the direction of CP for an orbit of angle θ.
glm::dvec2 polar_direction(double theta);
// Step 2: the screen centre P = C + d·(cos θ, sin θ) of an orbit (before any mistake).
glm::dvec2 orbit_screen_centre(const Orbit2D& orbit);

// The factors of M_d = T(OP) · R(α) · H(1, d_f), kept one by one because the app shows them.
struct Placement2D {
  glm::dmat3 scale{1.0};        // H(1, d_f)
  glm::dmat3 rotation{1.0};     // R(α), α = θ - π/2 turns u0 onto v
  glm::dmat3 translation{1.0};  // T(OP)
  double alpha = 0.0;
  glm::dmat3 world_from_camera{1.0};  // T·R·H
};

// The handout's frames a → d: the product of the first `step` factors in the order they apply.
// 0: identity (frame a), 1: H, 2: R·H, 3: T·R·H = world_from_camera (frame d). Throws outside [0, 3].
inline constexpr int kConstructionSteps2D = 3;
glm::dmat3 construction_step(const Placement2D& placement, int step);

// The only place M_d is composed (through construction_step). Throws std::invalid_argument on d ≤ 0, d_f ≤ 0
// or non-finite input. The mistakes that change M_d (printed_rotation_sign, degrees_as_radians,
// no_focal_scale) are applied here.
Placement2D placement_matrix(const Orbit2D& orbit, const ClassicMistakes& mistakes);
inline Placement2D placement_matrix(const Orbit2D& orbit, bool printed_rotation_sign = false) {
  return placement_matrix(orbit, rotation_mistake_only(printed_rotation_sign));
}

// How many M_d (2D or 3D) this thread has composed: lets tests check that placing a camera builds it once.
long long placements_built_on_this_thread();

// Angle of a non-zero vector (radians, in (-π, π]) by the chosen route.
double polar_angle(glm::dvec2 v, AngleRoute route);
// Free placement (exercise 1, second route): the orbit with screen centre `position` and target C (P ≠ C):
// d = |CP|, θ = angle of CP by `route`. Throws std::invalid_argument when P = C or a coordinate is out of
// range.
Orbit2D free_orbit(glm::dvec2 position, glm::dvec2 target, double df, AngleRoute route);

// Camera facts of any placement matrix (the final M_d or a construction step's product), in the world.
glm::dvec2 eye_of(const glm::dmat3& world_from_camera);  // M·E0
// The screen's two ends M·(-1, 0) and M·(+1, 0) (the 2D screen's "corners").
std::array<glm::dvec2, 2> screen_corners_of(const glm::dmat3& world_from_camera);
// Full field of view (radians) of a screen of half-width 1 at focal distance df: 2·atan(1/df).
double field_of_view(double df);

struct Ray2D {
  glm::dvec2 origin{0.0};     // on the screen (P_k), not at the eye: hits need t ≥ 0 from here
  glm::dvec2 direction{0.0};  // unit unless ClassicMistakes::skip_renormalise
};

class Camera2D {
 public:
  // N = max_pixels, in [1, kMaxPixels2D]; res = 1. Throws std::invalid_argument otherwise. M_d is built
  // once, for this orbit and these mistakes.
  explicit Camera2D(int max_pixels = 256, const Orbit2D& orbit = {}, const ClassicMistakes& mistakes = {});

  int max_pixels() const { return max_pixels_; }
  double res() const { return res_; }
  void set_res(double res);                         // res ∈ ]0, 1]
  int pixel_count() const { return pixel_count_; }  // n = clamp(round(res·N), 1, N) (floor: res_truncated)

  void set_orbit(const Orbit2D& orbit) {
    placement_ = placement_matrix(orbit, mistakes_);  // throws before anything changes
    orbit_ = orbit;
  }
  // Free placement from the screen centre P and target C (P ≠ C): d = |CP|, θ = angle of CP.
  void set_free(glm::dvec2 position, glm::dvec2 target, double df, AngleRoute route = AngleRoute::stable) {
    set_orbit(free_orbit(position, target, df, route));
  }
  const Orbit2D& orbit() const { return orbit_; }

  void set_mistakes(const ClassicMistakes& mistakes);  // rebuilds M_d (once)
  const ClassicMistakes& mistakes() const { return mistakes_; }

  const Placement2D& placement() const { return placement_; }
  const glm::dmat3& world_from_camera() const { return placement_.world_from_camera; }
  glm::dvec2 screen_centre() const;   // P = M_d·Ω
  glm::dvec2 eye() const;             // M_d·E0 = P - d_f·v
  glm::dvec2 view_direction() const;  // unit M_d·u0 (= v unless printed_rotation_sign)
  glm::dvec2 image_right() const;     // unit world direction of increasing columns: R·(-1, 0) (see header)
  double field_of_view() const { return raycam::field_of_view(orbit_.df); }  // radians
  std::array<glm::dvec2, 2> screen_corners() const { return screen_corners_of(world_from_camera()); }

  // The pixel <-> canonical pair of this camera, in pixel order k (not image columns: column = n-1-k).
  double screen_from_raster(double k) const { return raycam::screen_from_raster(k, pixel_count_); }
  double raster_from_screen(double x) const { return raycam::raster_from_screen(x, pixel_count_); }

  glm::dvec2 canonical_pixel(int k) const;  // P_k^0 (a pixel edge under ClassicMistakes::pixel_edges)
  Ray2D primary_ray(int k) const;           // exercise 2: P_k = M_d·P_k^0, u_k = M_d·(P_k^0 - E0)
  void primary_rays(int first, int last, Ray2D* rays) const;  // pixels first…last, each exactly primary_ray's
  int column_of_pixel(int k) const { return pixel_count_ - 1 - k; }
  int pixel_of_column(int column) const { return pixel_count_ - 1 - column; }

 private:
  double canonical_x(int k) const;

  int max_pixels_;
  double res_ = 1.0;
  int pixel_count_;
  Orbit2D orbit_;
  ClassicMistakes mistakes_;
  Placement2D placement_;
};

}  // namespace raycam
