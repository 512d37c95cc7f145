// The classic mistakes as the app teaches them: each one changes the image (at once, or after its "show me"),
// and what the panel says forgetting to renormalise does is what the caster does, checked against the
// conditions derived by hand in mistake_lessons.cpp (not against the caster's own output).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "session/app_options.h"
#include "app_state_for.h"
#include "session/inspection.h"
#include "session/mistake_lessons.h"

using namespace raycam;
using raycam::test::state_for;

namespace {

std::vector<int> ids_now(session::AppState& state) {
  state.cameras_dirty = true;
  REQUIRE(session::recast_if_needed(state));
  return state.map.ids;
}

int count_differences(const std::vector<int>& a, const std::vector<int>& b) {
  if (a.size() != b.size()) return int(std::max(a.size(), b.size()));  // another pixel count: all changed
  int differences = 0;
  for (std::size_t i = 0; i < a.size(); ++i) differences += a[i] != b[i];
  return differences;
}
}  // namespace

TEST_CASE("every classic mistake changes the image, at once or after its show me", "[ui][mistakes]") {
  for (const char* view : {"2d", "3d"})
    for (const session::MistakeLesson& lesson : session::mistake_lessons()) {
      session::AppState state = state_for({"--view", view});
      if (!session::mistake_applies(state, lesson)) continue;
      session::show_mistake(state, lesson);
      CHECK(state.mistake_look_at == lesson.look_at);
      CHECK(session::mistakes_on(state) == session::mistake_label(state, lesson));
      const std::vector<int> with_mistake = ids_now(state);
      session::mistake_flag(state, lesson) = false;
      const std::vector<int> without = ids_now(state);
      INFO(view << " " << lesson.id << ": " << state.map.width << "x" << state.map.height << ", "
                << count_differences(with_mistake, without) << " pixels differ");
      // At least 2% of the pixels (one pixel of a 13-pixel bar).
      CHECK(count_differences(with_mistake, without) * 50 >= int(without.size()));
      CHECK(session::mistakes_on(state).empty());
    }
}

TEST_CASE("show me moves to where the mistake shows", "[ui][mistakes]") {
  auto lesson = [](const std::string& id) {
    const session::MistakeLesson* found = session::find_lesson(id);
    REQUIRE(found);
    return *found;
  };
  session::AppState edges = state_for({"--view", "2d"});
  session::show_mistake(edges, lesson("pixel_edges"));
  CHECK(edges.res == Approx(0.05));
  session::AppState arccos = state_for({"--view", "2d", "--theta", "5"});
  session::show_mistake(arccos, lesson("arccos"));
  CHECK(dimension(arccos) == 3);  // in 2D the error never moves a pixel
  CHECK(view3d(arccos).orbit.phi < 1e-8);
  CHECK(std::abs(view3d(arccos).orbit.theta) > 0.3);  // theta must not be ~0, or losing it would change nothing
  session::AppState renormalise = state_for({"--df", "3"});
  session::show_mistake(renormalise, lesson("skip_renormalise"));
  CHECK(view3d(renormalise).orbit.df == 1.0);
}

// One circle, so that each pixel's hit or miss is decided by that circle alone. With f = origin - centre,
// b̂ = f·û, p² = |f|² - b̂² (squared distance from the centre to the ray's line), an un-normalised u hits
//   naive:  when p² ≤ r² + (|u|² - 1)·b̂²  (swollen),
//   stable: when p² + (|u|² - 1)²·b̂² ≤ r²  (shrunk to nothing unless |u| ≈ 1 or b̂ ≈ 0),
// with the object in front (b̂ < 0) and the origin outside it.
TEST_CASE("forgetting to renormalise does what the panel says, with both formulas", "[ui][mistakes]") {
  for (const IntersectFormula formula : {IntersectFormula::naive, IntersectFormula::stable})
    for (const double df : {1.0, 1.5, 3.0}) {
      session::AppState state =
          state_for({"--view", "2d", "--df", std::to_string(df), "--d", "6", "--mistake", "no-renormalise"});
      state.accuracy.options.formula = formula;
      const Circle circle{{0.4, 0.3}, 1.0, {200, 10, 10}, "lone"};
      view2d(state).scene.circles = {circle};
      ids_now(state);
      int predicted_hits = 0, hits = 0, disagreements = 0;
      for (int column = 0; column < state.map.width; ++column) {
        const Ray2D ray = view2d(state).camera.primary_ray(view2d(state).camera.pixel_of_column(column));
        const double length = glm::length(ray.direction);
        const glm::dvec2 f = ray.origin - circle.centre;
        const double b_unit = glm::dot(f, ray.direction / length);
        const double p2 = glm::dot(f, f) - b_unit * b_unit, r2 = circle.radius * circle.radius,
                     stretch = length * length - 1.0;
        const bool hit = b_unit < 0 && (formula == IntersectFormula::naive
                                            ? p2 <= r2 + stretch * b_unit * b_unit
                                            : p2 + stretch * stretch * b_unit * b_unit <= r2);
        predicted_hits += hit;
        hits += state.map.ids[std::size_t(column)] == 0;
        disagreements += hit != (state.map.ids[std::size_t(column)] == 0);
      }
      INFO((formula == IntersectFormula::naive ? "naive" : "stable")
           << " df " << df << ": " << hits << " hits, predicted " << predicted_hits);
      CHECK(disagreements <= 1);  // a ray grazing the predicted boundary may round either way
      // And the panel's words: the naive formula swells the circle (more hits than the correct camera); the
      // stable one loses it except where |u| ≈ 1 (d_f = 1, near the axis).
      session::AppState correct = state;
      correct.mistakes.skip_renormalise = false;
      const std::vector<int> right = ids_now(correct);
      int right_hits = 0;
      for (int id : right) right_hits += id == 0;
      if (formula == IntersectFormula::naive) {
        CHECK(hits > right_hits);
        CHECK_THAT(session::mistake_text(state, state, *session::find_lesson("skip_renormalise")), Catch::Contains("swells"));
      } else {
        CHECK(hits <= right_hits);
        if (df > 1.0) CHECK(hits == 0);
        CHECK_THAT(session::mistake_text(state, state, *session::find_lesson("skip_renormalise")), Catch::Contains("background"));
      }
    }
}

