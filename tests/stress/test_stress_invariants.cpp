// The camera invariants (docs/testing.md) under stress: far, tiny and huge cameras, the poles and ±π, huge translations.
// Also the handout's arccos route against atan2 near ±1 and near the poles.
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include "raycam/exact_bar.h"
#include "raycam/ray_caster.h"
#include "raycam/stress_cases.h"

using namespace raycam;

namespace {
constexpr double kPi = glm::pi<double>();

// Scale of the numbers involved: errors are judged relative to it.
double scale_of(glm::dvec3 target, double d, double df) { return glm::length(target) + d + df; }

bool grazes_any(const Ray2D& ray, const std::vector<Circle>& circles, double tolerance) {
  for (const Circle& c : circles) {
    const glm::dvec2 f = c.centre - ray.origin;
    const glm::dvec2 perpendicular = f - glm::dot(f, ray.direction) * ray.direction;
    if (std::abs(glm::length(perpendicular) - c.radius) <= tolerance * (c.radius + glm::length(f)))
      return true;
  }
  return false;
}
}  // namespace

TEST_CASE("3D placement invariants 1-3 hold on every stress camera", "[stress][invariant]") {
  for (const StressCase3D& stress_case : stress_cases_3d(false)) {
    const Camera3D& camera = stress_case.camera;
    const Orbit3D& orbit = camera.orbit();
    const double scale = scale_of(orbit.target, orbit.d, orbit.df);
    INFO(stress_case.group << " " << stress_case.name);
    // 1: the eye is at distance d + d_f from C.
    CHECK(std::abs(glm::length(camera.eye() - orbit.target) - (orbit.d + orbit.df)) <= 1e-14 * scale);
    // 2: the line from the eye along the view direction (through the screen centre) passes through C.
    const glm::dvec3 axis = camera.view_direction();  // (P - E)/d_f, without dividing by a tiny d_f
    const glm::dvec3 to_target = orbit.target - camera.eye();
    CHECK(glm::length(to_target - glm::dot(to_target, axis) * axis) <= 1e-14 * scale);
    // 3: linear part = rotation · H: orthogonal columns of lengths 1, 1, d_f, determinant +d_f.
    const glm::dmat3 linear(camera.world_from_camera());
    CHECK(std::abs(glm::dot(linear[0], linear[1])) <= 1e-14);
    CHECK(std::abs(glm::dot(linear[0], linear[2])) <= 1e-14 * orbit.df);
    CHECK(std::abs(glm::dot(linear[1], linear[2])) <= 1e-14 * orbit.df);
    CHECK(glm::determinant(linear) == Approx(orbit.df).epsilon(1e-14));
  }
}

TEST_CASE("2D placement invariants 1-2 hold on every stress camera", "[stress][invariant]") {
  for (const StressCase2D& stress_case : stress_cases_2d(false)) {
    const Camera2D& camera = stress_case.camera;
    const Orbit2D& orbit = camera.orbit();
    const double scale = glm::length(orbit.target) + orbit.d + orbit.df;
    INFO(stress_case.group << " " << stress_case.name);
    CHECK(std::abs(glm::length(camera.eye() - orbit.target) - (orbit.d + orbit.df)) <= 1e-14 * scale);
    const glm::dvec2 axis = camera.view_direction();
    const glm::dvec2 to_target = orbit.target - camera.eye();
    CHECK(std::abs(axis.x * to_target.y - axis.y * to_target.x) <= 1e-14 * scale);
  }
}

TEST_CASE("invariant 7: nothing flips across the poles or when θ wraps", "[stress][invariant]") {
  // Neighbouring cameras within a few ulp must give the same ids (checked against the first).
  const Scene3D scene = stress_cases_3d(false).front().scene;
  auto ids_at = [&](double theta, double phi) {
    Camera3D camera(33, 33);
    camera.set_orbit(Orbit3D{{0, 0, 0}, 8.0, theta, phi, 2.0});
    return cast_primary_rays(camera, scene).ids;
  };
  const double tiny = std::nextafter(0.0, 1.0);
  const auto at_pole = ids_at(0.5, 0.0);
  for (double phi : {tiny, -tiny, 4 * tiny, -4 * tiny, 1e-300, -1e-300}) CHECK(ids_at(0.5, phi) == at_pole);
  const auto at_south = ids_at(0.5, kPi);
  for (double phi : {std::nextafter(kPi, 0.0), std::nextafter(kPi, 4.0)}) CHECK(ids_at(0.5, phi) == at_south);
  const auto at_pi = ids_at(kPi, 1.0);
  for (double theta : {-kPi, std::nextafter(kPi, 4.0), std::nextafter(-kPi, -4.0), 3 * kPi})
    CHECK(ids_at(theta, 1.0) == at_pi);
}

