// The exact 2D bar checked against independent facts: a circle's angular size seen from the eye, dense
// sampling by the plain caster, mirror symmetry, a screen cutting a circle, and coverage summing to one.
#include <catch2/catch.hpp>
#include <cmath>

#include "raycam/exact_bar.h"
#include "raycam/ray_caster.h"
#include "test_support.h"

using namespace raycam;
using raycam::test::kPi;
using raycam::test::Random;

namespace {
Camera2D camera_at(int n, double d, double theta, double df, glm::dvec2 target = {0, 0}) {
  Camera2D camera(n);
  camera.set_orbit(Orbit2D{target, d, theta, df});
  return camera;
}

Scene2D random_scene(Random& random, int count, double spread) {
  Scene2D scene;
  for (int i = 0; i < count; ++i) {
    Circle c;
    c.centre = {random.uniform(-spread, spread), random.uniform(-spread, spread)};
    c.radius = random.uniform(0.2, 1.5);
    c.colour = Rgb8{std::uint8_t(random.integer(0, 255)), std::uint8_t(random.integer(0, 255)),
                    std::uint8_t(random.integer(0, 255))};
    scene.circles.push_back(c);
  }
  return scene;
}
}  // namespace

TEST_CASE("a lone circle's footprint spans 2·asin(r/D) as seen from the eye", "[exact]") {
  Random random(11);
  for (int trial = 0; trial < 200; ++trial) {
    const double df = random.log_uniform(0.2, 5.0);
    const Camera2D camera = camera_at(64, random.uniform(4, 30), random.uniform(-kPi, kPi), df);
    // A circle on the view axis beyond the target, small enough to lie wholly inside the field of view.
    const double distance_beyond = random.uniform(0.0, 5.0);
    const glm::dvec2 v = camera.view_direction();
    Scene2D scene;
    Circle c;
    c.centre =
        camera.orbit().target + distance_beyond * v + random.uniform(-0.3, 0.3) * glm::dvec2(-v.y, v.x);
    const double eye_distance = glm::length(c.centre - camera.eye());
    c.radius = random.uniform(0.05, 0.4) * eye_distance * std::tan(std::atan(1.0 / df) / 2);
    scene.circles.push_back(c);

    const auto footprint = exact_footprint(camera, scene);
    REQUIRE(footprint.size() == 3);  // background, the circle, background
    CHECK(footprint[1].id == 0);
    // The ray through s leaves the eye at angle atan(s/d_f) from the view axis (|M_d·(1,0)| = 1).
    const double seen = std::atan(footprint[1].s_end / df) - std::atan(footprint[1].s_begin / df);
    CHECK(seen == Approx(2 * std::asin(c.radius / eye_distance)).epsilon(1e-11));
  }
}

TEST_CASE("coverage fractions sum to one and match dense sampling by the plain caster",
          "[exact][crosscheck]") {
  Random random(12);
  const int n = 24, m = 401;  // m sub-pixels per pixel: their centres are stratified samples of the pixel
  for (int trial = 0; trial < 40; ++trial) {
    const Scene2D scene = random_scene(random, random.integer(1, 7), 3.0);  // overlaps are common
    const double d = random.uniform(0.5, 8), theta = random.uniform(-kPi, kPi),
                 df = random.log_uniform(0.3, 3);
    const Camera2D coarse = camera_at(n, d, theta, df);
    const Camera2D fine = camera_at(n * m, d, theta, df);
    const ExactBar bar = exact_bar(coarse, scene);
    const ColourMap dense = cast_primary_rays(fine, scene);
    for (int column = 0; column < n; ++column) {
      double total = 0;
      for (int id = -1; id < bar.objects; ++id) total += bar.coverage_of(column, id);
      CHECK(total == Approx(1.0).margin(1e-12));
      // Fine columns n·m-1-(k·m+j) for j < m all belong to coarse pixel k = n-1-column.
      const int k = n - 1 - column;
      for (int id = -1; id < bar.objects; ++id) {
        int count = 0;
        for (int j = 0; j < m; ++j) count += dense.ids[std::size_t(fine.column_of_pixel(k * m + j))] == id;
        // Each breakpoint inside the pixel shifts the count by at most one sample.
        INFO("trial " << trial << " column " << column << " id " << id);
        CHECK(std::abs(double(count) / m - bar.coverage_of(column, id)) <= 8.0 / m);
      }
    }
  }
}

