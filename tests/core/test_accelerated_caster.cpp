// The accelerated casters (culled, footprint, binned, automatic) against the plain loop: the same ids and
// colours, pixel for pixel, on random scenes, on rays built to graze a sphere, on the numerical stress
// cases, with 1 to 3 threads; and the work they skip, against what geometry says they must skip.
#include <catch2/catch.hpp>

#include "raycam/ray_caster.h"
#include "raycam/speed_families.h"
#include "raycam/stress_cases.h"
#include "test_support.h"

using namespace raycam;
using test::kPi;

namespace {
constexpr CastMethod kAccelerated[] = {CastMethod::culled, CastMethod::footprint, CastMethod::binned,
                                       CastMethod::automatic};

CastOptions with(CastMethod method, int threads = 1) {
  CastOptions options;
  options.method = method;
  options.threads = threads;
  return options;
}

// Number of pixels whose id or colour differs.
int differences(const ColourMap& a, const ColourMap& b) {
  if (a.width != b.width || a.height != b.height) return -1;
  int count = 0;
  for (std::size_t i = 0; i < a.ids.size(); ++i) count += a.ids[i] != b.ids[i] || a.colours[i] != b.colours[i];
  return count;
}

template <class Camera, class Scene>
void check_every_method_matches_plain(const Camera& camera, const Scene& scene) {
  const ColourMap plain = cast_primary_rays(camera, scene, with(CastMethod::plain));
  for (CastMethod method : kAccelerated)
    for (int threads : {1, 2, 3}) {
      INFO(cast_method_name(method) << ", " << threads << " threads");
      CHECK(differences(cast_primary_rays(camera, scene, with(method, threads)), plain) == 0);
    }
  // The textbook formula cancels far from the sphere and so hits a little outside its true silhouette:
  // the bounds widen for it, and the ids still match its own plain loop.
  CastOptions naive_plain = with(CastMethod::plain), naive_fast = with(CastMethod::automatic, 2);
  naive_plain.formula = naive_fast.formula = IntersectFormula::naive;
  CHECK(differences(cast_primary_rays(camera, scene, naive_fast), cast_primary_rays(camera, scene, naive_plain)) == 0);
}

Scene3D random_spheres(test::Random& random, int count, double spread, double max_radius) {
  Scene3D scene;
  scene.background = {1, 2, 3};
  for (int i = 0; i < count; ++i)
    scene.spheres.push_back({{random.uniform(-spread, spread), random.uniform(-spread, spread),
                              random.uniform(-spread, spread)},
                             random.log_uniform(max_radius / 30, max_radius),
                             {std::uint8_t(i * 37), std::uint8_t(i * 11), std::uint8_t(i)},
                             ""});
  return scene;
}
}  // namespace

namespace {
// An object of random radius touching `ray`, on a random side along `normal` (unit, normal to the ray), at a
// random distance along it: the ray grazes it, the hardest case for the footprint bounds.
template <class Object, class Ray, class Vector>
Object touching(test::Random& random, const Ray& ray, const Vector& normal, Rgb8 colour) {
  const double sign = random.integer(0, 1) == 0 ? 1.0 : -1.0;
  const double radius = random.log_uniform(0.01, 2);
  const Vector touch = ray.origin + random.log_uniform(0.3, 30) * ray.direction;
  return Object{touch + radius * sign * normal, radius, colour, ""};
}
}  // namespace

TEST_CASE("every method gives the plain loop's ids on random 3D scenes", "[caster][accelerated]") {
  test::Random random(2024);
  for (int trial = 0; trial < 60; ++trial) {
    // Near cameras put spheres across the screen, around the eye and behind it; far ones shrink them.
    const int count = random.integer(1, trial % 3 == 0 ? 400 : 40);
    const Scene3D scene = random_spheres(random, count, 6.0, 3.0);
    Camera3D camera(random.integer(1, 70), random.integer(1, 50));
    camera.set_orbit({{random.uniform(-2, 2), random.uniform(-2, 2), random.uniform(-2, 2)},
                      random.log_uniform(0.05, 40),
                      random.uniform(-kPi, kPi),
                      random.uniform(0, kPi),
                      random.log_uniform(0.05, 20)});
    INFO("trial " << trial << ", " << count << " spheres");
    check_every_method_matches_plain(camera, scene);
  }
}

