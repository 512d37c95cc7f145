// The classic mistakes (include/raycam/classic_mistakes.h): each one does what its name says, checked against
// formulas written here, and the accelerated casters stay exact for the mistakes that keep them.
#include <catch2/catch.hpp>
#include <glm/trigonometric.hpp>
#include <set>
#include <string>

#include "raycam/classic_mistakes.h"
#include "raycam/ray_caster.h"
#include "test_support.h"

using namespace raycam;
using raycam::test::kPi;

namespace {
ClassicMistakes only(bool ClassicMistakes::*flag) {
  ClassicMistakes mistakes;
  mistakes.*flag = true;
  return mistakes;
}

double max_difference(const glm::dmat4& a, const glm::dmat4& b) {
  double worst = 0;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) worst = std::max(worst, std::abs(a[c][r] - b[c][r]));
  return worst;
}

Scene3D spheres_around_target() {
  Scene3D scene;
  scene.spheres = {{{0, 0, 0}, 1.0, {200, 0, 0}, "a"},
                   {{1.5, 0.5, 0.8}, 0.6, {0, 200, 0}, "b"},
                   {{-1.2, 0.9, -0.4}, 0.7, {0, 0, 200}, "c"}};
  return scene;
}
}  // namespace

TEST_CASE("the mistake table names each ID once, the published ones all, in both languages", "[mistake]") {
  // The IDs docs/check.md and `check --report` published: never renamed nor removed (a new one is not added
  // here: the table is the only list of mistakes).
  const std::set<std::string> published = {"printed_rotation_sign", "pixel_edges", "mirrored", "upside_down",
                                           "rows_flipped", "degrees_as_radians", "no_focal_scale",
                                           "direction_translated", "eye_origin", "no_t_min", "theta_phi_swapped",
                                           "skip_renormalise", "square_pixels", "res_truncated"};
  std::set<std::string> seen;
  ClassicMistakes all;
  for (const MistakeInfo& info : kClassicMistakes) {
    INFO(info.id);
    CHECK(seen.insert(info.id).second);
    CHECK_FALSE(all.*info.flag);  // each entry has its own flag
    all.*info.flag = true;
    CHECK(find_mistake(info.id) == &info);
    for (Language language : kLanguages) {
      INFO(kLanguageCodes[std::size_t(language)]);
      CHECK(std::string(info.explanation[language]).find("Ex. ") == 0);  // points to the handout's exercise
      if (language != Language::en) CHECK(std::string(info.explanation[language]) != info.explanation.english());
    }
    CHECK((info.in_2d || info.in_3d));
    CHECK(std::string(info.battery_needs).size() > 0);
    CHECK(any_mistake(only(info.flag)));
  }
  for (const std::string& id : published) CHECK(seen.count(id) == 1);
  CHECK(find_mistake("typo") == nullptr);
  CHECK_FALSE(any_mistake(ClassicMistakes{}));
}

namespace {
// What a mistake changes in one dimension's camera: M_d, the rays of the pixels (their count included).
struct Change {
  bool placement = false, rays = false;
};
bool same_ray(const Ray3D& a, const Ray3D& b) { return a.origin == b.origin && a.direction == b.direction; }
bool same_ray(const Ray2D& a, const Ray2D& b) { return a.origin == b.origin && a.direction == b.direction; }

Change change_3d(const ClassicMistakes& mistakes, const Camera3D& right) {
  Camera3D wrong = right;
  wrong.set_mistakes(mistakes);
  Change change;
  change.placement = max_difference(wrong.world_from_camera(), right.world_from_camera()) > 0;
  change.rays = wrong.columns() != right.columns() || wrong.rows() != right.rows();
  for (int r = 0; !change.rays && r < right.rows(); ++r)
    for (int c = 0; c < right.columns(); ++c) change.rays = change.rays || !same_ray(wrong.primary_ray(r, c), right.primary_ray(r, c));
  return change;
}
Change change_2d(const ClassicMistakes& mistakes, const Camera2D& right) {
  Camera2D wrong = right;
  wrong.set_mistakes(mistakes);
  Change change;
  const glm::dmat3 a = wrong.world_from_camera(), b = right.world_from_camera();
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) change.placement = change.placement || a[c][r] != b[c][r];
  change.rays = wrong.pixel_count() != right.pixel_count();
  for (int k = 0; !change.rays && k < right.pixel_count(); ++k)
    change.rays = !same_ray(wrong.primary_ray(k), right.primary_ray(k));
  return change;
}
}  // namespace

