// Camera2D: the camera invariants 1–7 (docs/testing.md) in 2D and the handout's analytic expectations.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "raycam/ray_caster.h"
#include "test_support.h"

using namespace raycam;
using test::kPi;

namespace {
Orbit2D random_orbit(test::Random& random) {
  Orbit2D orbit;
  orbit.target = {random.uniform(-100, 100), random.uniform(-100, 100)};
  orbit.d = random.log_uniform(1e-3, 1e7);
  orbit.theta = random.uniform(-4 * kPi, 4 * kPi);
  orbit.df = random.log_uniform(1e-3, 1e3);
  return orbit;
}

// The linear part of M_d must be a rotation times H(1, d_f).
void check_linear_part(const glm::dmat3& m, double df) {
  const glm::dvec2 column0(m[0]), column1(m[1]);
  CHECK(std::abs(glm::dot(column0, column1)) <= 1e-12 * df);
  CHECK(glm::length(column0) == Approx(1.0).epsilon(1e-12));
  CHECK(glm::length(column1) == Approx(df).epsilon(1e-12));
  const double det = column0.x * column1.y - column0.y * column1.x;
  CHECK(det == Approx(df).epsilon(1e-12));
  CHECK(m[0][2] == 0.0);
  CHECK(m[1][2] == 0.0);
  CHECK(m[2][2] == 1.0);
}
}  // namespace

TEST_CASE("2D invariants 1-3 hold over random placements", "[camera2d][invariant]") {
  test::Random random(2024);
  for (int trial = 0; trial < 2000; ++trial) {
    const Orbit2D orbit = random_orbit(random);
    Camera2D camera(65);  // odd: pixel 32 is the screen centre
    camera.set_orbit(orbit);
    const glm::dvec2 expected_position =
        orbit.target + orbit.d * glm::dvec2(std::cos(orbit.theta), std::sin(orbit.theta));
    const double scale = glm::length(orbit.target) + orbit.d + orbit.df;
    // 1. screen centre at P; eye at P - d_f·v, so at distance d + d_f from C.
    CHECK(glm::length(camera.screen_centre() - expected_position) <= 1e-12 * scale);
    CHECK(glm::length(camera.eye() - orbit.target) == Approx(orbit.d + orbit.df).epsilon(1e-9));
    // 2. the ray from the eye through the screen centre (the centre pixel's primary ray) passes through C.
    //    (Rebuilding it as screen_centre - eye would cancel when d_f << |P|; the camera's ray does not.)
    const Ray2D axis = camera.primary_ray(32);
    const glm::dvec2 to_target = orbit.target - axis.origin;
    CHECK(std::abs(axis.direction.x * to_target.y - axis.direction.y * to_target.x) <= 1e-12 * scale);
    CHECK(glm::dot(axis.direction, to_target) > 0.0);  // in front, not behind
    // 3. orthogonal columns, det +d_f.
    check_linear_part(camera.world_from_camera(), orbit.df);
  }
}

TEST_CASE("2D edge angles and extreme focal distances give finite, correct placements", "[camera2d][edge]") {
  const double ulp = std::numeric_limits<double>::epsilon();
  for (double theta :
       {0.0, kPi, -kPi, std::nextafter(kPi, 0.0), std::nextafter(-kPi, 0.0), 2 * kPi, ulp, -ulp}) {
    for (double df : {1e-9, 1e-3, 1.0, 1e3, 1e9}) {
      Camera2D camera(3);  // odd n: the middle ray is the axis itself
      camera.set_orbit({{1.0, -2.0}, 5.0, theta, df});
      check_linear_part(camera.world_from_camera(), df);
      for (int k = 0; k < camera.pixel_count(); ++k) {
        const Ray2D ray = camera.primary_ray(k);
        REQUIRE(std::isfinite(ray.direction.x));
        REQUIRE(std::isfinite(ray.direction.y));
        CHECK(glm::length(ray.direction) == Approx(1.0).epsilon(1e-15));
      }
      // The middle ray points at the target.
      const Ray2D middle = camera.primary_ray(1);
      const glm::dvec2 to_target = glm::normalize(glm::dvec2(1.0, -2.0) - middle.origin);
      CHECK(glm::length(middle.direction - to_target) <= 1e-12);
    }
  }
}

