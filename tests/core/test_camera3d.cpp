// Camera3D: the camera invariants 1–7 (docs/testing.md) in 3D, the poles, and analytic expectations.
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/gtc/matrix_access.hpp>
#include <limits>

#include "raycam/ray_caster.h"
#include "raycam/transform.h"
#include "test_support.h"

using namespace raycam;
using test::kPi;

namespace {
glm::dvec3 spherical(double theta, double phi) {
  return {std::cos(theta) * std::sin(phi), std::sin(theta) * std::sin(phi), std::cos(phi)};
}

// The linear part of M_d must be a rotation times H(1, 1, d_f): orthogonal columns of lengths 1, 1, d_f,
// determinant +d_f, nothing NaN.
void check_linear_part(const glm::dmat4& m, double df) {
  const glm::dvec3 c0(m[0]), c1(m[1]), c2(m[2]);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) REQUIRE(std::isfinite(m[i][j]));
  CHECK(std::abs(glm::dot(c0, c1)) <= 1e-12);
  CHECK(std::abs(glm::dot(c0, c2)) <= 1e-12 * df);
  CHECK(std::abs(glm::dot(c1, c2)) <= 1e-12 * df);
  CHECK(glm::length(c0) == Approx(1.0).epsilon(1e-12));
  CHECK(glm::length(c1) == Approx(1.0).epsilon(1e-12));
  CHECK(glm::length(c2) == Approx(df).epsilon(1e-12));
  CHECK(glm::dot(glm::cross(c0, c1), c2) == Approx(df).epsilon(1e-12));
  CHECK(glm::row(m, 3) == glm::dvec4(0, 0, 0, 1));
}

Scene3D random_scene(test::Random& random, int count, double spread) {
  Scene3D scene;
  for (int i = 0; i < count; ++i)
    scene.spheres.push_back(
        {{random.uniform(-spread, spread), random.uniform(-spread, spread), random.uniform(-spread, spread)},
         random.uniform(0.2, 1.2),
         {std::uint8_t(i * 40), 0, 0},
         ""});
  return scene;
}

int count_non_grazing_differences(const ColourMap& a, const ColourMap& b, const Camera3D& camera,
                                  const Scene3D& scene) {
  int bad = 0;
  for (int row = 0; row < a.height; ++row)
    for (int column = 0; column < a.width; ++column)
      if (a.id_at(row, column) != b.id_at(row, column) &&
          !test::ray_grazes_any(camera.primary_ray(row, column), scene.spheres, 1e-9))
        ++bad;
  return bad;
}
}  // namespace

TEST_CASE("3D invariants 1-3 hold over random placements", "[camera3d][invariant]") {
  test::Random random(99);
  for (int trial = 0; trial < 2000; ++trial) {
    Orbit3D orbit;
    orbit.target = {random.uniform(-100, 100), random.uniform(-100, 100), random.uniform(-100, 100)};
    orbit.d = random.log_uniform(1e-3, 1e7);
    orbit.theta = random.uniform(-4 * kPi, 4 * kPi);
    orbit.phi = random.uniform(-0.5, kPi + 0.5);
    orbit.df = random.log_uniform(1e-3, 1e3);
    Camera3D camera(5, 5);  // odd: pixel (2, 2) is the screen centre
    camera.set_orbit(orbit);
    const double scale = glm::length(orbit.target) + orbit.d + orbit.df;
    const glm::dvec3 expected_position = orbit.target + orbit.d * spherical(orbit.theta, orbit.phi);
    CHECK(glm::length(camera.screen_centre() - expected_position) <= 1e-12 * scale);
    CHECK(glm::length(camera.eye() - orbit.target) == Approx(orbit.d + orbit.df).epsilon(1e-9));
    const Ray3D axis = camera.primary_ray(2, 2);
    const glm::dvec3 to_target = orbit.target - axis.origin;
    CHECK(glm::length(glm::cross(axis.direction, to_target)) <= 1e-12 * scale);
    CHECK(glm::dot(axis.direction, to_target) > 0.0);
    check_linear_part(camera.world_from_camera(), orbit.df);
  }
}

