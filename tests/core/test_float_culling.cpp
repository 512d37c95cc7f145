// The float culling pass (Footprint::spheres_maybe_seen, src/core/float_culling.cpp) against the double boxes
// (sphere_boxes) it stands before: it must never drop a sphere whose double box holds a pixel, on cameras and
// scenes chosen to be hard for single precision (spheres grazing pixel-centre rays, across the screen's
// plane, far from the origin, tiny); and it must drop most of what the double pass drops, or it is no use.
// The casts with and without it give the plain loop's ids.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "raycam/ray_caster.h"
#include "core/screen_footprint.h"
#include "test_support.h"

using namespace raycam;
using test::kPi;

namespace {
struct Tally {
  long long spheres = 0, double_culled = 0, float_culled = 0, wrongly_dropped = 0;
};

// Runs both passes over the packed scene's clusters; counts, and checks every dropped sphere's double box.
void compare_passes(const Camera3D& camera, const Scene3D& scene, Tally& tally) {
  const PackedScene3D packed(scene);
  const SphereClusters& c = packed.clusters;
  const detail::Footprint footprint(camera, IntersectFormula::stable);
  REQUIRE(footprint.culls_clusters());
  const int count = c.size();
  std::vector<detail::PixelBox> boxes(static_cast<std::size_t>(count));
  footprint.sphere_boxes({c.x.data(), c.y.data(), c.z.data(), c.radius.data()}, count, camera.rows(),
                         camera.columns(), boxes.data());
  std::vector<int> kept(static_cast<std::size_t>(count));
  std::vector<unsigned char> scratch(static_cast<std::size_t>(count));
  const int n = footprint.spheres_maybe_seen({c.float_x.data(), c.float_y.data(), c.float_z.data(), c.float_radius.data()},
                                             count, camera.rows(), camera.columns(), kept.data(), scratch.data());
  std::vector<bool> float_keeps(static_cast<std::size_t>(count), false);
  for (int j = 0; j < n; ++j) {
    REQUIRE((j == 0 || kept[std::size_t(j)] > kept[std::size_t(j - 1)]));  // in order, each once
    float_keeps[std::size_t(kept[std::size_t(j)])] = true;
  }
  for (int i = 0; i < count; ++i) {
    const bool double_keeps = !boxes[std::size_t(i)].empty();
    ++tally.spheres;
    tally.double_culled += !double_keeps;
    tally.float_culled += !float_keeps[std::size_t(i)];
    if (double_keeps && !float_keeps[std::size_t(i)]) {
      ++tally.wrongly_dropped;
      const Sphere& s = scene.spheres[std::size_t(c.object[std::size_t(i)])];
      UNSCOPED_INFO("dropped sphere " << c.object[std::size_t(i)] << " at (" << s.centre.x << ", " << s.centre.y
                                      << ", " << s.centre.z << ") r " << s.radius << ", its double box rows "
                                      << boxes[std::size_t(i)].rows.first << "…" << boxes[std::size_t(i)].rows.last
                                      << ", columns " << boxes[std::size_t(i)].columns.first << "…"
                                      << boxes[std::size_t(i)].columns.last);
    }
  }
}

Camera3D random_camera(test::Random& random, const glm::dvec3& target, int trial) {
  Camera3D camera(random.integer(1, 300), random.integer(1, 300));
  camera.set_orbit({target, random.log_uniform(0.5, 40), random.uniform(-kPi, kPi), random.uniform(0.05, kPi - 0.05),
                    trial % 4 == 0 ? 1e-2 : random.log_uniform(1e-2, 50)});
  return camera;
}

// A sphere whose surface passes within `gap` (relative to its radius; negative: overlapping) of a pixel
// centre's ray, sideways along a row or a column: its box's edge falls on that pixel.
Sphere grazing(test::Random& random, const Camera3D& camera, double radius, double gap) {
  const Ray3D ray = camera.primary_ray(random.integer(0, camera.rows() - 1), random.integer(0, camera.columns() - 1));
  const glm::dvec3 axis = random.integer(0, 1) == 0 ? glm::normalize(camera.image_up()) : glm::normalize(camera.image_right());
  const glm::dvec3 side = glm::normalize(glm::cross(ray.direction, axis)) * (random.integer(0, 1) == 0 ? 1.0 : -1.0);
  const glm::dvec3 touch = ray.origin + random.log_uniform(1e-3, 1e3) * ray.direction;
  return Sphere{touch + radius * (1.0 + gap) * side, radius, {1, 2, 3}, ""};
}
}  // namespace