TEST_CASE("pixel centres are symmetric and res controls n", "[camera2d]") {
  Camera2D camera(100);
  CHECK(camera.pixel_count() == 100);
  camera.set_res(0.5);
  CHECK(camera.pixel_count() == 50);
  camera.set_res(1.0 / 100);  // res = 1/N gives a single pixel, on the axis
  CHECK(camera.pixel_count() == 1);
  CHECK(camera.canonical_pixel(0).x == 0.0);
  camera.set_res(1e-9);  // never 0 pixels
  CHECK(camera.pixel_count() == 1);
  camera.set_res(0.37);
  const int n = camera.pixel_count();
  CHECK(n == 37);
  for (int k = 0; k < n; ++k)
    CHECK(camera.canonical_pixel(k).x == Approx(-camera.canonical_pixel(n - 1 - k).x).margin(1e-15));
  CHECK(camera.canonical_pixel(0).x == Approx(-1.0 + 1.0 / n));
  CHECK_THROWS_WITH(camera.set_res(0.0), Catch::Contains("res") && Catch::Contains("]0, 1]"));
  CHECK_THROWS_WITH(camera.set_res(1.5), Catch::Contains("res"));
  CHECK_THROWS_WITH(camera.set_res(std::nan("")), Catch::Contains("res"));
  CHECK(camera.pixel_count() == 37);  // a refused value changes nothing
}

TEST_CASE("bad placements are refused with the field name", "[camera2d][input]") {
  Camera2D camera(8);
  CHECK_THROWS_WITH(camera.set_orbit({{0, 0}, 0.0, 0.0, 1.0}), Catch::Contains("d = 0"));
  CHECK_THROWS_WITH(camera.set_orbit({{0, 0}, 1.0, 0.0, -1.0}), Catch::Contains("df"));
  CHECK_THROWS_WITH(camera.set_orbit({{0, 0}, 1.0, std::nan(""), 1.0}), Catch::Contains("theta"));
  CHECK_THROWS_WITH(camera.set_orbit({{std::numeric_limits<double>::infinity(), 0}, 1.0, 0.0, 1.0}),
                    Catch::Contains("target.x"));
  CHECK_THROWS_WITH(camera.set_free({2, 3}, {2, 3}, 1.0), Catch::Contains("sits on its target"));
  CHECK_THROWS_AS(Camera2D(0), std::invalid_argument);
  CHECK_THROWS_AS(Camera2D(1 << 21), std::invalid_argument);
}

TEST_CASE("field of view is 2·atan(1/d_f)", "[camera2d][analytic]") {
  for (double df : {0.25, 1.0, 1.5, 4.0}) {
    for (int n : {2, 15, 256}) {
      Camera2D camera(n);
      camera.set_orbit({{0, 0}, 3.0, 0.7, df});
      // The extreme pixel centres sit at ±(1 - 1/n) on the screen, d_f in front of the eye.
      const double spread =
          std::acos(glm::dot(camera.primary_ray(0).direction, camera.primary_ray(n - 1).direction));
      CHECK(spread == Approx(2 * std::atan((1.0 - 1.0 / n) / df)).epsilon(1e-12));
    }
    // A circle centred on the axis fills the whole bar iff it subtends more than the field of view.
    Camera2D camera(200);
    camera.set_orbit({{0, 0}, 10.0, 0.3, df});
    const double eye_distance = 10.0 + df, half_fov = std::atan(1.0 / df);
    Scene2D wide, narrow;
    wide.circles = {{{0, 0}, eye_distance * std::sin(half_fov) * 1.001, {1, 2, 3}, ""}};
    narrow.circles = {
        {{0, 0}, eye_distance * std::sin(std::atan((1.0 - 1.0 / 200) / df)) * 0.999, {1, 2, 3}, ""}};
    if (wide.circles[0].radius < 10.0) {  // the screen must stay outside the circle for this argument
      const ColourMap full = cast_primary_rays(camera, wide);
      for (int id : full.ids) CHECK(id == 0);
      const ColourMap partial = cast_primary_rays(camera, narrow);
      CHECK(partial.ids.front() == -1);
      CHECK(partial.ids.back() == -1);
      CHECK(partial.ids[100] == 0);
    }
  }
}

