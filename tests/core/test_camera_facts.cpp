// The camera facts the core states once (eye, view, image axes, field of view, screen corners, the
// pixel <-> canonical-screen pair), checked against the handout's definitions and against each other.
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/geometric.hpp>

#include "raycam/camera2d.h"
#include "raycam/camera3d.h"
#include "test_support.h"

using namespace raycam;
using raycam::test::kPi;
using raycam::test::Random;

TEST_CASE("the pixel <-> screen pair gives the handout's centres and edges and inverts itself",
          "[camera][pixels]") {
  for (int count : {1, 2, 3, 7, 256, 4095}) {
    for (int i = 0; i < count; i += std::max(1, count / 17)) {
      // Handout, exercise 2: centre -1 + (2i+1)/n, left edge -1 + 2i/n, computed here independently.
      CHECK(screen_from_raster(i + 0.5, count) == -1.0 + (2.0 * i + 1.0) / count);
      CHECK(screen_from_raster(i, count) == -1.0 + 2.0 * i / count);
      CHECK(raster_from_screen(screen_from_raster(i + 0.5, count), count) == Approx(i + 0.5).epsilon(1e-14));
    }
    CHECK(screen_from_raster(0, count) == -1.0);
    CHECK(screen_from_raster(count, count) == 1.0);
  }
  Camera3D camera(40, 30);
  for (int row : {0, 7, 29})
    for (int column : {0, 13, 39}) {
      const glm::dvec3 centre = camera.canonical_pixel(row, column);
      CHECK(glm::dvec2(centre) == camera.screen_from_raster({column + 0.5, row + 0.5}));
      const glm::dvec2 back = camera.raster_from_screen(glm::dvec2(centre));
      CHECK(back.x == Approx(column + 0.5));
      CHECK(back.y == Approx(row + 0.5));
    }
  CHECK(camera.screen_from_raster({0, 0}) == glm::dvec2(-1, 1));  // raster (0, 0) is the top-left corner
  Camera2D bar(33);
  for (int k : {0, 16, 32}) CHECK(bar.canonical_pixel(k).x == bar.screen_from_raster(k + 0.5));
  ClassicMistakes edges;
  edges.pixel_edges = true;
  bar.set_mistakes(edges);
  CHECK(bar.canonical_pixel(5).x == bar.screen_from_raster(5));
}

TEST_CASE("3D corners, eye, axes and field of view agree with the placement", "[camera3d][facts]") {
  Random random(5);
  for (int trial = 0; trial < 200; ++trial) {
    const Orbit3D orbit{{random.uniform(-50, 50), random.uniform(-50, 50), random.uniform(-50, 50)},
                        random.log_uniform(0.1, 1e3),
                        random.uniform(-kPi, kPi),
                        random.uniform(0, kPi),
                        random.log_uniform(0.05, 20)};
    const Camera3D camera(64, 64, orbit);
    const double scale = glm::length(orbit.target) + orbit.d + orbit.df;
    const glm::dvec3 p = camera.screen_centre();
    CHECK(glm::length(p - orbit_screen_centre(orbit)) <= 1e-12 * scale);
    CHECK(glm::length(camera.eye() - (p - orbit.df * camera.view_direction())) <= 1e-12 * scale);
    const auto corners = camera.screen_corners();
    glm::dvec3 middle(0.0);
    for (const glm::dvec3& c : corners) middle += 0.25 * c;
    CHECK(glm::length(middle - p) <= 1e-12 * scale);
    // Top-left to top-right runs along image right, top to bottom against image up; the sides are 2 long.
    CHECK(glm::length(corners[1] - corners[0] - 2.0 * camera.image_right()) <= 1e-12 * scale);
    CHECK(glm::length(corners[0] - corners[3] - 2.0 * camera.image_up()) <= 1e-12 * scale);
    CHECK(std::abs(glm::dot(camera.image_right(), camera.view_direction())) <= 1e-12);
    // The field of view is the angle between the rays from the eye to the middles of the left and right
    // sides.
    const glm::dvec3 left = 0.5 * (corners[0] + corners[3]) - camera.eye(),
                     right = 0.5 * (corners[1] + corners[2]) - camera.eye();
    const double angle = std::acos(glm::dot(left, right) / (glm::length(left) * glm::length(right)));
    CHECK(camera.field_of_view() == Approx(angle).epsilon(1e-9));
  }
}

TEST_CASE("2D screen ends, eye, image right and field of view agree with the rays", "[camera2d][facts]") {
  Random random(6);
  for (int trial = 0; trial < 200; ++trial) {
    const Orbit2D orbit{{random.uniform(-50, 50), random.uniform(-50, 50)},
                        random.log_uniform(0.1, 1e3),
                        random.uniform(-kPi, kPi),
                        random.log_uniform(0.05, 20)};
    const Camera2D camera(random.integer(2, 300), orbit);
    const double scale = glm::length(orbit.target) + orbit.d + orbit.df;
    CHECK(glm::length(camera.screen_centre() - orbit_screen_centre(orbit)) <= 1e-12 * scale);
    CHECK(glm::length(camera.eye() - eye_of(camera.world_from_camera())) == 0.0);
    const auto ends = camera.screen_corners();
    CHECK(glm::length(ends[1] - ends[0]) == Approx(2.0).epsilon(1e-12));
    // Column c+1 lies along image_right from column c (column 0 is the eye's left).
    const int n = camera.pixel_count();
    const glm::dvec2 step = camera.primary_ray(camera.pixel_of_column(1)).origin -
                            camera.primary_ray(camera.pixel_of_column(0)).origin;
    CHECK(glm::dot(step, camera.image_right()) == Approx(2.0 / n).epsilon(1e-9));
    const glm::dvec2 a = ends[0] - camera.eye(), b = ends[1] - camera.eye();
    const double angle = std::acos(glm::dot(a, b) / (glm::length(a) * glm::length(b)));
    CHECK(camera.field_of_view() == Approx(angle).epsilon(1e-9));
  }
}

TEST_CASE("placing a camera composes M_d once", "[camera][cache]") {
  ClassicMistakes mistakes;
  mistakes.printed_rotation_sign = true;
  long long before = placements_built_on_this_thread();
  Camera3D camera(16, 16, Orbit3D{}, mistakes);
  CHECK(placements_built_on_this_thread() - before == 1);
  before = placements_built_on_this_thread();
  camera.set_res(0.5);  // n changes, M_d does not
  CHECK(placements_built_on_this_thread() - before == 0);
  mistakes.printed_rotation_sign = false;
  camera.set_mistakes(mistakes);
  CHECK(placements_built_on_this_thread() - before == 1);
  CHECK(camera.view_direction() == Camera3D(16, 16).view_direction());  // and it rebuilt the right one
  before = placements_built_on_this_thread();
  Camera2D bar(16, Orbit2D{}, mistakes);
  bar.set_free({0, 3}, {0, 0}, 1.5);
  CHECK(placements_built_on_this_thread() - before == 2);
}