TEST_CASE("the views draw the caster's hits, mistakes included", "[ui][mistakes]") {
  for (const char* intersect : {"naive", "stable"})
    for (const char* view : {"2d", "3d"}) {
      session::AppState state = state_for({"--view", view, "--mistake", "no-renormalise", "--intersect", intersect,
                                      "--size", view == std::string("2d") ? "64" : "64x64"});
      ids_now(state);
      const std::vector<session::InspectedRay> fan = session::primary_ray_fan(state, state, 1000);
      REQUIRE(fan.size() == std::size_t(state.map.width));
      int hits = 0;
      for (const session::InspectedRay& ray : fan) {
        const int row = state.map.height / 2;
        CHECK(ray.hit.id == state.map.id_at(row, ray.pixel.column));
        if (ray.hit.id >= 0) {
          ++hits;
          CHECK(std::isfinite(ray.hit.t));
        }
      }
      // Before, the views always used the stable formula: with the naive one they drew every ray as a miss
      // while the bar was full of swollen objects.
      if (std::string(intersect) == "naive") CHECK(hits > 0);
    }
}

TEST_CASE("with unit rays, each drawn ray ends on the surface of the object the caster found",
          "[ui][mistakes]") {
  // Hits behind the origin (no_t_min) and rays from the eye included: the end point is where the caster hit.
  for (const char* id : {"", "no_t_min", "eye_origin"})
    for (const char* view : {"2d", "3d"}) {
      session::AppState state = state_for({"--view", view, "--size", std::string(view) == "2d" ? "64" : "64x64"});
      if (*id) session::show_mistake(state, *session::find_lesson(id));
      ids_now(state);
      int hits = 0;
      for (const session::InspectedRay& ray : session::primary_ray_fan(state, state, 1000)) {
        if (ray.hit.id < 0) continue;
        ++hits;
        const glm::dvec3 centre =
            std::string(view) == "2d"
                ? glm::dvec3(view2d(state).scene.circles[std::size_t(ray.hit.id)].centre, 0.0)
                : view3d(state).scene.spheres[std::size_t(ray.hit.id)].centre;
        const double radius = std::string(view) == "2d"
                                  ? view2d(state).scene.circles[std::size_t(ray.hit.id)].radius
                                  : view3d(state).scene.spheres[std::size_t(ray.hit.id)].radius;
        INFO(view << " " << id << " column " << ray.pixel.column);
        REQUIRE(std::isfinite(ray.hit.t));
        CHECK(glm::length(ray.end(0.0) - centre) == Approx(radius).epsilon(1e-9));
      }
      CHECK(hits > 0);
    }
}

// What each show-me line says is what the state shows: H forgotten says d_f = 3 (at d_f = 2 too); the two
// mistakes about what lies between the eye and the screen show the object on part of the image, not as a
// flat square filling it (which says nothing), and the correct camera sees past it there.
TEST_CASE("show me sets what its line says, and the image shows the mistake on part of it", "[ui][mistakes]") {
  for (const char* view : {"2d", "3d"}) {
    INFO(view);
    session::AppState focal = state_for({"--view", view, "--df", "2"});
    session::show_mistake(focal, *session::find_lesson("no_focal_scale"));
    CHECK(session::active_orbit(focal).df == 3.0);
    CHECK(std::string(focal.mistake_look_at).find("d_f = 3") != std::string::npos);
    for (const char* id : {"eye_origin", "no_t_min"}) {
      INFO(id);
      session::AppState state = state_for({"--view", view});
      const session::MistakeLesson& lesson = *session::find_lesson(id);
      CHECK(lesson.what_it_does != nullptr);  // a line says what the mistake does before any show-me
      session::show_mistake(state, lesson);
      const std::vector<int> with_mistake = ids_now(state);
      session::mistake_flag(state, lesson) = false;
      const std::vector<int> without = ids_now(state);
      const int differing = count_differences(with_mistake, without);
      CHECK(differing * 10 >= int(without.size()));      // the mistake shows…
      CHECK(differing * 10 <= 9 * int(without.size()));  // …on part of the image, not all of it
      const int first = with_mistake.front();
      CHECK(std::any_of(with_mistake.begin(), with_mistake.end(), [&](int id) { return id != first; }));
    }
  }
}

TEST_CASE("with non-square on, a show-me's coarse res reaches the rows too", "[ui][mistakes]") {
  // 256 x 256 at res_c 1, res_l 0.5: 256 columns, 128 rows. The show-me's res is meant for both sides: the
  // pixel edges' half pixel and the truncated res's lost pixel must show in the rows as in the columns.
  for (const char* id : {"pixel_edges", "res_truncated"}) {
    session::AppState state = state_for({"--view", "3d", "--size", "256x256", "--res", "1,0.5"});
    REQUIRE(state.res_rows);
    const session::MistakeLesson* lesson = session::find_lesson(id);
    REQUIRE(lesson);
    session::show_mistake(state, *lesson);
    ids_now(state);
    INFO(id << ": " << state.map.width << " x " << state.map.height);
    CHECK(state.map.width <= 13);  // round(0.05 * 256) = 13; 12.75 / 256 rounds to 13, truncates to 12
    CHECK(state.map.height == state.map.width);  // the same res on both sides of a square size
  }
}