TEST_CASE("every method gives the plain loop's ids on random 2D bars", "[caster][accelerated]") {
  test::Random random(2025);
  for (int trial = 0; trial < 200; ++trial) {
    Scene2D scene;
    for (int i = 0, count = random.integer(1, 60); i < count; ++i)
      scene.circles.push_back({{random.uniform(-6, 6), random.uniform(-6, 6)},
                               random.log_uniform(0.05, 3),
                               {std::uint8_t(i), 9, 9},
                               ""});
    Camera2D camera(random.integer(1, 600));
    camera.set_orbit({{random.uniform(-2, 2), random.uniform(-2, 2)},
                      random.log_uniform(0.05, 40),
                      random.uniform(-kPi, kPi),
                      random.log_uniform(0.05, 20)});
    INFO("trial " << trial);
    check_every_method_matches_plain(camera, scene);
  }
}

// Grazing, for real: a ball tangent to a pixel-centre ray AND to the plane through the eye that holds that
// ray and the image's up (or right) axis. That plane is where the footprint's column (or row) bound lies, so
// the bound falls exactly on the grazed pixel's centre, and whether the pixel is a candidate depends on the
// rounding slack in the bounds (screen_footprint.cpp): without it the fast casters drop pixels the plain loop
// hits. Every fast method, both formulas, 1-3 threads; targets far from the origin too, where the rays'
// coordinates round at a larger scale.
template <class Camera, class Scene>
void check_grazing(const Camera& camera, const Scene& scene, int& casts) {
  for (IntersectFormula formula : {IntersectFormula::stable, IntersectFormula::naive}) {
    CastOptions plain = with(CastMethod::plain);
    plain.formula = formula;
    const ColourMap expected = cast_primary_rays(camera, scene, plain);
    for (CastMethod method : kAccelerated)
      for (int threads : {1, 2, 3}) {
        CastOptions fast = with(method, threads);
        fast.formula = formula;
        INFO(cast_method_name(method)
             << ", " << threads << " threads, " << (formula == IntersectFormula::naive ? "naive" : "stable"));
        CHECK(differences(cast_primary_rays(camera, scene, fast), expected) == 0);
        ++casts;
      }
  }
}

TEST_CASE("spheres tangent to pixel-centre rays at the footprint's box edges give the plain loop's ids",
          "[caster][accelerated][grazing]") {
  test::Random random(7);
  int casts = 0;
  for (int trial = 0; trial < 60; ++trial) {
    Camera3D camera(48, 40);
    const double far = trial % 3 == 0 ? random.log_uniform(1e2, 1e6) : 0.0;
    const glm::dvec3 target(far, -0.5 * far, 0.25 * far);
    camera.set_orbit({target, random.log_uniform(2, 40), random.uniform(-kPi, kPi), random.uniform(0.1, 3.0),
                      random.log_uniform(0.3, 4)});
    // Independent of the footprint code: the image axes are M_d's first two columns.
    const glm::dvec3 up = glm::normalize(camera.image_up()), right = glm::normalize(camera.image_right());
    Scene3D scene;
    for (int i = 0; i < 16; ++i) {
      const Ray3D ray = camera.primary_ray(random.integer(0, 39), random.integer(0, 47));
      // ray × up is normal to the plane (eye, ray, up): a column bound; ray × right: a row bound.
      const glm::dvec3 axis = i % 2 == 0 ? up : right;
      scene.spheres.push_back(touching<Sphere>(random, ray, glm::normalize(glm::cross(ray.direction, axis)),
                                               {std::uint8_t(i + 1), 0, 0}));
    }
    INFO("trial " << trial);
    check_grazing(camera, scene, casts);
  }
  CHECK(casts == 60 * 2 * 4 * 3);
}

