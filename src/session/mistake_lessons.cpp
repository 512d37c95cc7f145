#include "session/mistake_lessons.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>
#include <stdexcept>

#include "session/text.h"

namespace raycam::session {

namespace {
double& focal(AppState& state) { return active_orbit(state).df; }
double focal(const Lesson& state) { return active_orbit(state).df; }
int max_side(const AppState& state) { return active_max_side(state); }

// ---- pixel edges ---------------------------------------------------------------------------------------
std::string pixel_edges_does(const Lesson& state, const CastCache& cast) {
  const int n = std::max(cast.map.width, 1);
  std::string text =
      trf(state.language, "Every ray leaves half a pixel (1/n = %.3g) off its centre: a symmetric scene no longer "
          "gives a symmetric image.",
          1.0 / n);
  if (n > 32) text += " " + trf(state.language, "At n = %d, half a pixel is too small to see: show me.", n);
  return text;
}
// A show-me's res is both sides': with "non-square" on, setting only res (the columns') would leave the
// rows at their fine res, where the rows' half pixel or lost row is again too small to see.
void show_at_res(AppState& state, double res) {
  state.res = res;
  if (state.res_rows) state.res_rows = res;
}
void pixel_edges_show(AppState& state) { show_at_res(state, std::max(0.05, 1.0 / max_side(state))); }

// ---- res truncated -------------------------------------------------------------------------------------
void res_truncated_show(AppState& state) { show_at_res(state, 12.75 / max_side(state)); }  // round 13, floor 12

// ---- square pixels ---------------------------------------------------------------------------------------
// Only a non-square image shows it: the canonical screen is the square whatever nbc and nbl.
void square_pixels_show(AppState& state) {
  switch_dimension(state, 3);
  view3d(state).max_rows = std::max(16, view3d(state).max_columns / 2);
}

// ---- forgot to renormalise -----------------------------------------------------------------------------
// u_k = M_d·(P_k^0 - E0) keeps the length of (x, y, -d_f): |u| = sqrt(x² + y² + d_f²), from d_f on the axis
// to sqrt(1 + d_f²) (2D) or sqrt(2 + d_f²) (3D) at the edges. With f = origin - centre and b̂ = f·û:
// - naive: Δ = b² - c with b = |u|·b̂ accepts a ray when its distance p to the centre satisfies
//   p² ≤ r² + (|u|² - 1)·b̂²: objects swell with their distance;
// - stable: |f - b·u|² = p² + (|u|² - 1)²·b̂², so a ray hits only if p² + (|u|² - 1)²·b̂² ≤ r²: unless
//   |u| ≈ 1, only objects whose nearest point is close to the screen (b̂ small) are hit.
// (tests/session/test_mistake_lessons.cpp checks both conditions pixel by pixel.)
std::string renormalise_does(const Lesson& state, const CastCache&) {
  const double df = focal(state), edge = std::sqrt((dimension(state) - 1) + df * df);  // 1 or 2 screen coordinates
  std::string text = trf(state.language, "Here |u| = %.2f on the axis to %.2f at the edges.", df, edge) + " ";
  if (state.accuracy.options.formula == IntersectFormula::stable)
    text +=
        tr(state.language, "The stable test takes |f − (f·u)u| as the ray's distance to the centre; that is a distance only "
           "if |u| = 1, and otherwise grows with how far the object is: rays miss everything not touching "
           "the screen, so the image is background (the ground too). With the naive formula objects swell "
           "instead.");
  else
    text +=
        tr(state.language, "The naive test Δ = b² − c uses b = f·u, too big by |u|: a ray hits when it passes within "
           "√(r² + (|u|² − 1)·b²) of the centre, so every object swells, the far ones most, and covers its "
           "neighbours; t is wrong too. With the stable formula objects vanish instead.");
  return text;
}
void renormalise_show(AppState& state) { focal(state) = 1.0; }

// ---- scaling H forgotten -------------------------------------------------------------------------------
// d_f = 3, whatever it was: the line says so, and at d_f = 1 H is the identity anyway.
void focal_scale_show(AppState& state) { focal(state) = 3.0; }

// ---- rays from the eye, hits behind the ray --------------------------------------------------------------
// Both only change what lies between the eye and the screen. Keep the camera's direction and move it so that
// the object nearest the target sits just behind the screen, between it and the eye, and to one side: its
// disc then covers half the image (centred, an object as wide as the screen would fill it all, a flat
// square that says nothing). The correct camera sees past it; the mistaken one shows it on that half.
template <class Vector, class Objects>
void put_object_behind_screen(const Objects& objects, Vector& target, double d, double& df, const Vector& view,
                              const Vector& side) {
  if (objects.empty()) return;
  const auto nearest = std::min_element(objects.begin(), objects.end(), [&](const auto& a, const auto& b) {
    return glm::length(a.centre - target) < glm::length(b.centre - target);
  });
  const double r = nearest->radius, depth = 1.25 * r;  // the centre's distance in front of the screen
  df = std::max(df, 3.0 * r);                             // the eye behind the object
  // r to the side: the object's edge on the axis, so its disc starts at the image's centre.
  const Vector screen_centre = nearest->centre + view * depth - side * r;
  target = screen_centre + view * d;
}
void object_behind_screen_show(AppState& state) {
  try {
    place_cameras(state);  // the current view direction
  } catch (const std::invalid_argument&) {
    return;  // parameters out of range: the recast says why
  }
  std::visit(
      [](auto& view) {
        put_object_behind_screen(objects_of(view.scene), view.orbit.target, view.orbit.d, view.orbit.df,
                                 view.camera.view_direction(), view.camera.image_right());
      },
      state.view);
}
std::string eye_origin_does(const Lesson& state, const CastCache&) {
  return tr(state.language, "Rays start at the eye instead of the pixel on the screen: what lies between the eye and the "
            "screen is now seen, and t is measured from the eye. At most settings nothing is there: show me.");
}
std::string no_t_min_does(const Lesson& state, const CastCache&) {
  return tr(state.language, "The smaller root is taken whatever its sign: a hit behind the ray's start on the screen counts, "
            "and beats any in front. At most settings nothing is behind the screen: show me.");
}

// ---- arccos route --------------------------------------------------------------------------------------
std::string arccos_does(const Lesson& state, const CastCache&) {
  if (dimension(state) == 2)
    return tr(state.language,
        "Placing the camera from P and C with the handout's arccos: an input rounding ε becomes an angle "
        "error √(2ε), at most ~10⁻⁸ rad in 2D: no pixel moves at any setting (the numbers below show it). "
        "Show me goes to 3D, where the pole makes it visible.");
  return tr(state.language,
      "Placing the camera from P and C with the handout's arccos: near a pole an input rounding ε becomes an "
      "angle error √(2ε); below φ ≈ 10⁻⁸ rad cos φ rounds to 1, φ becomes 0 and θ is lost.");
}
void arccos_show(AppState& state) {
  switch_dimension(state, 3);
  view3d(state).orbit.phi = glm::radians(1e-7);
  if (std::abs(std::remainder(view3d(state).orbit.theta, 2 * glm::pi<double>())) < glm::radians(20.0))
    view3d(state).orbit.theta = glm::radians(60.0);
}

const char* kNothingToAdd = "";
}  // namespace

const std::vector<MistakeLesson>& mistake_lessons() {
  static const std::vector<MistakeLesson> lessons = [] {
    std::vector<MistakeLesson> all;
    for (const MistakeInfo& info : kClassicMistakes) all.push_back({info.id, &info, nullptr, nullptr, kNothingToAdd});
    auto extend = [&](const char* id, decltype(MistakeLesson::what_it_does) does, void (*show)(AppState&), const char* look) {
      for (MistakeLesson& lesson : all)
        if (std::string(lesson.id) == id) lesson.what_it_does = does, lesson.show_me = show, lesson.look_at = look;
    };
    extend("pixel_edges", pixel_edges_does, pixel_edges_show,
           tr_later(
               "res 0.05: each ray leaves from a pixel's left edge, not its centre; toggle to see the image "
               "jump half a pixel"));
    extend("skip_renormalise", renormalise_does, renormalise_show,
           tr_later("d_f = 1: the axis ray has |u| = 1 and is right; the error grows towards the edges of "
                    "the image"));
    extend("res_truncated", nullptr, res_truncated_show,
           tr_later("res·N = 12.75: floor gives 12 pixels, round 13; count them"));
    extend("square_pixels", nullptr, square_pixels_show,
           tr_later("the image is now twice as wide as tall: the square screen gives it pixels twice as tall as "
                    "wide, the stretched screen sees twice the field across"));
    extend("no_focal_scale", nullptr, focal_scale_show,
           tr_later("d_f = 3: without H the field of view stays 90°, as at d_f = 1"));
    const char* behind = tr_later(
        "the object nearest the target is now between the eye and the screen, to the right: the correct "
        "camera sees past it, the mistaken one shows it on the right half of the image");
    extend("eye_origin", eye_origin_does, object_behind_screen_show, behind);
    extend("no_t_min", no_t_min_does, object_behind_screen_show, behind);
    all.push_back(
        {"arccos", nullptr, arccos_does, arccos_show,
         tr_later("φ = 10⁻⁷°: arccos returns φ = 0 and θ = 0, so the image turns by θ; toggle to compare")});
    return all;
  }();
  return lessons;
}

const MistakeLesson* find_lesson(const std::string& id) {
  for (const MistakeLesson& lesson : mistake_lessons())
    if (id == lesson.id) return &lesson;
  return nullptr;
}

bool& mistake_flag(Lesson& state, const MistakeLesson& lesson) {
  return lesson.info ? state.mistakes.*lesson.info->flag : state.arccos_route;
}
bool mistake_is_on(const Lesson& state, const MistakeLesson& lesson) {
  return lesson.info ? state.mistakes.*lesson.info->flag : state.arccos_route;
}
bool mistake_applies(const Lesson& state, const MistakeLesson& lesson) {
  return !lesson.info || exists_in(*lesson.info, dimension(state));
}
const char* mistake_label(const Lesson& state, const MistakeLesson& lesson) {
  return lesson.info ? lesson.info->label[state.language]
                     : tr(state.language, "arccos route near a pole");
}

std::string mistake_text(const Lesson& state, const CastCache& cast, const MistakeLesson& lesson) {
  std::string text = lesson.info ? lesson.info->explanation[state.language] : "";
  if (lesson.what_it_does) text += (text.empty() ? "" : " ") + lesson.what_it_does(state, cast);
  return text;
}

void show_mistake(AppState& state, const MistakeLesson& lesson) {
  mistake_flag(state, lesson) = true;
  if (lesson.show_me) lesson.show_me(state);
  state.mistake_look_at = lesson.look_at;
  state.cameras_dirty = true;
}

std::string mistakes_on(const Lesson& state) {
  std::string names;
  for (const MistakeLesson& lesson : mistake_lessons())
    if (mistake_is_on(state, lesson) && mistake_applies(state, lesson))
      names += (names.empty() ? "" : ", ") + std::string(mistake_label(state, lesson));
  return names;
}

}  // namespace raycam::session