TEST_CASE("the poles: phi = 0 and π exactly and within a few ulp", "[camera3d][edge]") {
  const double ulp = std::numeric_limits<double>::epsilon();
  for (double phi :
       {0.0, 4 * ulp, -4 * ulp, kPi, std::nextafter(kPi, 0.0), std::nextafter(kPi, 4.0), kPi + 8 * ulp}) {
    for (double theta : {0.0, kPi, -kPi, 1.0}) {
      for (double df : {1e-9, 1.0, 1e9}) {
        Camera3D camera(3, 3);
        camera.set_orbit({{1, 2, 3}, 4.0, theta, phi, df});
        check_linear_part(camera.world_from_camera(), df);
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) {
            const Ray3D ray = camera.primary_ray(r, c);
            REQUIRE(std::isfinite(glm::dot(ray.direction, ray.direction)));
            CHECK(glm::length(ray.direction) == Approx(1.0).epsilon(1e-15));
          }
        const glm::dvec3 to_target = glm::normalize(glm::dvec3(1, 2, 3) - camera.screen_centre());
        CHECK(glm::length(camera.primary_ray(1, 1).direction - to_target) <= 1e-12);
      }
    }
  }
}

TEST_CASE("world up is up in the image and the image is not mirrored", "[camera3d][invariant]") {
  test::Random random(17);
  for (int trial = 0; trial < 200; ++trial) {
    const double phi = random.uniform(0.05, kPi - 0.05), theta = random.uniform(-kPi, kPi);
    Camera3D camera(64, 64);
    camera.set_orbit({{0, 0, 0}, 10.0, theta, phi, 1.5});
    // Independent frame: forward from the eye to C, right = forward × z (normalised), up = right × forward.
    const glm::dvec3 forward = -spherical(theta, phi);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0, 0, 1)));
    const glm::dvec3 up = glm::cross(right, forward);
    CHECK(up.z > 0.0);
    CHECK(glm::length(camera.image_up() - up) < 1e-12);
    CHECK(glm::length(camera.image_right() - right) < 1e-12);
    for (const auto& [offset, in_expected_half] :
         {std::pair<glm::dvec3, int>{2.0 * right, 0}, {-2.0 * right, 1}, {2.0 * up, 2}, {-2.0 * up, 3}}) {
      Scene3D scene;
      scene.spheres = {{offset, 0.5, {255, 0, 0}, ""}};
      const ColourMap map = cast_primary_rays(camera, scene);
      double mean_row = 0, mean_column = 0;
      int hits = 0;
      for (int r = 0; r < 64; ++r)
        for (int c = 0; c < 64; ++c)
          if (map.id_at(r, c) == 0) mean_row += r, mean_column += c, ++hits;
      REQUIRE(hits > 0);
      mean_row /= hits;
      mean_column /= hits;
      if (in_expected_half == 0) CHECK(mean_column > 32);  // right
      if (in_expected_half == 1) CHECK(mean_column < 32);  // left
      if (in_expected_half == 2) CHECK(mean_row < 32);     // up = top rows
      if (in_expected_half == 3) CHECK(mean_row > 32);
    }
  }
}

TEST_CASE("an object at a known direction lands in the predicted pixel", "[camera3d][analytic]") {
  test::Random random(23);
  for (int trial = 0; trial < 200; ++trial) {
    const int columns = random.integer(2, 80), rows = random.integer(2, 80);
    const Orbit3D orbit{{random.uniform(-3, 3), random.uniform(-3, 3), random.uniform(-3, 3)},
                        random.uniform(1, 20),
                        random.uniform(-kPi, kPi),
                        random.uniform(0.1, kPi - 0.1),
                        random.uniform(0.5, 3)};
    Camera3D camera(columns, rows);
    camera.set_orbit(orbit);
    const glm::dvec3 forward = -spherical(orbit.theta, orbit.phi);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0, 0, 1)));
    const glm::dvec3 up = glm::cross(right, forward);
    const glm::dvec3 eye = orbit.target - (orbit.d + orbit.df) * forward;
    const int row = random.integer(0, rows - 1), column = random.integer(0, columns - 1);
    const double x = -1.0 + (2.0 * column + 1.0) / columns, y = 1.0 - (2.0 * row + 1.0) / rows;
    const glm::dvec3 direction = glm::normalize(orbit.df * forward + x * right + y * up);
    const double range = orbit.d + orbit.df + 5.0;
    const double pixel = 2.0 / std::max(columns, rows) / orbit.df * std::pow(glm::dot(direction, forward), 2);
    Scene3D scene;
    scene.spheres = {{eye + range * direction, range * pixel * 0.2, {1, 1, 1}, ""}};
    const ColourMap map = cast_primary_rays(camera, scene);
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < columns; ++c) CHECK(map.id_at(r, c) == (r == row && c == column ? 0 : -1));
  }
}

