// The seam between kinds of object (raycam/scene.h: Shape3D): a scene holding a kind the fast casters do not
// know is cast by the plain loop, with the same nearest-hit rule and ids (spheres first, the other kinds after
// them). Checked against this file's own intersections (the geometric sphere test, not the caster's quadratic;
// the plane's parameter by its own projection), not against the caster's code.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "raycam/ray_caster.h"
#include "raycam/scene_file.h"
#include "test_support.h"

using namespace raycam;
using test::kPi;

namespace {
constexpr double kMiss = std::numeric_limits<double>::infinity();

// The geometric sphere test (distance of the centre to the ray's line): the nearest t ≥ 0, or kMiss.
double sphere_t(const Sphere& s, const Ray3D& ray) {
  const glm::dvec3 to_centre = s.centre - ray.origin;
  const double along = glm::dot(to_centre, ray.direction);
  const double off2 = glm::dot(to_centre, to_centre) - along * along;
  const double half2 = s.radius * s.radius - off2;
  if (half2 < 0) return kMiss;
  const double half = std::sqrt(half2);
  if (along - half >= 0) return along - half;
  return along + half >= 0 ? along + half : kMiss;
}

// The plane's t from the distances of the ray's origin and of the point one unit along it to the plane.
double plane_t(const Plane& p, const Ray3D& ray) {
  const glm::dvec3 n = glm::normalize(p.normal);
  const double here = glm::dot(ray.origin - p.point, n);
  const double there = glm::dot(ray.origin + ray.direction - p.point, n);
  if (here == there) return kMiss;
  const double t = here / (here - there);
  return t >= 0 ? t : kMiss;
}

struct Expected {
  int id = -1;
  bool ambiguous = false;  // two objects within rounding of each other, or a grazing ray: either id is right
};

Expected expected_hit(const Scene3D& scene, const Ray3D& ray) {
  double best = kMiss, second = kMiss;
  int id = -1;
  const auto offer = [&](double t, int i) {
    if (t < best) {
      second = best;
      best = t;
      id = i;
    } else if (t < second) {
      second = t;
    }
  };
  for (std::size_t i = 0; i < scene.spheres.size(); ++i) offer(sphere_t(scene.spheres[i], ray), int(i));
  for (std::size_t k = 0; k < scene.shapes.size(); ++k)
    offer(plane_t(std::get<Plane>(scene.shapes[k]), ray), int(scene.spheres.size() + k));
  const bool close = second < kMiss && second - best <= 1e-9 * std::max(1.0, best);
  return {id, close || test::ray_grazes_any(ray, scene.spheres, 1e-9)};
}

Scene3D spheres_and_planes(test::Random& random, int spheres, int planes) {
  Scene3D scene;
  for (int i = 0; i < spheres; ++i)
    scene.spheres.push_back({{random.uniform(-4, 4), random.uniform(-4, 4), random.uniform(-4, 4)},
                             random.uniform(0.3, 1.5),
                             {std::uint8_t(10 + i), 0, 0},
                             ""});
  for (int k = 0; k < planes; ++k) {
    const glm::dvec3 normal{random.uniform(-0.3, 0.3), random.uniform(-0.3, 0.3), 1.0};
    scene.shapes.push_back(Plane{{0, 0, random.uniform(-5, -1)}, normal * random.uniform(0.5, 3), {0, std::uint8_t(100 + k), 0}, ""});
  }
  return scene;
}
}  // namespace

TEST_CASE("a scene with planes: every method gives the nearest hit of this file's own intersections, planes "
          "numbered after the spheres",
          "[caster][kinds]") {
  test::Random random(2024);
  long long checked = 0, planes_seen = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const Scene3D scene = spheres_and_planes(random, 6, 1 + trial % 3);
    Camera3D camera(24, 18);
    camera.set_orbit({{0, 0, 0}, random.uniform(10, 18), random.uniform(-kPi, kPi), random.uniform(0.3, 2.8),
                      random.uniform(0.7, 2)});
    for (const CastMethod method : kCastMethods) {
      CastOptions options;
      options.method = method;
      const ColourMap map = cast_primary_rays(camera, scene, options);
      for (int r = 0; r < map.height; ++r)
        for (int c = 0; c < map.width; ++c) {
          const Expected want = expected_hit(scene, camera.primary_ray(r, c));
          if (want.ambiguous) continue;
          ++checked;
          REQUIRE(map.id_at(r, c) == want.id);
          if (want.id >= int(scene.spheres.size())) {
            ++planes_seen;
            const Plane& plane = std::get<Plane>(scene.shapes[std::size_t(want.id) - scene.spheres.size()]);
            REQUIRE(map.colours[map.index(r, c)] == plane.colour);
          }
        }
    }
  }
  CHECK(checked > 30 * 5 * 24 * 18 * 9 / 10);
  CHECK(planes_seen > 1000);  // the planes are really seen, not all behind the camera
}