TEST_CASE("exact centre ids agree with the plain caster away from grazing rays", "[exact][crosscheck]") {
  Random random(13);
  for (int trial = 0; trial < 50; ++trial) {
    const Scene2D scene = random_scene(random, random.integer(1, 8), 4.0);
    const Camera2D camera =
        camera_at(128, random.uniform(0.5, 10), random.uniform(-kPi, kPi), random.uniform(0.5, 3));
    const ExactBar bar = exact_bar(camera, scene);
    const ColourMap map = cast_primary_rays(camera, scene);
    for (int k = 0; k < camera.pixel_count(); ++k) {
      const int column = camera.column_of_pixel(k);
      if (raycam::test::ray_grazes_any(camera.primary_ray(k), scene.circles)) continue;
      CHECK(bar.centre_ids[std::size_t(column)] == map.ids[std::size_t(column)]);
    }
  }
}

TEST_CASE("a scene symmetric about the view axis gives mirror-symmetric coverage", "[exact][invariant]") {
  Scene2D scene;
  const double x[] = {0.0, -2.0, 2.0, -3.5, 3.5}, y[] = {0.0, -1.0, -1.0, -4.0, -4.0},
               r[] = {0.8, 0.6, 0.6, 1, 1};
  for (int i = 0; i < 5; ++i) scene.circles.push_back(Circle{{x[i], y[i]}, r[i], Rgb8{}, ""});
  const int mirror_of[] = {0, 2, 1, 4, 3};
  const Camera2D camera = camera_at(101, 5.0, kPi / 2, 1.0);
  const ExactBar bar = exact_bar(camera, scene);
  const int n = bar.pixels;
  for (int column = 0; column < n; ++column) {
    CHECK(bar.coverage_of(column, -1) == Approx(bar.coverage_of(n - 1 - column, -1)).margin(1e-9));
    for (int id = 0; id < 5; ++id)
      CHECK(bar.coverage_of(column, id) ==
            Approx(bar.coverage_of(n - 1 - column, mirror_of[id])).margin(1e-9));
  }
}

TEST_CASE("a screen cutting through a circle sees it exactly where the screen is inside", "[exact][stress]") {
  // A circle centred on the screen centre: rays that start inside see its far side; rays starting outside
  // diverge from the axis and never come back. So the footprint is exactly s ∈ [-ρ, ρ].
  for (double rho : {0.25, 0.5, 0.999}) {
    const Camera2D camera = camera_at(16, 7.0, 0.3, 1.2, {1.0, -2.0});
    Scene2D scene;
    scene.circles.push_back(Circle{camera.screen_centre(), rho, Rgb8{}, ""});
    const auto footprint = exact_footprint(camera, scene);
    REQUIRE(footprint.size() == 3);
    CHECK(footprint[1].id == 0);
    CHECK(footprint[1].s_begin == Approx(-rho).margin(1e-12));
    CHECK(footprint[1].s_end == Approx(rho).margin(1e-12));
  }
}

TEST_CASE("the exact bar image averages colours by coverage", "[exact]") {
  Scene2D scene;
  scene.background = Rgb8{0, 0, 0};
  scene.circles.push_back(Circle{{0, 0}, 1.0, Rgb8{200, 100, 50}, ""});
  const Camera2D camera = camera_at(7, 5.0, kPi / 2, 1.0);
  const ExactBar bar = exact_bar(camera, scene);
  const CoverageImage image = exact_bar_image(bar, scene);
  for (int column = 0; column < 7; ++column) {
    const double w = bar.coverage_of(column, 0);
    CHECK(image.colours[std::size_t(column)].x == Approx(200 * w).margin(1e-9));
    CHECK(image.colours[std::size_t(column)].z == Approx(50 * w).margin(1e-9));
  }
}

TEST_CASE("the exact bar refuses scenes beyond its quadratic budget", "[exact]") {
  Random random(14);
  const Camera2D camera = camera_at(16, 6.0, kPi / 2, 1.5);
  const Scene2D scene = random_scene(random, int(kMaxExactBarCircles) + 1, 50.0);
  CHECK_THROWS_WITH(exact_bar(camera, scene), Catch::Contains("circles"));
}