TEST_CASE("a scene symmetric about the vertical plane through the view axis gives a symmetric image",
          "[camera3d][invariant]") {
  test::Random random(31);
  for (int trial = 0; trial < 30; ++trial) {
    const Orbit3D orbit{
        {0, 0, 0}, random.uniform(5, 10), random.uniform(-kPi, kPi), random.uniform(0.3, kPi - 0.3), 1.5};
    Camera3D camera(48, 40);
    camera.set_orbit(orbit);
    const glm::dvec3 right = camera.image_right();
    Scene3D scene;
    for (int i = 0; i < 4; ++i) {
      const glm::dvec3 p{random.uniform(-3, 3), random.uniform(-3, 3), random.uniform(-3, 3)};
      const glm::dvec3 mirrored = p - 2.0 * glm::dot(p, right) * right;  // reflect across the plane ⟂ right
      const double r = random.uniform(0.3, 1.0);
      scene.spheres.push_back({p, r, {std::uint8_t(i), 0, 0}, ""});
      scene.spheres.push_back({mirrored, r, {std::uint8_t(i), 0, 0}, ""});
    }
    const ColourMap map = cast_primary_rays(camera, scene);
    for (int r = 0; r < map.height; ++r)
      for (int c = 0; c < map.width; ++c) {
        const int mc = map.width - 1 - c;
        if (map.colour_at(r, c) == map.colour_at(r, mc)) continue;
        CHECK((test::ray_grazes_any(camera.primary_ray(r, c), scene.spheres, 1e-9) ||
               test::ray_grazes_any(camera.primary_ray(r, mc), scene.spheres, 1e-9)));
      }
  }
}

TEST_CASE("rotating about z or translating scene and camera together leaves the image unchanged",
          "[camera3d][invariant]") {
  test::Random random(41);
  for (int trial = 0; trial < 20; ++trial) {
    const Scene3D scene = random_scene(random, 8, 4);
    const Orbit3D orbit{{0.5, -0.5, 0.2},
                        random.uniform(6, 12),
                        random.uniform(-kPi, kPi),
                        random.uniform(0.2, kPi - 0.2),
                        1.5};
    Camera3D camera(40, 40);
    camera.set_orbit(orbit);
    const ColourMap reference = cast_primary_rays(camera, scene);

    const double turn = random.uniform(-kPi, kPi);
    const glm::dvec3 shift{random.uniform(-1e3, 1e3), random.uniform(-1e3, 1e3), random.uniform(-1e3, 1e3)};
    auto move = [&](glm::dvec3 p) {
      const glm::dvec2 xy = test::rotated({p.x, p.y}, turn);
      return glm::dvec3(xy, p.z) + shift;
    };
    Scene3D moved = scene;
    for (Sphere& s : moved.spheres) s.centre = move(s.centre);
    Camera3D moved_camera(40, 40);
    moved_camera.set_orbit({move(orbit.target), orbit.d, orbit.theta + turn, orbit.phi, orbit.df});
    CHECK(count_non_grazing_differences(cast_primary_rays(moved_camera, moved), reference, camera, scene) ==
          0);
  }
}