TEST_CASE("a plane and a sphere at the same distance: the lower id (the sphere) wins, and a plane behind the eye "
          "is not seen",
          "[caster][kinds]") {
  Camera3D camera(9, 9);
  camera.set_orbit({{0, 0, 0}, 5.0, 0.0, kPi / 2, 1.0});  // on +x looking at the origin
  Scene3D scene;
  scene.spheres = {{{-1, 0, 0}, 1.0, {1, 0, 0}, "sphere"}};
  // Through the sphere's near point (x = 0): the centre pixel's ray meets both at t = 4 exactly.
  scene.shapes = {Plane{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, "tied"}, Plane{{20, 0, 0}, {1, 0, 0}, {3, 0, 0}, "behind"}};
  for (const CastMethod method : kCastMethods) {
    CastOptions options;
    options.method = method;
    const ColourMap map = cast_primary_rays(camera, scene, options);
    CHECK(map.id_at(4, 4) == 0);
    CHECK(map.id_at(0, 0) == 1);  // the corner misses the sphere and meets the plane; never the one behind
    for (int id : map.ids) CHECK(id != 2);
  }
  CHECK(nearest_hit(scene, camera.primary_ray(4, 4), IntersectFormula::stable).id == 0);
}

TEST_CASE("spheres alone keep the fast caster, and one plane makes the cast the plain loop", "[caster][kinds]") {
  test::Random random(7);
  Scene3D scene = spheres_and_planes(random, 50, 0);
  Camera3D camera(64, 64);
  camera.set_orbit({{0, 0, 0}, 15.0, 0.4, 1.2, 1.5});
  CastStats fast, plain;
  cast_primary_rays(camera, scene, CastOptions{}, &fast);
  CHECK(fast.intersection_tests < fast.rays * 50);  // boxes skip most tests
  scene.shapes.push_back(Plane{{0, 0, -6}, {0, 0, 1}, {9, 9, 9}, ""});
  cast_primary_rays(camera, scene, CastOptions{}, &plain);
  CHECK(plain.intersection_tests == plain.rays * 51);
}

TEST_CASE("a plane's point and normal are checked, naming the object", "[caster][kinds][validation]") {
  Scene3D scene;
  scene.spheres = {{{0, 0, 0}, 1.0, {1, 1, 1}, ""}};
  scene.shapes = {Plane{{0, 0, 0}, {0, 0, 0}, {1, 1, 1}, ""}};
  CHECK_THROWS_WITH(validate(scene), Catch::Contains("objects[1].normal"));
  scene.shapes = {Plane{{0, std::nan(""), 0}, {0, 0, 1}, {1, 1, 1}, ""}};
  CHECK_THROWS_WITH(validate(scene), Catch::Contains("objects[1].point[1]"));
  scene.shapes = {Plane{{0, 0, 0}, {0, 0, 2}, {1, 1, 1}, ""}};
  CHECK_NOTHROW(validate(scene));
}

TEST_CASE("a scene file never drops a plane: writing one is refused, naming the objects", "[kinds][files]") {
  SceneFile file;
  file.dimension = 3;
  Scene3D scene;
  scene.spheres = {{{0, 0, 0}, 1.0, {1, 1, 1}, ""}};
  file.scene3d = scene;
  CHECK_NOTHROW(scene_to_json(file));
  scene.shapes = {Plane{{0, 0, -2}, {0, 0, 1}, {1, 1, 1}, ""}};
  file.scene3d = scene;
  CHECK_THROWS_WITH(scene_to_json(file), Catch::Contains("objects: 1 of the scene's objects are not spheres"));
}
