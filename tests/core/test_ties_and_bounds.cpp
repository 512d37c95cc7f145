// Ties go to the lower object index for EVERY cast method (plain included), with 1-3 threads and both
// formulas, and through the accuracy knobs (the reference caster, the exact bar); and the open bounds (radius 0, res 0, d 0, d_f just outside [1e-9, 1e9]) are refused by the
// setters and by scene files, while the closed ends and values just inside are accepted.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "raycam/accuracy_options.h"
#include "raycam/ray_caster.h"
#include "raycam/scene_file.h"
#include "test_support.h"

using namespace raycam;
using raycam::test::error_of;
using test::kPi;

namespace {
constexpr IntersectFormula kFormulas[] = {IntersectFormula::stable, IntersectFormula::naive};

// A scene where object 1 and object 2 are the same ball (every ray that hits one hits the other at the same
// t, bit for bit), object 0 elsewhere, and object 3 the same as 1 again: ids 2 and 3 may never appear.
template <class Object>
std::vector<Object> tied(const Object& elsewhere, const Object& ball) {
  Object twin = ball, third = ball;
  twin.colour = {2, 2, 2};
  third.colour = {3, 3, 3};
  return {elsewhere, ball, twin, third};
}

template <class Camera, class Scene>
void check_ties(const Camera& camera, const Scene& scene) {
  for (CastMethod method : kCastMethods)
    for (IntersectFormula formula : kFormulas)
      for (int threads : {1, 2, 3}) {
        INFO(cast_method_name(method) << ", formula " << int(formula) << ", " << threads << " threads");
        CastOptions options;
        options.method = method;
        options.formula = formula;
        options.threads = threads;
        const ColourMap map = cast_primary_rays(camera, scene, options);
        int ball = 0, later = 0;
        for (std::size_t i = 0; i < map.ids.size(); ++i) {
          ball += map.ids[i] == 1;
          later += map.ids[i] >= 2;
        }
        CHECK(ball > 0);  // the tied ball is in view: the tie is really exercised
        CHECK(later == 0);
      }
}
}  // namespace

TEST_CASE("ties go to the lower index for every cast method, 2D", "[caster][ties]") {
  Camera2D camera(64);
  camera.set_orbit({{0, 0}, 5.0, kPi / 2, 1.0});
  Scene2D scene;
  scene.circles = tied(Circle{{3, -1}, 0.5, {1, 1, 1}, ""}, Circle{{0, 0}, 0.8, {9, 9, 9}, ""});
  check_ties(camera, scene);
}

TEST_CASE("ties go to the lower index for every cast method, 3D", "[caster][ties]") {
  Camera3D camera(48, 40);
  camera.set_orbit({{0, 0, 0}, 6.0, 0.7, 1.2, 1.5});
  Scene3D scene;
  scene.spheres = tied(Sphere{{2, -2, 1}, 0.7, {1, 1, 1}, ""}, Sphere{{0, 0, 0}, 1.2, {9, 9, 9}, ""});
  check_ties(camera, scene);
}

namespace {
// The same tie through render_with_accuracy(), the path the accuracy knobs take (the reference caster; the
// exact bar in 2D): every scalar, both formulas, world and camera-relative frames, one and several samples.
template <class Camera, class Scene>
void check_ties_with_knobs(const Camera& camera, const Scene& scene, std::initializer_list<int> samples,
                           bool with_exact) {
  for (Scalar scalar : {Scalar::float32, Scalar::float64, Scalar::extended})
    for (IntersectFormula formula : kFormulas)
      for (int spp : samples)
        for (bool relative : {false, true})
          for (bool exact : {false, with_exact}) {
            INFO("scalar " << int(scalar) << ", formula " << int(formula) << ", " << spp << " samples, "
                           << (relative ? "camera-relative" : "world") << (exact ? ", exact bar" : ""));
            AccuracyFlags flags;
            flags.options = ReferenceOptions{scalar, formula, spp, relative};
            flags.exact = exact;
            const ColourMap map = render_with_accuracy(camera, scene, flags);
            int ball = 0, later = 0;
            for (int id : map.ids) {
              ball += id == 1;
              later += id >= 2;
            }
            CHECK(ball > 0);  // the tied ball is in view: the tie is really exercised
            CHECK(later == 0);
          }
}
}  // namespace