TEST_CASE("each mistake's row names its hook and whether it only moves the camera, as it behaves",
          "[mistake]") {
  // A generic camera: every angle off the axes, d_f off 1, res·N with a fractional part, a non-square image.
  Camera3D right3d(40, 30, {{0.5, -1, 2}, 7.0, glm::radians(30.0), glm::radians(70.0), 2.5});
  right3d.set_res(0.83);
  Camera2D right2d(97, {{0.5, -1}, 6.0, glm::radians(35.0), 1.7});
  right2d.set_res(0.77);
  for (const MistakeInfo& info : kClassicMistakes) {
    INFO(info.id);
    std::vector<Change> changes;
    if (info.in_3d) changes.push_back(change_3d(only(info.flag), right3d));
    if (info.in_2d) changes.push_back(change_2d(only(info.flag), right2d));
    for (const Change& change : changes) {
      switch (info.hook) {
        case MistakeHook::placement:
          CHECK(change.placement);
          break;
        case MistakeHook::pixel:  // the same M_d, other rays
          CHECK_FALSE(change.placement);
          CHECK(change.rays);
          break;
        case MistakeHook::hit_rule:  // the same M_d and rays: only the caster's rule differs
          CHECK_FALSE(change.placement);
          CHECK_FALSE(change.rays);
          break;
      }
    }
    // A mistake on M_d keeps the fast casters; one on the hit rule cannot (they test boxes, not the rule).
    if (info.hook == MistakeHook::placement) CHECK(info.only_moves_camera);
    if (info.hook == MistakeHook::hit_rule) CHECK_FALSE(info.only_moves_camera);
    if (info.hook == MistakeHook::pixel && info.only_moves_camera && info.in_3d) {
      // Only n changes: the rays are those of a right camera with that many pixels.
      Camera3D wrong = right3d;
      wrong.set_mistakes(only(info.flag));
      Camera3D same_count = right3d;
      same_count.set_res(double(wrong.columns()) / wrong.max_columns(), double(wrong.rows()) / wrong.max_rows());
      CHECK_FALSE(change_3d(only(info.flag), same_count).rays);
    }
    CHECK(mistakes_change_only_placement(only(info.flag)) == info.only_moves_camera);
  }
}

TEST_CASE("mistakes on M_d: degrees as radians, no focal scale, theta/phi swapped, roll -pi/2", "[mistake]") {
  const Orbit3D orbit{{0.5, -1, 2}, 7.0, glm::radians(30.0), glm::radians(70.0), 2.5};
  Camera3D camera(8, 8);
  camera.set_orbit(orbit);
  const glm::dmat4 right = camera.world_from_camera();

  camera.set_mistakes(only(&ClassicMistakes::degrees_as_radians));
  CHECK(max_difference(camera.world_from_camera(),
                       placement_matrix(Orbit3D{orbit.target, 7.0, 30, 70, 2.5}).world_from_camera) < 1e-12);

  camera.set_mistakes(only(&ClassicMistakes::no_focal_scale));
  CHECK(max_difference(
            camera.world_from_camera(),
            placement_matrix(Orbit3D{orbit.target, 7.0, orbit.theta, orbit.phi, 1.0}).world_from_camera) ==
        0);
  CHECK(glm::length(camera.eye() - camera.screen_centre()) == Approx(1.0));

  camera.set_mistakes(only(&ClassicMistakes::theta_phi_swapped));
  CHECK(max_difference(
            camera.world_from_camera(),
            placement_matrix(Orbit3D{orbit.target, 7.0, orbit.phi, orbit.theta, 2.5}).world_from_camera) ==
        0);

  // Roll -π/2 instead of +π/2: the image's right and up both turn half a turn; the view does not change.
  camera.set_mistakes(only(&ClassicMistakes::upside_down));
  CHECK(glm::length(camera.screen_centre() - glm::dvec3(right[3])) < 1e-12);
  CHECK(glm::length(glm::dvec3(camera.world_from_camera()[0]) + glm::dvec3(right[0])) < 1e-12);
  CHECK(glm::length(glm::dvec3(camera.world_from_camera()[1]) + glm::dvec3(right[1])) < 1e-12);
  CHECK(camera.image_up().z < 0);  // world up now at the bottom

  Camera2D bar(16);
  bar.set_orbit({{1, 2}, 5.0, glm::radians(40.0), 1.5});
  bar.set_mistakes(only(&ClassicMistakes::degrees_as_radians));
  const glm::dvec2 expected = glm::dvec2(1, 2) + 5.0 * glm::dvec2(std::cos(40.0), std::sin(40.0));
  CHECK(glm::length(bar.screen_centre() - expected) < 1e-12);
  bar.set_mistakes(only(&ClassicMistakes::no_focal_scale));
  CHECK(glm::length(bar.eye() - bar.screen_centre()) == Approx(1.0));
}