TEST_CASE("an object at a known angle lands in the predicted pixel, on the eye's side",
          "[camera2d][analytic][invariant]") {
  test::Random random(7);
  for (int trial = 0; trial < 300; ++trial) {
    const int n = random.integer(2, 400);
    Camera2D camera(n);
    const Orbit2D orbit{{random.uniform(-5, 5), random.uniform(-5, 5)},
                        random.uniform(0.5, 20),
                        random.uniform(-kPi, kPi),
                        random.uniform(0.3, 3)};
    camera.set_orbit(orbit);
    // Independent geometry: forward f from the eye to C, left = f turned +90° (counter-clockwise).
    const glm::dvec2 eye =
        orbit.target + (orbit.d + orbit.df) * glm::dvec2(std::cos(orbit.theta), std::sin(orbit.theta));
    const glm::dvec2 forward = glm::normalize(orbit.target - eye);
    const glm::dvec2 left{-forward.y, forward.x};
    const int k = random.integer(0, n - 1);
    const double x = -1.0 + (2.0 * k + 1.0) / n;   // canonical +x is the eye's left
    const double angle = std::atan(x / orbit.df);  // from the axis, towards the left
    const double range = orbit.d + orbit.df + random.uniform(1, 10);
    Scene2D scene;
    const double pixel_angle = 2.0 / n * orbit.df / (orbit.df * orbit.df + x * x);  // d(angle)/dk
    scene.circles = {{eye + range * (std::cos(angle) * forward + std::sin(angle) * left),
                      range * pixel_angle * 0.2,
                      {9, 9, 9},
                      ""}};
    const ColourMap map = cast_primary_rays(camera, scene);
    const int expected_column = n - 1 - k;  // column 0 is the eye's left
    for (int c = 0; c < n; ++c) CHECK(map.ids[c] == (c == expected_column ? 0 : -1));
  }
}

TEST_CASE("the bar is not mirrored: what is on the eye's left is on the left", "[camera2d][invariant]") {
  // Camera above the origin looking down (-y): its left is +x.
  Camera2D camera(32);
  camera.set_orbit({{0, 0}, 5.0, kPi / 2, 1.0});
  Scene2D scene;
  scene.circles = {{{2.0, 0.0}, 0.5, {255, 0, 0}, "on +x"}};
  const ColourMap map = cast_primary_rays(camera, scene);
  int first_hit = -1;
  for (int c = 0; c < map.width; ++c)
    if (map.ids[c] == 0 && first_hit < 0) first_hit = c;
  CHECK(first_hit >= 0);
  CHECK(first_hit < map.width / 2);
}

TEST_CASE("a scene symmetric about the view axis gives a symmetric bar", "[camera2d][invariant]") {
  test::Random random(11);
  for (int trial = 0; trial < 100; ++trial) {
    const Orbit2D orbit{{random.uniform(-10, 10), random.uniform(-10, 10)},
                        random.uniform(1, 10),
                        random.uniform(-kPi, kPi),
                        random.uniform(0.5, 2)};
    Camera2D camera(random.integer(1, 300));
    camera.set_orbit(orbit);
    const glm::dvec2 back{std::cos(orbit.theta), std::sin(orbit.theta)};  // C -> P
    const glm::dvec2 side{-back.y, back.x};
    Scene2D scene;
    for (int i = 0; i < 4; ++i) {
      const double along = random.uniform(-8, 4), across = random.uniform(0, 6), r = random.uniform(0.2, 1.5);
      const Rgb8 colour{std::uint8_t(i), 0, 0};
      scene.circles.push_back({orbit.target + along * back + across * side, r, colour, ""});
      scene.circles.push_back({orbit.target + along * back - across * side, r, colour, ""});
    }
    const ColourMap map = cast_primary_rays(camera, scene);
    const int n = map.width;
    for (int c = 0; c < n; ++c) {
      if (map.colours[c] == map.colours[n - 1 - c]) continue;
      // Only a ray that grazes a circle may disagree with its mirror image.
      const bool grazing =
          test::ray_grazes_any(camera.primary_ray(camera.pixel_of_column(c)), scene.circles, 1e-9) ||
          test::ray_grazes_any(camera.primary_ray(camera.pixel_of_column(n - 1 - c)), scene.circles, 1e-9);
      CHECK(grazing);
    }
  }
}