TEST_CASE("circles tangent to pixel-centre rays give the plain loop's ids",
          "[caster][accelerated][grazing]") {
  test::Random random(8);
  int casts = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int n = random.integer(8, 400);
    Camera2D camera(n);
    const double far = trial % 3 == 0 ? random.log_uniform(1e2, 1e6) : 0.0;
    camera.set_orbit({{far, -0.7 * far},
                      random.log_uniform(1, 40),
                      random.uniform(-kPi, kPi),
                      random.log_uniform(0.3, 4)});
    Scene2D scene;
    for (int i = 0; i < 6; ++i) {
      const Ray2D ray = camera.primary_ray(random.integer(0, n - 1));
      // In 2D the bound is the tangent line itself: the side vector is the ray's normal, either way.
      scene.circles.push_back(touching<Circle>(random, ray, glm::dvec2(-ray.direction.y, ray.direction.x),
                                               {std::uint8_t(i + 1), 9, 9}));
    }
    INFO("trial " << trial);
    check_grazing(camera, scene, casts);
  }
  CHECK(casts == 300 * 2 * 4 * 3);
}

TEST_CASE("the numerical stress cases give the plain loop's ids", "[caster][accelerated][stress]") {
  for (const StressCase3D& c : stress_cases_3d(false)) {
    INFO(c.group << ": " << c.name);
    check_every_method_matches_plain(c.camera, c.scene);
  }
  for (const StressCase2D& c : stress_cases_2d(false)) {
    INFO(c.group << ": " << c.name);
    check_every_method_matches_plain(c.camera, c.scene);
  }
}

TEST_CASE("a cast big enough to share is shared by the threads, and still gives the plain loop's ids",
          "[caster][accelerated]") {
  test::Random random(11);
  const Scene3D scene = random_spheres(random, 60, 4.0, 2.5);
  Camera3D camera(600, 500);
  camera.set_orbit({{0, 0, 0}, 9.0, 0.4, 1.1, 1.2});
  const ColourMap plain = cast_primary_rays(camera, scene, with(CastMethod::plain));
  for (CastMethod method : {CastMethod::footprint, CastMethod::binned}) {
    CastStats stats;
    const ColourMap map = cast_primary_rays(camera, scene, with(method, 3), &stats);
    CHECK(stats.threads == 3);
    CHECK(differences(map, plain) == 0);
  }
  CastStats small;
  cast_primary_rays(camera, Scene3D{}, with(CastMethod::automatic, 3), &small);
  CHECK(small.threads == 1);  // an empty scene: writing the background is not worth a thread
}

TEST_CASE("objects behind the screen or out of view are culled, never tested", "[caster][accelerated]") {
  Camera3D camera(64, 64);
  camera.set_orbit({{0, 0, 0}, 10.0, 0.0, kPi / 2, 2.0});  // on +x, looking down -x; eye at x = 12
  Scene3D scene;
  scene.spheres = {{{0, 0, 0}, 1.0, {1, 0, 0}, "in view"},
                   {{11, 0, 0}, 0.5, {2, 0, 0}, "between eye and screen"},
                   {{20, 0, 0}, 1.0, {3, 0, 0}, "behind the eye"},
                   {{0, 30, 0}, 1.0, {4, 0, 0}, "outside the field of view (26.6 deg half-angle)"}};
  for (CastMethod method : kAccelerated) {
    CastStats stats;
    cast_primary_rays(camera, scene, with(method), &stats);
    CHECK(stats.objects_culled == 3);
    CHECK(stats.rays == 64 * 64);
  }
  // The lone visible sphere subtends asin(1/12) from the eye: its box holds about (2·12/√143·64/2)² pixels.
  CastStats stats;
  cast_primary_rays(camera, scene, with(CastMethod::footprint), &stats);
  const double side = 2 * (2.0 / std::sqrt(143.0)) * 64 / 2;  // screen half-width 1 at d_f = 2
  // Pixel centres inside an interval `side` pixels wide: side - 1 to side + 1 of them per axis.
  CHECK(stats.intersection_tests <= (side + 1) * (side + 1));
  CHECK(stats.intersection_tests >= (side - 1) * (side - 1));
  CHECK(stats.pixels_skipped == 64 * 64 - stats.intersection_tests);  // one object: one test per touched pixel
  CastStats culled;
  cast_primary_rays(camera, scene, with(CastMethod::culled), &culled);
  CHECK(culled.intersection_tests == 64 * 64);  // every pixel, the one surviving sphere
  CHECK(culled.pixels_skipped == 0);
}