TEST_CASE("mistakes on the pixels: mirrored, rows flipped, res truncated", "[mistake]") {
  Camera2D bar(60);
  bar.set_res(0.345);  // 20.7 pixels: round gives 21, floor 20
  CHECK(bar.pixel_count() == 21);
  bar.set_mistakes(only(&ClassicMistakes::res_truncated));
  CHECK(bar.pixel_count() == 20);
  bar.set_mistakes({});
  CHECK(bar.pixel_count() == 21);

  bar.set_mistakes(only(&ClassicMistakes::mirrored));
  for (int k = 0; k < 21; ++k)
    CHECK(bar.canonical_pixel(k).x == Approx(1.0 - (2.0 * k + 1.0) / 21).margin(1e-15));

  Camera3D camera(5, 4);
  camera.set_mistakes(only(&ClassicMistakes::rows_flipped));
  CHECK(camera.canonical_pixel(0, 0).y == Approx(-1.0 + 1.0 / 4));  // row 0 at the bottom
  CHECK(camera.canonical_pixel(0, 0).x == Approx(-1.0 + 1.0 / 5));
  camera.set_mistakes(only(&ClassicMistakes::mirrored));
  CHECK(camera.canonical_pixel(0, 0).x == Approx(1.0 - 1.0 / 5));
  CHECK(camera.canonical_pixel(0, 0).y == Approx(1.0 - 1.0 / 4));
  camera.set_res(0.7);  // 3.5 columns and 2.8 rows: round 4 × 3, floor 3 × 2
  camera.set_mistakes(only(&ClassicMistakes::res_truncated));
  CHECK(camera.columns() == 3);
  CHECK(camera.rows() == 2);
}

TEST_CASE("mistakes on the rays: eye origin, direction translated, hits behind accepted", "[mistake]") {
  Camera3D camera(6, 6);
  camera.set_orbit({{3, -2, 1}, 6.0, 0.7, 1.2, 2.0});
  const Ray3D right = camera.primary_ray(1, 4);
  const glm::dmat4 m = camera.world_from_camera();
  const glm::dvec3 canonical = camera.canonical_pixel(1, 4);

  camera.set_mistakes(only(&ClassicMistakes::eye_origin));
  CHECK(glm::length(camera.primary_ray(1, 4).origin - camera.eye()) < 1e-12);
  CHECK(glm::length(camera.primary_ray(1, 4).direction - right.direction) == 0);

  camera.set_mistakes(only(&ClassicMistakes::direction_translated));
  const glm::dvec4 as_point = m * glm::dvec4(canonical - glm::dvec3(0, 0, 1), 1.0);
  CHECK(glm::length(camera.primary_ray(1, 4).direction - glm::normalize(glm::dvec3(as_point))) < 1e-12);

  // A sphere wholly behind the camera, on its axis: the right camera never sees it; accepting t < 0 does.
  Camera3D looking(9, 9);
  looking.set_orbit({{0, 0, 0}, 5.0, 0.0, kPi / 2, 1.0});  // at (5,0,0) looking down -x
  Scene3D scene;
  scene.spheres = {{{9, 0, 0}, 1.0, {255, 0, 0}, "behind"}};
  CHECK(cast_primary_rays(looking, scene).id_at(4, 4) == -1);
  looking.set_mistakes(only(&ClassicMistakes::no_t_min));
  CHECK(cast_primary_rays(looking, scene).id_at(4, 4) == 0);
  // ... and it hides a sphere in front, whose hit has a larger t.
  scene.spheres.push_back({{0, 0, 0}, 1.0, {0, 255, 0}, "front"});
  CHECK(cast_primary_rays(looking, scene).id_at(4, 4) == 0);
  looking.set_mistakes({});
  CHECK(cast_primary_rays(looking, scene).id_at(4, 4) == 1);
}

