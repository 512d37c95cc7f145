#include "mistake_lessons.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

namespace raycam::ui {

namespace {
std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
  char text[512];
  std::snprintf(text, sizeof text, pattern, a, b, c);
  return text;
}

// ---- printed rotation sign -----------------------------------------------------------------------------
std::string rotation_sign_does(const AppState&) {
  return "alpha = phi_v - 90 deg with phi_v the angle of v = PC turns u0 onto -v: the camera turns its back "
         "to "
         "the target and shows what is behind it.";
}

// ---- pixel edges ---------------------------------------------------------------------------------------
std::string pixel_edges_does(const AppState& state) {
  const int n = state.map.width;
  std::string text = format(
      "-1 + 2k/n is the left edge of pixel k: every ray leaves half a pixel (1/n = %.3g) "
      "off its centre, so the image slides half a pixel and a symmetric scene no longer "
      "gives a symmetric image.",
      1.0 / std::max(n, 1));
  if (n > 32) text += " At n = " + std::to_string(n) + " half a pixel is too small to see: show me.";
  return text;
}
void pixel_edges_show(AppState& state) {
  const int size =
      state.dimension == 2 ? state.max_pixels_2d : std::max(state.max_columns_3d, state.max_rows_3d);
  state.res = std::max(0.05, 1.0 / size);
}

// ---- forgot to renormalise -----------------------------------------------------------------------------
// u_k = M_d·(P_k^0 - E0) keeps the length of (x, y, -d_f): |u| = sqrt(x² + y² + d_f²), between d_f on the
// axis and sqrt(1 + d_f²) (2D) or sqrt(2 + d_f²) (3D) at the edges. With f = origin - centre and b̂ = f·û:
// - naive: Δ = b² - c with b = |u|·b̂ accepts a ray when its distance p to the centre satisfies
//   p² ≤ r² + (|u|² - 1)·b̂²: objects swell with their distance;
// - stable: |f - b·u|² = p² + (|u|² - 1)²·b̂², so a ray hits only if p² + (|u|² - 1)²·b̂² ≤ r²: unless
//   |u| ≈ 1, only objects whose nearest point is close to the screen (b̂ small) are hit.
std::string renormalise_does(const AppState& state) {
  const double df = state.dimension == 2 ? state.orbit2d.df : state.orbit3d.df;
  const double edge = std::sqrt((state.dimension == 2 ? 1.0 : 2.0) + df * df);
  std::string text =
      format("u_k keeps the length H gave it: |u| = %.2f on the axis to %.2f at the edges. ", df, edge);
  if (state.accuracy.options.formula == IntersectFormula::stable)
    text +=
        "The stable test takes |f - (f.u)u| as the ray's distance to the centre; that is a distance only if "
        "|u| = 1, and otherwise grows with how far the object is: rays miss everything not touching the "
        "screen, so the image is background (the ground too). With the naive formula the objects swell "
        "instead.";
  else
    text +=
        "The naive test Delta = b^2 - c uses b = f.u, too big by |u|: a ray hits when it passes within "
        "sqrt(r^2 + (|u|^2 - 1) b^2) of the centre, so every object swells, the far ones most, and covers "
        "its "
        "neighbours; t is wrong too. With the stable formula the objects vanish instead.";
  return text;
}
void renormalise_show(AppState& state) { (state.dimension == 2 ? state.orbit2d.df : state.orbit3d.df) = 1.0; }

// ---- arccos route --------------------------------------------------------------------------------------
std::string arccos_does(const AppState& state) {
  if (state.dimension == 2)
    return "Placing the camera from P and C with the handout's arccos: an input rounding e becomes an angle "
           "error "
           "sqrt(2e), at most ~1e-8 rad in 2D: no pixel moves at any setting here (the numbers below show "
           "it). "
           "Show me goes to 3D, where the pole makes it visible.";
  return "Placing the camera from P and C with the handout's arccos: near a pole an input rounding e becomes "
         "an "
         "angle error sqrt(2e); below phi ~ 1e-8 rad cos(phi) rounds to 1, phi becomes 0 and theta is lost.";
}
void arccos_show(AppState& state) {
  if (state.dimension == 2) switch_dimension(state, 3);
  state.arccos_route = true;
  state.orbit3d.phi = glm::radians(1e-7);
  if (std::abs(std::remainder(state.orbit3d.theta, 2 * glm::pi<double>())) < glm::radians(20.0))
    state.orbit3d.theta = glm::radians(60.0);
}
}  // namespace

const std::vector<MistakeLesson>& mistake_lessons() {
  static const std::vector<MistakeLesson> lessons = {
      {"printed-rotation", "printed rotation sign", "printed rotation sign",
       [](AppState& s) -> bool& { return s.mistakes.printed_rotation_sign; }, rotation_sign_does, nullptr,
       "the image shows what is behind the camera; the overhead view shows it looking away from C"},
      {"pixel-edges", "pixel edges instead of centres", "pixel edges",
       [](AppState& s) -> bool& { return s.mistakes.pixel_edges; }, pixel_edges_does, pixel_edges_show,
       "res 0.05: each ray leaves from a pixel's left edge (ticks on the screen); toggle to see the image "
       "jump "
       "half a pixel"},
      {"no-renormalise", "forgot to renormalise u_k", "u_k not renormalised",
       [](AppState& s) -> bool& { return s.mistakes.skip_renormalise; }, renormalise_does, renormalise_show,
       "d_f = 1: the axis ray has |u| = 1 and is right, the error grows towards the edges of the image"},
      {"arccos", "arccos route near a pole", "arccos route",
       [](AppState& s) -> bool& { return s.arccos_route; }, arccos_does, arccos_show,
       "phi = 1e-7 deg: arccos returns phi = 0 and theta = 0, so the image turns by theta; toggle to "
       "compare"},
  };
  return lessons;
}

void show_mistake(AppState& state, const MistakeLesson& lesson) {
  lesson.flag(state) = true;
  if (lesson.show_me) lesson.show_me(state);
  state.mistake_look_at = lesson.look_at;
  state.cameras_dirty = true;
}

std::string mistakes_on(const AppState& state) {
  std::string names;
  for (const MistakeLesson& lesson : mistake_lessons())
    if (lesson.flag(const_cast<AppState&>(state)))  // read only
      names += (names.empty() ? "" : ", ") + std::string(lesson.short_name);
  return names;
}

}  // namespace raycam::ui