TEST_CASE("no flip when phi crosses a pole or theta wraps", "[camera3d][invariant]") {
  const Scene3D scene = demo_scene_3d();
  auto render = [&](double theta, double phi) {
    Camera3D camera(64, 64);
    camera.set_orbit({{0, 0, 0}, 8.0, theta, phi, 2.0});
    return cast_primary_rays(camera, scene);
  };
  auto differing = [](const ColourMap& a, const ColourMap& b) {
    int count = 0;
    for (std::size_t i = 0; i < a.ids.size(); ++i) count += a.ids[i] != b.ids[i];
    return count;
  };
  // Across the poles: a tiny step in phi changes at most a few grazing pixels.
  for (double pole : {0.0, kPi})
    for (double theta : {0.0, 2.0, -kPi})
      CHECK(differing(render(theta, pole - 1e-9), render(theta, pole + 1e-9)) <= 4);
  // Wrapping theta at ±π and at 2π.
  CHECK(differing(render(kPi - 1e-12, 1.0), render(-kPi + 1e-12, 1.0)) <= 4);
  CHECK(differing(render(0.5, 1.0), render(0.5 + 2 * kPi, 1.0)) <= 4);
}

TEST_CASE("spherical angles: atan2 is exact at the poles, the handout's arccos loses half the digits",
          "[camera3d][angles]") {
  test::Random random(8);
  for (int trial = 0; trial < 500; ++trial) {
    const double theta = random.uniform(-kPi + 1e-3, kPi - 1e-3), phi = random.uniform(0.2, kPi - 0.2);
    const glm::dvec3 v = random.uniform(0.1, 100) * spherical(theta, phi);
    const SphericalAngles stable = spherical_angles(v, AngleRoute::stable);
    const SphericalAngles arccos = spherical_angles(v, AngleRoute::handout_arccos);
    CHECK(stable.theta == Approx(theta).margin(1e-13));
    CHECK(stable.phi == Approx(phi).margin(1e-13));
    CHECK(arccos.theta == Approx(theta).margin(1e-7));
    CHECK(arccos.phi == Approx(phi).margin(1e-7));
  }
  // At the poles θ is undefined; both routes must stay finite and report φ exactly.
  for (const glm::dvec3& v : {glm::dvec3(0, 0, 2), glm::dvec3(0, 0, -2)}) {
    for (AngleRoute route : {AngleRoute::stable, AngleRoute::handout_arccos}) {
      const SphericalAngles a = spherical_angles(v, route);
      CHECK(std::isfinite(a.theta));
      CHECK(a.phi == (v.z > 0 ? 0.0 : kPi));
    }
  }
  // A tiny polar angle: atan2 recovers it, arccos(z) cannot (cos φ rounds to 1 for φ < ~1e-8).
  const double tiny = 1e-10;
  const glm::dvec3 v = spherical(0.3, tiny);
  CHECK(spherical_angles(v, AngleRoute::stable).phi == Approx(tiny).epsilon(1e-12));
  CHECK(spherical_angles(v, AngleRoute::handout_arccos).phi == 0.0);
}

TEST_CASE("free placement puts the screen at P looking at C", "[camera3d]") {
  test::Random random(4);
  for (int trial = 0; trial < 200; ++trial) {
    const glm::dvec3 target{random.uniform(-5, 5), random.uniform(-5, 5), random.uniform(-5, 5)};
    glm::dvec3 position =
        target + glm::dvec3(random.uniform(-5, 5), random.uniform(-5, 5), random.uniform(-5, 5));
    if (trial % 10 == 0)
      position = target + glm::dvec3(0, 0, trial % 20 == 0 ? 3.0 : -3.0);  // straight above / below
    Camera3D camera(9, 9);
    camera.set_free(position, target, 1.2, AngleRoute::stable);
    CHECK(glm::length(camera.screen_centre() - position) <= 1e-12 * (glm::length(position) + 1));
    const glm::dvec3 to_target = glm::normalize(target - position);
    CHECK(glm::length(camera.view_direction() - to_target) <= 1e-12);
  }
  Camera3D camera(4, 4);
  CHECK_THROWS_WITH(camera.set_free({1, 1, 1}, {1, 1, 1}, 1.0), Catch::Contains("sits on its target"));
}

