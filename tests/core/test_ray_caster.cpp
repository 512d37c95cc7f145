// The plain caster: nearest hit, ties, background, and a cross-check against an independent
// angular visibility test (a ray from the eye sees a ball iff its angle to the centre is below asin(r/dist)).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "raycam/ray_caster.h"
#include "test_support.h"

using namespace raycam;
using test::kPi;

TEST_CASE("ties go to the lower index, misses to the background", "[caster]") {
  Camera2D camera(16);
  camera.set_orbit({{0, 0}, 5.0, kPi / 2, 1.0});
  Scene2D scene;
  scene.background = {1, 2, 3};
  scene.circles = {{{0, 0}, 0.5, {10, 0, 0}, "first"}, {{0, 0}, 0.5, {20, 0, 0}, "identical"}};
  CastOptions plain;  // this file tests the plain loop; every other method: test_ties_and_bounds.cpp
  plain.method = CastMethod::plain;
  const ColourMap map = cast_primary_rays(camera, scene, plain);
  bool saw_hit = false, saw_miss = false;
  for (int c = 0; c < map.width; ++c) {
    CHECK(map.ids[c] != 1);  // the identical second circle never wins
    if (map.ids[c] == 0) {
      saw_hit = true;
      CHECK(map.colours[c] == Rgb8{10, 0, 0});
    }
    if (map.ids[c] == -1) {
      saw_miss = true;
      CHECK(map.colours[c] == Rgb8{1, 2, 3});
    }
  }
  CHECK(saw_hit);
  CHECK(saw_miss);
}

TEST_CASE("the nearest object wins and objects behind the screen are not seen", "[caster]") {
  Camera3D camera(9, 9);
  camera.set_orbit({{0, 0, 0}, 5.0, 0.0, kPi / 2, 1.0});  // on +x looking at the origin
  Scene3D scene;
  scene.spheres = {{{-3, 0, 0}, 1.0, {1, 0, 0}, "far"},
                   {{0, 0, 0}, 1.0, {2, 0, 0}, "near"},
                   {{5.5, 0, 0}, 0.2, {3, 0, 0}, "between eye and screen"}};
  const ColourMap map = cast_primary_rays(camera, scene);
  CHECK(map.id_at(4, 4) == 1);
  Ray3D ray = camera.primary_ray(4, 4);
  CHECK(nearest_hit(scene.spheres, ray, IntersectFormula::stable).t == Approx(4.0));
}

TEST_CASE("the caster agrees with an independent angular visibility test", "[caster][crosscheck]") {
  test::Random random(77);
  for (int trial = 0; trial < 40; ++trial) {
    Scene3D scene;
    for (int i = 0; i < 5; ++i)
      scene.spheres.push_back({{random.uniform(-4, 4), random.uniform(-4, 4), random.uniform(-4, 4)},
                               random.uniform(0.3, 1.5),
                               {std::uint8_t(i), 0, 0},
                               ""});
    Camera3D camera(32, 24);
    camera.set_orbit({{0, 0, 0},
                      random.uniform(12, 20),
                      random.uniform(-kPi, kPi),
                      random.uniform(0.2, 3.0),
                      random.uniform(0.7, 2)});
    const ColourMap map = cast_primary_rays(camera, scene);
    const glm::dvec3 eye = camera.eye();
    for (int r = 0; r < map.height; ++r)
      for (int c = 0; c < map.width; ++c) {
        const Ray3D ray = camera.primary_ray(r, c);
        // Independent: a sphere lies along the eye->pixel direction iff the angle between that direction and
        // its centre is below asin(r / distance). The hit must be one of those, and a miss must have none.
        // (The spheres are far beyond the screen, so the screen-origin rays see what the eye sees.)
        int visible = 0;
        bool hit_is_visible = false;
        for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
          const glm::dvec3 to_centre = scene.spheres[i].centre - eye;
          const double angle =
              std::acos(std::clamp(glm::dot(glm::normalize(to_centre), ray.direction), -1.0, 1.0));
          if (angle < std::asin(scene.spheres[i].radius / glm::length(to_centre))) {
            ++visible;
            hit_is_visible = hit_is_visible || int(i) == map.id_at(r, c);
          }
        }
        if (test::ray_grazes_any(ray, scene.spheres, 1e-9)) continue;
        if (map.id_at(r, c) < 0)
          CHECK(visible == 0);
        else
          CHECK(hit_is_visible);
      }
  }
}

TEST_CASE("stats count rays and tests", "[caster]") {
  Camera3D camera(10, 7);
  CastStats stats;
  CastOptions plain;
  plain.method = CastMethod::plain;
  cast_primary_rays(camera, demo_scene_3d(), plain, &stats);
  CHECK(stats.rays == 70);
  CHECK(stats.intersection_tests == 70 * 5);
  CHECK(stats.objects_culled == 0);
  CHECK(stats.pixels_skipped == 0);
}
