// The configurable caster: it reproduces the plain caster exactly at its default knobs, converges to the
// exact 2D bar with samples, and rejects bad knobs.
#include <catch2/catch.hpp>
#include <cmath>

#include "raycam/exact_bar.h"
#include "raycam/ray_caster.h"
#include "raycam/reference_caster.h"
#include "test_support.h"

using namespace raycam;
using raycam::test::kPi;
using raycam::test::Random;

namespace {
Scene2D random_scene_2d(Random& random, int count, double spread, glm::dvec2 offset = {0, 0}) {
  Scene2D scene;
  for (int i = 0; i < count; ++i)
    scene.circles.push_back(
        Circle{offset + glm::dvec2(random.uniform(-spread, spread), random.uniform(-spread, spread)),
               random.uniform(0.2, 1.5),
               Rgb8{std::uint8_t(random.integer(0, 255)), std::uint8_t(random.integer(0, 255)), 7}, ""});
  return scene;
}
Scene3D random_scene_3d(Random& random, int count, double spread) {
  Scene3D scene;
  for (int i = 0; i < count; ++i)
    scene.spheres.push_back(Sphere{
        {random.uniform(-spread, spread), random.uniform(-spread, spread), random.uniform(-spread, spread)},
        random.uniform(0.2, 1.5),
        Rgb8{std::uint8_t(random.integer(0, 255)), 3, std::uint8_t(random.integer(0, 255))},
        ""});
  return scene;
}
// A camera above a scene of half-size ~3 around the origin, at a random distance in [d_lo, d_hi].
Camera2D random_camera_2d(Random& random, int pixels, double d_lo, double d_hi) {
  return Camera2D(
      pixels, Orbit2D{{0, 0}, random.uniform(d_lo, d_hi), random.uniform(-kPi, kPi), random.uniform(0.5, 2)});
}
}  // namespace

TEST_CASE("spp 1, double, stable, world coordinates equals cast_primary_rays id for id", "[reference]") {
  Random random(21);
  const ReferenceOptions defaults;  // double, stable, 1 spp, world
  for (int trial = 0; trial < 60; ++trial) {
    // Wide ranges on purpose, including far and translated cameras where rounding matters.
    const glm::dvec2 offset(random.log_uniform(1e-3, 1e6), -random.log_uniform(1e-3, 1e6));
    const Scene2D scene = random_scene_2d(random, random.integer(1, 10), 4.0, offset);
    Camera2D camera(random.integer(1, 300));
    camera.set_orbit(Orbit2D{offset, random.log_uniform(1e-2, 1e5), random.uniform(-kPi, kPi),
                             random.log_uniform(1e-3, 1e3)});
    CHECK(reference_cast(camera, scene, defaults).ids == cast_primary_rays(camera, scene).ids);
  }
  for (int trial = 0; trial < 15; ++trial) {
    const Scene3D scene = random_scene_3d(random, random.integer(1, 8), 3.0);
    Camera3D camera(random.integer(1, 40), random.integer(1, 40));
    camera.set_orbit(Orbit3D{{0, 0, 0},
                             random.log_uniform(0.5, 1e4),
                             random.uniform(-kPi, kPi),
                             random.uniform(0, kPi),
                             random.log_uniform(0.1, 10)});
    CHECK(reference_cast(camera, scene, defaults).ids == cast_primary_rays(camera, scene).ids);
  }
}

TEST_CASE("every scalar and frame agrees with the plain caster on ordinary scenes, except grazing rays",
          "[reference]") {
  Random random(22);
  for (int trial = 0; trial < 20; ++trial) {
    const Scene2D scene = random_scene_2d(random, random.integer(1, 6), 3.0);
    const Camera2D camera = random_camera_2d(random, 97, 3, 10);
    const ColourMap plain = cast_primary_rays(camera, scene);
    for (Scalar scalar : {Scalar::float32, Scalar::float64, Scalar::extended})
      for (bool relative : {false, true}) {
        const CoverageImage image =
            reference_cast(camera, scene, ReferenceOptions{scalar, IntersectFormula::stable, 1, relative});
        for (int k = 0; k < camera.pixel_count(); ++k) {
          const std::size_t column = std::size_t(camera.column_of_pixel(k));
          // float rounds at ~6e-8 relative; treat rays within 1e-5 of a silhouette as grazing.
          if (raycam::test::ray_grazes_any(camera.primary_ray(k), scene.circles, 1e-5)) continue;
          CHECK(image.ids[column] == plain.ids[column]);
        }
      }
  }
}