TEST_CASE("rotating or translating scene and camera together leaves the bar unchanged",
          "[camera2d][invariant]") {
  test::Random random(5);
  for (int trial = 0; trial < 100; ++trial) {
    Scene2D scene;
    for (int i = 0; i < 6; ++i)
      scene.circles.push_back({{random.uniform(-5, 5), random.uniform(-5, 5)},
                               random.uniform(0.2, 1.5),
                               {std::uint8_t(i), 0, 0},
                               ""});
    const Orbit2D orbit{{random.uniform(-2, 2), random.uniform(-2, 2)},
                        random.uniform(4, 12),
                        random.uniform(-kPi, kPi),
                        random.uniform(0.5, 2)};
    Camera2D camera(128);
    camera.set_orbit(orbit);
    const ColourMap reference = cast_primary_rays(camera, scene);

    const double turn = random.uniform(-kPi, kPi);
    const glm::dvec2 shift{random.uniform(-1e3, 1e3), random.uniform(-1e3, 1e3)};
    Scene2D moved = scene;
    for (Circle& c : moved.circles) c.centre = test::rotated(c.centre, turn) + shift;
    Camera2D moved_camera(128);
    moved_camera.set_orbit(
        {test::rotated(orbit.target, turn) + shift, orbit.d, orbit.theta + turn, orbit.df});
    const ColourMap map = cast_primary_rays(moved_camera, moved);
    for (int c = 0; c < map.width; ++c) {
      if (map.ids[c] == reference.ids[c]) continue;
      CHECK(test::ray_grazes_any(camera.primary_ray(camera.pixel_of_column(c)), scene.circles, 1e-9));
    }
  }
}

TEST_CASE("the image is continuous when theta wraps at 2π", "[camera2d][invariant]") {
  const Scene2D scene = demo_scene_2d();
  Camera2D a(256), b(256);
  for (double theta : {kPi, -kPi, 0.0}) {
    a.set_orbit({{0, 0}, 6.0, theta - 1e-12, 1.5});
    b.set_orbit({{0, 0}, 6.0, theta + 1e-12 + 2 * kPi, 1.5});
    const ColourMap ma = cast_primary_rays(a, scene), mb = cast_primary_rays(b, scene);
    int differing = 0;
    for (int c = 0; c < 256; ++c) differing += ma.ids[c] != mb.ids[c];
    CHECK(differing <= 1);
  }
}

TEST_CASE("the handout's printed rotation looks away from the target", "[camera2d][mistake]") {
  Camera2D camera(16);
  camera.set_orbit({{1, 2}, 4.0, 0.9, 1.0});
  const glm::dvec2 towards_target = glm::normalize(glm::dvec2(1, 2) - camera.screen_centre());
  CHECK(glm::dot(camera.view_direction(), towards_target) == Approx(1.0));
  camera.set_mistakes({true, false, false});
  CHECK(glm::dot(camera.view_direction(), towards_target) == Approx(-1.0));
  CHECK(glm::length(camera.screen_centre() -
                    (glm::dvec2(1, 2) + 4.0 * glm::dvec2(std::cos(0.9), std::sin(0.9)))) < 1e-12);
}

TEST_CASE("free placement: atan2 and the handout's arccos agree away from ±1, arccos loses digits near it",
          "[camera2d]") {
  test::Random random(3);
  for (int trial = 0; trial < 200; ++trial) {
    const glm::dvec2 v{random.uniform(-1, 1), random.uniform(-1, 1)};
    const double reference = std::atan2(v.y, v.x);
    CHECK(polar_angle(v, AngleRoute::stable) == Approx(reference).margin(1e-15));
    if (std::abs(v.y) > 0.1 * glm::length(v))
      CHECK(polar_angle(v, AngleRoute::handout_arccos) == Approx(reference).margin(1e-13));
  }
  // Near x_v = 1 (the view vector almost along +x) a tiny angle is recovered by atan2, not by arccos.
  const double tiny = 1e-9;
  const glm::dvec2 v{std::cos(tiny), std::sin(tiny)};
  CHECK(polar_angle(v, AngleRoute::stable) == Approx(tiny).epsilon(1e-12));
  CHECK(std::abs(polar_angle(v, AngleRoute::handout_arccos) - tiny) > 1e-2 * tiny);

  Camera2D camera(8);
  camera.set_free({3, 4}, {1, 1}, 2.0);
  CHECK(camera.orbit().d == Approx(std::sqrt(13.0)));
  CHECK(glm::length(camera.screen_centre() - glm::dvec2(3, 4)) < 1e-12);
}