TEST_CASE("invariants 5 and 6: symmetric scenes stay symmetric when translated by up to 1e7",
          "[stress][invariant]") {
  for (double shift : {0.0, 1e3, 1e5, 1e7}) {
    for (double theta : {kPi / 2, kPi, -kPi, 0.7}) {
      const glm::dvec2 target(shift, -0.3 * shift);
      Camera2D camera(129);
      camera.set_orbit(Orbit2D{target, 6.0, theta, 1.5});
      const glm::dvec2 v = camera.view_direction(), w(-v.y, v.x);
      Scene2D scene;  // pairs mirrored about the view axis, one circle on it
      scene.circles.push_back(Circle{target + 1.0 * v, 0.8, Rgb8{}, ""});
      scene.circles.push_back(Circle{target + 2.0 * v + 2.0 * w, 0.6, Rgb8{}, ""});
      scene.circles.push_back(Circle{target + 2.0 * v - 2.0 * w, 0.6, Rgb8{}, ""});
      const int mirror_of[] = {0, 2, 1};
      const ColourMap map = cast_primary_rays(camera, scene);
      const int n = camera.pixel_count();
      INFO("shift " << shift << " theta " << theta);
      for (int k = 0; k < n; ++k) {
        // Positions near 1e7 are rounded to ~2e-9: rays that close to a silhouette may go either way.
        if (grazes_any(camera.primary_ray(k), scene.circles, 1e-12 * (1 + shift)) ||
            grazes_any(camera.primary_ray(n - 1 - k), scene.circles, 1e-12 * (1 + shift)))
          continue;
        const int id = map.ids[std::size_t(camera.column_of_pixel(k))];
        const int mirrored = map.ids[std::size_t(camera.column_of_pixel(n - 1 - k))];
        CHECK(id == (mirrored < 0 ? -1 : mirror_of[mirrored]));
      }
      // The exact reference agrees that the scene did not change with the translation.
      const ExactBar bar = exact_bar(camera, scene);
      for (int column = 0; column < n; ++column)
        CHECK(bar.coverage_of(column, 1) == Approx(bar.coverage_of(n - 1 - column, 2)).margin(1e-6));
    }
  }
}

TEST_CASE("equal depth: identical objects always show the lower index", "[stress]") {
  for (const StressCase2D& stress_case : stress_cases_2d(false)) {
    if (stress_case.name != "identical + crossing on axis") continue;
    for (int id : cast_primary_rays(stress_case.camera, stress_case.scene).ids) CHECK(id != 1);
    for (const VisibleInterval& interval : exact_footprint(stress_case.camera, stress_case.scene))
      CHECK(interval.id != 1);
  }
}

TEST_CASE("the handout's arccos route loses ~sqrt(2 eps) near ±1, atan2 does not", "[stress][angles]") {
  // Unit vectors a small angle δ from +x (2D) or from +z (3D): the true angle is δ.
  double worst_arccos = 0, worst_stable = 0;
  for (double delta = 1e-12; delta < 1e-2; delta *= 3.7) {
    const glm::dvec2 v2(std::cos(delta), std::sin(delta));
    worst_arccos = std::max(worst_arccos, std::abs(polar_angle(v2, AngleRoute::handout_arccos) - delta));
    worst_stable = std::max(worst_stable, std::abs(polar_angle(v2, AngleRoute::stable) - delta));
    const glm::dvec3 v3(std::cos(0.7) * std::sin(delta), std::sin(0.7) * std::sin(delta), std::cos(delta));
    worst_arccos =
        std::max(worst_arccos, std::abs(spherical_angles(v3, AngleRoute::handout_arccos).phi - delta));
    worst_stable = std::max(worst_stable, std::abs(spherical_angles(v3, AngleRoute::stable).phi - delta));
  }
  const double eps = std::numeric_limits<double>::epsilon();
  CHECK(worst_stable <= 1e-18);                     // relative error of a few ulp of δ ≤ 1e-2
  CHECK(worst_arccos > 0.1 * std::sqrt(eps));       // the √ε loss is real …
  CHECK(worst_arccos <= 2.0 * std::sqrt(2 * eps));  // … and no worse than √(2ε) (≈ 2.1e-8)
}