TEST_CASE("stratified samples converge to the exact bar's coverage colours", "[reference][crosscheck]") {
  Random random(23);
  for (int trial = 0; trial < 10; ++trial) {
    const Scene2D scene = random_scene_2d(random, random.integer(2, 6), 3.0);
    const Camera2D camera = random_camera_2d(random, 40, 3, 8);
    const ExactBar bar = exact_bar(camera, scene);
    const CoverageImage exact = exact_bar_image(bar, scene);
    const double breakpoints = double(bar.footprint.size() - 1);
    for (int spp : {1, 16, 256}) {
      const double error = mean_colour_error(
          reference_cast(camera, scene,
                         ReferenceOptions{Scalar::float64, IntersectFormula::stable, spp, false}),
          exact);
      // Each visibility change inside a pixel misclassifies at most one stratum of it (colour error ≤ 255
      // per channel over 1/spp of that pixel): the mean falls like 1/spp.
      CHECK(error <= 255.0 * breakpoints / spp / camera.pixel_count() + 1e-9);
    }
  }
}

TEST_CASE("3D supersampling of a sphere seen head-on converges to its disc area", "[reference][crosscheck]") {
  // A sphere on the view axis projects to a disc of screen radius ρ' = d_f·tan(asin(r/D)) (D from the eye);
  // on a 1-pixel camera the covered fraction of the 2×2 screen square is π ρ'² / 4.
  Scene3D scene;
  scene.background = Rgb8{0, 0, 0};
  scene.spheres.push_back(Sphere{{0, 0, 0}, 1.0, Rgb8{255, 255, 255}, ""});
  Camera3D camera(1, 1);
  camera.set_orbit(Orbit3D{{0, 0, 0}, 4.0, 0.4, 1.1, 2.0});
  const double eye_distance = 4.0 + 2.0;
  const double disc = 2.0 * std::tan(std::asin(1.0 / eye_distance));
  const double expected = kPi * disc * disc / 4.0;
  const CoverageImage image = reference_cast(
      camera, scene, ReferenceOptions{Scalar::float64, IntersectFormula::stable, 256 * 256, true});
  CHECK(image.colours[0].x / 255.0 == Approx(expected).margin(2e-4));
  CHECK(image.ids[0] == 0);
}

TEST_CASE("bad knobs are refused with the field named", "[reference]") {
  Camera3D camera(4, 4);
  Scene3D scene;
  CHECK_THROWS_WITH(
      reference_cast(camera, scene, ReferenceOptions{Scalar::float64, IntersectFormula::stable, 8, false}),
      Catch::Contains("perfect square"));
  Camera2D camera2d(4);
  CHECK_THROWS_WITH(reference_cast(camera2d, Scene2D{},
                                   ReferenceOptions{Scalar::float64, IntersectFormula::stable, 0, false}),
                    Catch::Contains("samples_per_pixel"));
}

TEST_CASE("one rule picks the caster: where it says fast, the fast caster gives the reference's image",
          "[reference][caster-choice]") {
  CHECK_FALSE(needs_reference_caster(ReferenceOptions{}, false));
  CHECK(needs_reference_caster(ReferenceOptions{}, true));  // the exact 2D bar
  CHECK(needs_reference_caster(ReferenceOptions{Scalar::float32}, false));
  CHECK(needs_reference_caster(ReferenceOptions{Scalar::extended}, false));
  CHECK(needs_reference_caster(ReferenceOptions{Scalar::float64, IntersectFormula::stable, 4}, false));
  CHECK(needs_reference_caster(ReferenceOptions{Scalar::float64, IntersectFormula::stable, 1, true}, false));
  // The formula alone never needs the reference caster: the fast caster takes it, with the same result.
  Random random(23);
  for (IntersectFormula formula : {IntersectFormula::stable, IntersectFormula::naive}) {
    const ReferenceOptions options{Scalar::float64, formula};
    REQUIRE_FALSE(needs_reference_caster(options, false));
    CastOptions fast;
    fast.formula = formula;
    for (int trial = 0; trial < 20; ++trial) {
      const Scene2D scene2d = random_scene_2d(random, random.integer(1, 10), 4.0);
      Camera2D camera2d(
          random.integer(1, 300),
          Orbit2D{
              {0, 0}, random.log_uniform(0.5, 1e3), random.uniform(-kPi, kPi), random.log_uniform(0.1, 10)});
      const CoverageImage reference2d = reference_cast(camera2d, scene2d, options);
      const ColourMap fast2d = cast_primary_rays(camera2d, scene2d, fast);
      CHECK(reference2d.ids == fast2d.ids);
      CHECK(to_colour_map(reference2d).colours == fast2d.colours);
      const Scene3D scene3d = random_scene_3d(random, random.integer(1, 8), 3.0);
      Camera3D camera3d(random.integer(1, 40), random.integer(1, 40),
                        Orbit3D{{0, 0, 0},
                                random.log_uniform(0.5, 1e3),
                                random.uniform(-kPi, kPi),
                                random.uniform(0, kPi),
                                2.0});
      const CoverageImage reference3d = reference_cast(camera3d, scene3d, options);
      const ColourMap fast3d = cast_primary_rays(camera3d, scene3d, fast);
      CHECK(reference3d.ids == fast3d.ids);
      CHECK(to_colour_map(reference3d).colours == fast3d.colours);
    }
  }
}