TEST_CASE("ties go to the lower index through the accuracy knobs, 2D", "[caster][ties][reference]") {
  Camera2D camera(64);
  camera.set_orbit({{0, 0}, 5.0, kPi / 2, 1.0});
  Scene2D scene;
  scene.circles = tied(Circle{{3, -1}, 0.5, {1, 1, 1}, ""}, Circle{{0, 0}, 0.8, {9, 9, 9}, ""});
  check_ties_with_knobs(camera, scene, {1, 3}, true);
}

TEST_CASE("ties go to the lower index through the accuracy knobs, 3D", "[caster][ties][reference]") {
  Camera3D camera(48, 40);
  camera.set_orbit({{0, 0, 0}, 6.0, 0.7, 1.2, 1.5});
  Scene3D scene;
  scene.spheres = tied(Sphere{{2, -2, 1}, 0.7, {1, 1, 1}, ""}, Sphere{{0, 0, 0}, 1.2, {9, 9, 9}, ""});
  check_ties_with_knobs(camera, scene, {1, 4}, false);
}

TEST_CASE("the setters refuse the open bounds and accept the closed ones", "[input][bounds]") {
  Camera2D c2(8);
  Camera3D c3(8, 8);
  CHECK_THROWS_WITH(c2.set_orbit({{0, 0}, 0.0, 0.0, 1.0}),
                    Catch::Contains("d") && Catch::Contains("]0, 1e12]"));
  CHECK_THROWS_WITH(c3.set_orbit({{0, 0, 0}, 0.0, 0.0, 1.0, 1.0}),
                    Catch::Contains("d") && Catch::Contains("]0, 1e12]"));
  CHECK_NOTHROW(c2.set_orbit({{0, 0}, 1e-300, 0.0, 1.0}));  // d is open at 0 only
  CHECK_NOTHROW(c3.set_orbit({{0, 0, 0}, 1e12, 0.0, 1.0, 1.0}));
  // d_f is closed: [1e-9, 1e9]; one ulp outside is refused.
  for (double df : {1e-9, 1e9}) {
    CHECK_NOTHROW(c2.set_orbit({{0, 0}, 1.0, 0.0, df}));
    CHECK_NOTHROW(c3.set_orbit({{0, 0, 0}, 1.0, 0.0, 1.0, df}));
  }
  for (double df : {0.0, std::nextafter(1e-9, 0.0), std::nextafter(1e9, 2e9)}) {
    INFO("df " << df);
    CHECK_THROWS_WITH(c2.set_orbit({{0, 0}, 1.0, 0.0, df}),
                      Catch::Contains("df") && Catch::Contains("[1e-9, 1e9]"));
    CHECK_THROWS_WITH(c3.set_orbit({{0, 0, 0}, 1.0, 0.0, 1.0, df}),
                      Catch::Contains("df") && Catch::Contains("[1e-9, 1e9]"));
  }
  // res is ]0, 1]: 0 refused, the smallest positive double gives one pixel.
  CHECK_THROWS_WITH(c2.set_res(0.0), Catch::Contains("res") && Catch::Contains("]0, 1]"));
  CHECK_THROWS_WITH(c3.set_res(0.0, 1.0), Catch::Contains("res"));
  CHECK_THROWS_WITH(c3.set_res(1.0, 0.0), Catch::Contains("res"));
  CHECK_THROWS_WITH(c2.set_res(std::nextafter(1.0, 2.0)), Catch::Contains("res"));
  c2.set_res(4.9e-324);
  CHECK(c2.pixel_count() == 1);
  // radius is ]0, 1e12]: validate() is what every scene goes through.
  Scene2D s2;
  s2.circles = {{{0, 0}, 0.0, {}, ""}};
  CHECK_THROWS_WITH(validate(s2), Catch::Contains("objects[0].radius") && Catch::Contains("]0, 1e12]"));
  s2.circles[0].radius = 4.9e-324;
  CHECK_NOTHROW(validate(s2));
  Scene3D s3;
  s3.spheres = {{{0, 0, 0}, 1.0, {}, ""}, {{0, 0, 0}, 0.0, {}, ""}};
  CHECK_THROWS_WITH(validate(s3), Catch::Contains("objects[1].radius") && Catch::Contains("]0, 1e12]"));
  // ... and closed at 1e12: just above it is refused, in 2D and 3D.
  s3.spheres[1].radius = 1e12;
  CHECK_NOTHROW(validate(s3));
  for (double radius : {std::nextafter(1e12, 2e12), 1e13, 1e300}) {
    INFO("radius " << radius);
    s3.spheres[1].radius = radius;
    CHECK_THROWS_WITH(validate(s3), Catch::Contains("objects[1].radius") && Catch::Contains("]0, 1e12]"));
    s2.circles[0].radius = radius;
    CHECK_THROWS_WITH(validate(s2), Catch::Contains("objects[0].radius") && Catch::Contains("]0, 1e12]"));
  }
}