TEST_CASE("a 2D bar skips the pixels no circle can cover", "[caster][accelerated]") {
  Camera2D camera(1000);
  camera.set_orbit({{0, 0}, 5.0, kPi / 2, 1.0});  // eye at (0, 6), screen half-width 1 at d_f = 1
  Scene2D scene;
  scene.circles = {{{0, 0}, 0.6, {1, 0, 0}, "ahead"}, {{0, 9}, 0.5, {2, 0, 0}, "behind"}};
  CastStats stats;
  cast_primary_rays(camera, scene, {}, &stats);
  CHECK(stats.objects_culled == 1);
  // Seen from 6 away the circle spans tan(asin(0.1)) either side of the axis on a screen of half-width 1.
  const double half = std::tan(std::asin(0.1)) * 1000 / 2;
  CHECK(stats.intersection_tests <= 2 * half + 1);
  CHECK(stats.intersection_tests >= 2 * half - 1);
}

TEST_CASE("a colour map reused across casts is rewritten whole", "[caster][accelerated]") {
  test::Random random(3);
  const Scene3D scene = random_spheres(random, 30, 5, 1.5);
  Camera3D camera(40, 30);
  ColourMap map;
  for (double theta : {0.3, 2.0, -1.0}) {
    camera.set_orbit({{0, 0, 0}, 9, theta, 1.0, 1.5});
    cast_primary_rays(camera, scene, map);
    CHECK(differences(map, cast_primary_rays(camera, scene, with(CastMethod::plain))) == 0);
  }
}

// The speed bench's scene families (small K, small images): the near-to-far order gives the plain loop's
// ids on each, with skipping on and off, and where spheres hide each other it runs fewer tests than the
// boxes hold (the caster's cost follows what is visible); never more tests than the boxes hold.
TEST_CASE("near to far: every scene family gives the plain loop's ids, and skips hidden spheres' tests",
          "[caster][accelerated][families]") {
  for (const std::string& name : testkit::speed_family_names()) {
    const testkit::SpeedFamily family = testkit::speed_family(name, 3000);
    Camera3D camera(72, 64);
    camera.set_orbit(family.orbit);
    INFO(name);
    const ColourMap plain = cast_primary_rays(camera, family.scene, with(CastMethod::plain));
    for (CastMethod method : {CastMethod::footprint, CastMethod::binned, CastMethod::automatic}) {
      long long tests[2] = {0, 0};
      for (bool near_to_far : {true, false}) {
        CastOptions options = with(method, 2);
        options.near_to_far = near_to_far;
        CastStats stats;
        INFO(cast_method_name(method) << (near_to_far ? ", near to far" : ", object order"));
        CHECK(differences(cast_primary_rays(camera, family.scene, options, &stats), plain) == 0);
        CHECK(stats.intersection_tests <= stats.box_tests);
        tests[near_to_far] = stats.intersection_tests;
        if (!near_to_far) CHECK(stats.intersection_tests == stats.box_tests);  // the caster before: every test
      }
      // Where big and small spheres hide each other (box depth 2.8 here), a third of the tests are skipped.
      if (name == "radii ×20") CHECK(double(tests[true]) < 0.67 * double(tests[false]));
    }
  }
}