TEST_CASE("the float pass never drops a sphere whose double box holds a pixel, and drops most of the others",
          "[caster][float_culling][vector]") {
  test::Random random(4242);
  Tally tally, near_origin;  // all trials; those about the origin
  for (int trial = 0; trial < 120; ++trial) {
    // Far from the origin in a third of the trials: the float coordinates then lose most of their bits.
    const double far = trial % 3 == 0 ? random.log_uniform(1e2, 1e9) : 0.0;
    const glm::dvec3 target = glm::dvec3(far, -0.5 * far, 0.25 * far) + glm::dvec3(random.uniform(-2, 2), 0, 0);
    const Camera3D camera = random_camera(random, target, trial);
    Scene3D scene;
    const double spread = camera.orbit().d + 4;
    for (int i = 0; i < 1500; ++i) {  // around the target, the eye and the screen's edges; radii over 8 decades
      const glm::dvec3 at(random.uniform(-spread, spread), random.uniform(-spread, spread), random.uniform(-spread, spread));
      scene.spheres.push_back({target + at, random.log_uniform(1e-6, 3.0), {1, 2, 3}, ""});
    }
    for (int i = 0; i < 300; ++i) {  // grazing pixel-centre rays, on either side, by a hair or by much
      const double gap = (random.integer(0, 1) == 0 ? 1.0 : -1.0) * random.log_uniform(1e-12, 1e-1);
      scene.spheres.push_back(grazing(random, camera, random.log_uniform(1e-5, 2.0), gap));
    }
    // Touching the screen's plane from the eye's side, or the eye's plane from the front: the depth tests' edges.
    const glm::dvec3 forward = glm::normalize(target - camera.eye());
    for (int i = 0; i < 100; ++i) {
      const Ray3D ray = camera.primary_ray(random.integer(0, camera.rows() - 1), random.integer(0, camera.columns() - 1));
      const double radius = random.log_uniform(1e-4, 1.0), depth = radius * (1.0 + random.uniform(-1e-3, 1e-3));
      const glm::dvec3 centre = i % 2 == 0 ? ray.origin - depth * forward : camera.eye() + random.uniform(0, 3) * (ray.origin - camera.eye()) + depth * forward;
      scene.spheres.push_back({centre, radius, {1, 2, 3}, ""});
    }
    INFO("trial " << trial << ", camera " << camera.columns() << "×" << camera.rows() << ", d_f " << camera.orbit().df);
    Tally trial_tally;
    compare_passes(camera, scene, trial_tally);
    CHECK(trial_tally.wrongly_dropped == 0);
    for (Tally* t : {&tally, far == 0.0 ? &near_origin : nullptr})
      if (t) {
        t->spheres += trial_tally.spheres;
        t->double_culled += trial_tally.double_culled;
        t->float_culled += trial_tally.float_culled;
        t->wrongly_dropped += trial_tally.wrongly_dropped;
      }
  }
  INFO(tally.spheres << " spheres: the double boxes culled " << tally.double_culled << ", the float pass "
                     << tally.float_culled << "; about the origin " << near_origin.double_culled << " and "
                     << near_origin.float_culled << " of " << near_origin.spheres);
  CHECK(tally.wrongly_dropped == 0);
  // Of use: about the origin, nearly all of what the double pass culls is already dropped in float. (Far
  // from it, the floats' rounding grows the spheres past many pixels: there the pass keeps more.)
  CHECK(near_origin.float_culled >= 0.9 * near_origin.double_culled);
  CHECK(near_origin.double_culled > near_origin.spheres / 4);
}

TEST_CASE("casts with and without the float pass give the plain loop's ids", "[caster][float_culling][accelerated]") {
  test::Random random(99);
  for (int trial = 0; trial < 30; ++trial) {
    const glm::dvec3 target(trial % 2 == 0 ? 0.0 : 1e6, 0.0, 0.0);
    Camera3D camera(random.integer(8, 64), random.integer(8, 64));
    camera.set_orbit({target, random.log_uniform(1, 30), random.uniform(-kPi, kPi), random.uniform(0.1, 3.0),
                      random.log_uniform(1e-2, 5)});
    Scene3D scene;
    for (int i = 0; i < 600; ++i) scene.spheres.push_back(grazing(random, camera, random.log_uniform(1e-3, 0.5), random.uniform(-1e-6, 1e-6)));
    for (int i = 0; i < 600; ++i)
      scene.spheres.push_back({target + glm::dvec3(random.uniform(-20, 20), random.uniform(-20, 20), random.uniform(-20, 20)),
                               random.log_uniform(1e-3, 0.3), {1, 2, 3}, ""});
    CastOptions plain, with_float, without_float;
    plain.method = CastMethod::plain;
    for (CastOptions* o : {&with_float, &without_float}) o->method = CastMethod::footprint;
    with_float.float_culling = true;
    without_float.float_culling = false;
    const ColourMap want = cast_primary_rays(camera, scene, plain);
    INFO("trial " << trial);
    CHECK(cast_primary_rays(camera, scene, with_float).ids == want.ids);
    CHECK(cast_primary_rays(camera, scene, without_float).ids == want.ids);
  }
}