namespace {
std::string sphere_with(const std::string& camera) {
  return R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0,0,0], "radius": 1}], "camera": {)" +
         camera + "}}";
}
}  // namespace

TEST_CASE("scene files refuse the open bounds and accept the closed ones", "[scene_file][input][bounds]") {
  CHECK_THAT(error_of(R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0,0,0], "radius": 0}]})"),
             Catch::Contains("objects[0].radius") && Catch::Contains("]0, 1e12]"));
  CHECK_THAT(error_of(R"({"dimension": 2, "objects": [{"type": "circle", "center": [0,0], "radius": 0}]})"),
             Catch::Contains("objects[0].radius") && Catch::Contains("]0, 1e12]"));
  CHECK_THAT(error_of(sphere_with(R"("res": 0)")),
             Catch::Contains("camera.res") && Catch::Contains("]0, 1]"));
  CHECK_THAT(error_of(sphere_with(R"("d": 0)")), Catch::Contains("camera.d") && Catch::Contains("]0, 1e12]"));
  CHECK_THAT(error_of(sphere_with(R"("df": 9.99999e-10)")),
             Catch::Contains("camera.df") && Catch::Contains("[1e-9, 1e9]"));
  CHECK_THAT(error_of(sphere_with(R"("df": 1.000001e9)")),
             Catch::Contains("camera.df") && Catch::Contains("[1e-9, 1e9]"));
  CHECK(error_of(sphere_with(R"("df": 1e-9, "d": 1e-300, "res": 1e-300)")) == "(no error)");
  CHECK(error_of(sphere_with(R"("df": 1e9)")) == "(no error)");
  // A radius is closed at 1e12: just above it (and far above) is refused by the reader, in 2D and 3D.
  CHECK(error_of(R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0,0,0], "radius": 1e12}]})") ==
        "(no error)");
  for (const std::string radius : {"1.0000000000001e12", "1e13", "1e300"}) {
    INFO("radius " << radius);
    CHECK_THAT(error_of(R"({"dimension": 3, "objects": [{"type": "sphere", "center": [0,0,0], "radius": )" +
                        radius + "}]}"),
               Catch::Contains("objects[0].radius") && Catch::Contains("]0, 1e12]"));
    CHECK_THAT(error_of(R"({"dimension": 2, "objects": [{"type": "circle", "center": [0,0], "radius": )" +
                        radius + "}]}"),
               Catch::Contains("objects[0].radius") && Catch::Contains("]0, 1e12]"));
  }
}