TEST_CASE("upside down equals mirrored plus rows flipped", "[mistake]") {
  Camera3D a(24, 18), b(24, 18);
  const Orbit3D orbit{{0.2, 0.1, 0}, 6.0, 1.1, 1.0, 1.8};
  a.set_orbit(orbit);
  b.set_orbit(orbit);
  a.set_mistakes(only(&ClassicMistakes::upside_down));
  ClassicMistakes both;
  both.mirrored = both.rows_flipped = true;
  b.set_mistakes(both);
  const ColourMap ma = cast_primary_rays(a, spheres_around_target());
  const ColourMap mb = cast_primary_rays(b, spheres_around_target());
  int differ = 0;
  for (std::size_t i = 0; i < ma.ids.size(); ++i) differ += ma.ids[i] != mb.ids[i];
  CHECK(differ == 0);
}

TEST_CASE("accelerated casters equal the plain loop under the mistakes that keep them", "[mistake][caster]") {
  raycam::test::Random random(1212);
  for (const MistakeInfo& info : kClassicMistakes) {
    const ClassicMistakes mistakes = only(info.flag);
    INFO(info.id);
    for (int trial = 0; trial < 8; ++trial) {
      Scene3D scene;
      for (int i = 0; i < 20; ++i)
        scene.spheres.push_back({{random.uniform(-3, 3), random.uniform(-3, 3), random.uniform(-3, 3)},
                                 random.uniform(0.2, 1.0),
                                 {50, 50, 50},
                                 ""});
      Camera3D camera(40, 30);
      camera.set_res(0.83);
      camera.set_orbit({{0, 0, 0},
                        random.uniform(2, 9),
                        random.uniform(-3, 3),
                        random.uniform(0.1, 3),
                        random.uniform(0.5, 3)});
      camera.set_mistakes(mistakes);
      const ColourMap plain =
          cast_primary_rays(camera, scene, {IntersectFormula::stable, CastMethod::plain, 1});
      for (CastMethod method : {CastMethod::culled, CastMethod::footprint, CastMethod::binned})
        CHECK(cast_primary_rays(camera, scene, {IntersectFormula::stable, method, 2}).ids == plain.ids);

      Scene2D scene2d;
      for (int i = 0; i < 12; ++i)
        scene2d.circles.push_back(
            {{random.uniform(-3, 3), random.uniform(-3, 3)}, random.uniform(0.2, 1.0), {9, 9, 9}, ""});
      Camera2D bar(97);
      bar.set_res(0.77);
      bar.set_orbit({{0, 0}, random.uniform(2, 9), random.uniform(-3, 3), random.uniform(0.5, 3)});
      bar.set_mistakes(mistakes);
      const ColourMap plain2d =
          cast_primary_rays(bar, scene2d, {IntersectFormula::stable, CastMethod::plain, 1});
      CHECK(cast_primary_rays(bar, scene2d, {IntersectFormula::stable, CastMethod::footprint, 1}).ids ==
            plain2d.ids);
    }
  }
}