TEST_CASE("the printed angle convention looks away, sizes and res are checked",
          "[camera3d][input][mistake]") {
  Camera3D camera(10, 6);
  camera.set_orbit({{1, 2, 3}, 5.0, 0.4, 1.1, 1.0});
  const glm::dvec3 towards_target = glm::normalize(glm::dvec3(1, 2, 3) - camera.screen_centre());
  CHECK(glm::dot(camera.view_direction(), towards_target) == Approx(1.0));
  camera.set_mistakes({true, false, false});
  CHECK(glm::dot(camera.view_direction(), towards_target) == Approx(-1.0));

  CHECK(camera.columns() == 10);
  CHECK(camera.rows() == 6);
  camera.set_res(0.5, 1.0 / 6);
  CHECK(camera.columns() == 5);
  CHECK(camera.rows() == 1);
  CHECK_THROWS_WITH(camera.set_res(0.0), Catch::Contains("res"));
  CHECK_THROWS_WITH(Camera3D(0, 10), Catch::Contains("columns"));
  CHECK_THROWS_WITH(Camera3D(16384, 16384), Catch::Contains("columns x rows"));
  CHECK_THROWS_WITH(camera.set_orbit({{0, 0, 0}, 1.0, 0.0, std::numeric_limits<double>::infinity(), 1.0}),
                    Catch::Contains("phi"));
}

TEST_CASE("construction steps go from the identity to M_d, factor by factor", "[camera3d]") {
  // Each factor written out here from docs/conventions.md's formula (rows as printed; GLM stores columns, hence the
  // transpose), not through raycam's transform.h: M_d = T(OP)·R_z(θ)·R_y(φ)·R_z(π/2)·H(1, 1, d_f).
  const double theta = 0.4, phi = 1.1, df = 2.0;
  const glm::dvec3 target(1, 2, 3), position = target + 5.0 * spherical(theta, phi);
  Camera3D camera(4, 4);
  camera.set_orbit({target, 5.0, theta, phi, df});
  const Placement3D& p = camera.placement();
  auto rows = [](std::initializer_list<double> values) {
    glm::dmat4 m;
    auto it = values.begin();
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) m[c][r] = *it++;
    return m;
  };
  const double ct = std::cos(theta), st = std::sin(theta), cp = std::cos(phi), sp = std::sin(phi);
  const glm::dmat4 h = rows({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, df, 0, 0, 0, 0, 1});
  const glm::dmat4 roll = rows({0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});  // R_z(π/2)
  const glm::dmat4 polar = rows({cp, 0, sp, 0, 0, 1, 0, 0, -sp, 0, cp, 0, 0, 0, 0, 1});
  const glm::dmat4 azimuth = rows({ct, -st, 0, 0, st, ct, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
  const glm::dmat4 t = rows({1, 0, 0, position.x, 0, 1, 0, position.y, 0, 0, 1, position.z, 0, 0, 0, 1});
  const glm::dmat4 by_hand[] = {glm::dmat4(1.0),
                                h,
                                roll * h,
                                polar * roll * h,
                                azimuth * polar * roll * h,
                                t * azimuth * polar * roll * h};
  auto close = [](const glm::dmat4& a, const glm::dmat4& b) {
    double worst = 0;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) worst = std::max(worst, std::abs(a[c][r] - b[c][r]));
    return worst <= 1e-14 * 8;  // |entries| ≤ ~8 here: a few ulp of rounding in a five-factor product
  };
  for (int step = 0; step <= 5; ++step) {
    INFO("step " << step);
    CHECK(close(construction_step(p, step), by_hand[step]));
  }
  CHECK(close(camera.world_from_camera(), by_hand[5]));
  // The roll, seen through the image's up vector M_d·(0,1,0): after step 2 canonical up has turned to -x,
  // and in the end it is (−cos θ cos φ, −sin θ cos φ, sin φ) (docs/conventions.md): world +z is up.
  CHECK(glm::length(transform_vector(construction_step(p, 2), {0, 1, 0}) - glm::dvec3(-1, 0, 0)) < 1e-15);
  CHECK(glm::length(camera.image_up() - glm::dvec3(-ct * cp, -st * cp, sp)) < 1e-15);
  CHECK(camera.image_up().z > 0);
  CHECK_THROWS_WITH(construction_step(p, 6), Catch::Contains("construction step"));
}
