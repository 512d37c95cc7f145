#include "figure/construction_figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>
#include <limits>
#include <stdexcept>

#include "figure/figure_texts.h"
#include "figure/math_text.h"
#include "raycam/intersect.h"
#include "raycam/transform.h"

namespace raycam::figure {

namespace {

const std::string kMinus = "−";  // U+2212

std::string with_decimal_separator(std::string s, Language language) {
  std::string out;
  for (char c : s) {
    if (c == '-')
      out += kMinus;
    else
      out += c == '.' && language == Language::fr ? ',' : c;
  }
  return out;
}

}  // namespace

std::string decimal(double value, int decimals, Language language) {
  char text[400];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  std::string s = text;
  if (s.find_first_not_of("-0.") == std::string::npos && s[0] == '-') s.erase(0, 1);
  return with_decimal_separator(s, language);
}

std::string matrix_entry(double value, Language language) {
  constexpr std::size_t kWidest = 9;  // "−9999,999": wider, the columns would no longer fit the page
  char text[400];
  std::snprintf(text, sizeof text, "%.3f", value);
  if (std::strlen(text) <= kWidest) return decimal(value, 3, language);
  std::snprintf(text, sizeof text, "%.3e", value);  // "1.235e+05", "-4.000e-07"
  const std::string s = text;
  const std::size_t e = s.find('e');
  const int exponent = std::atoi(s.c_str() + e + 1);
  return with_decimal_separator(s.substr(0, e), language) + "·10^{" +
         with_decimal_separator(std::to_string(exponent), language) + "}";
}

std::string degrees_text(double radians, Language language) {
  double degrees = std::round(glm::degrees(radians) * 10.0) / 10.0;
  if (std::abs(degrees) == 360.0) degrees = 0.0;  // a full turn prints as none
  return decimal(degrees, 1, language) + "°";
}

namespace {

template <int N, class Matrix>
std::vector<std::array<double, 4>> rows_of(const Matrix& m) {
  std::vector<std::array<double, 4>> rows(N);
  for (int r = 0; r < N; ++r)
    for (int c = 0; c < N; ++c) rows[r][c] = m[c][r];  // GLM is column-major: m[column][row]
  return rows;
}

// A few pixels spread evenly over 0 … n-1, both ends included.
std::vector<int> ray_pixels(int count, int rays) {
  std::vector<int> pixels;
  if (rays <= 0) return pixels;
  if (rays == 1 || count == 1) return {(count - 1) / 2};
  for (int i = 0; i < rays; ++i) {
    const int k = int(std::lround(double(i) * (count - 1) / (rays - 1)));
    if (pixels.empty() || pixels.back() != k) pixels.push_back(k);
  }
  return pixels;
}

// Points drawn at the same place share one label, "C = Ω", rather than two labels printed over each other.
void merge_coincident_labels(Frame& frame) {
  for (std::size_t i = 0; i < frame.markers.size(); ++i)
    for (std::size_t j = i + 1; j < frame.markers.size(); ++j) {
      Marker &a = frame.markers[i], &b = frame.markers[j];
      if (b.label.empty() || glm::length(a.at - b.at) > 1e-9 * (1.0 + glm::length(a.at))) continue;
      const bool both_math = !a.label.empty() && a.label.back() == '$' && b.label.front() == '$';
      a.label = a.label.empty() ? b.label
                : both_math   ? a.label.substr(0, a.label.size() - 1) + " = " + b.label.substr(1)
                              : a.label + " = " + b.label;
      b.label.clear();
    }
}

// The caption's last words when the camera drawn has classic mistakes on: which ones.
std::string mistakes_said(const ClassicMistakes& mistakes, int dimension, Language language) {
  std::string names;
  for (const MistakeInfo& info : kClassicMistakes)
    if (mistakes.*info.flag && exists_in(info, dimension))
      names += (names.empty() ? "" : ", ") + escape_markup(info.label[language]);
  if (names.empty()) return "";
  return figure_text(language, "; classic mistake on: ") + names;
}

struct Extent {
  glm::dvec2 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
  void add(glm::dvec2 p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  double size() const { return std::max(hi.x - lo.x, hi.y - lo.y); }
  double distance(glm::dvec2 p) const { return glm::length(glm::max(glm::max(lo - p, p - hi), glm::dvec2(0.0))); }
};

bool on_camera(const Segment& s) { return s.stroke == Stroke::camera || s.stroke == Stroke::arrow; }
// The eye is left to the "near" test: at d_f = 50 it would shrink the screen and the scene to a dot.
bool on_camera(const Marker& m) { return m.point != Point::target && m.point != Point::origin && m.point != Point::eye; }

// The viewport: zoomed on the screen, with the eye, C, O and the construction lines when they are near it (within
// kNear camera sizes) and, once the camera is placed, the part of the scene around them. A target too far is
// shown by a pointer from the screen's centre. (A placed frame's rays may leave the viewport: it is clipped.)
void fit_viewport(Frame& frame) {
  constexpr double kNear = 6.0;
  Extent camera;
  for (const Segment& s : frame.segments)
    if (on_camera(s)) {
      camera.add(s.from);
      camera.add(s.to);
    }
  for (const Marker& m : frame.markers)
    if (on_camera(m)) camera.add(m.at);
  const double size = std::max(camera.size(), 1e-9);
  auto near = [&](glm::dvec2 p) { return camera.distance(p) <= kNear * size; };
  Extent view = camera;
  for (const Marker& m : frame.markers)
    if (near(m.at)) view.add(m.at);
  for (const Segment& s : frame.segments)
    if (s.stroke == Stroke::construction && near(s.from) && near(s.to)) {
      view.add(s.from);
      view.add(s.to);
    }
  for (const Label& l : frame.labels)
    if (near(l.at)) view.add(l.at);
  // C, O (once the camera is placed) or the eye (d_f = 50) far away: a pointer from the screen's centre named
  // after it; for C and O in place of the dashed line to it (the translation OP of a target at (5000, 3000)
  // ran off the page unnamed), the eye's lines to the pixels kept (they show where it lies).
  glm::dvec2 centre = 0.5 * (camera.lo + camera.hi);
  for (const Marker& m : frame.markers)
    if (m.point == Point::screen_centre) centre = m.at;
  std::vector<glm::dvec2> pointed;
  for (const Marker& m : frame.markers)
    if ((m.point == Point::target || m.point == Point::origin || m.point == Point::eye) && !near(m.at)) {
      const glm::dvec2 tip = centre + 0.9 * size * glm::normalize(m.at - centre);
      frame.segments.push_back({centre, tip, Stroke::pointer});
      frame.labels.push_back({tip, m.label});
      view.add(tip);
      if (m.point != Point::eye) pointed.push_back(m.at);
    }
  auto ends_at_pointed = [&](const Segment& s) {
    return s.stroke == Stroke::construction &&
           std::any_of(pointed.begin(), pointed.end(), [&](glm::dvec2 p) { return s.from == p || s.to == p; });
  };
  frame.segments.erase(std::remove_if(frame.segments.begin(), frame.segments.end(), ends_at_pointed),
                       frame.segments.end());
  if (!frame.objects_faded) {  // the scene around: each object's box, cut to the neighbourhood
    const double around = 0.5 * view.size();
    const glm::dvec2 lo = view.lo - around, hi = view.hi + around;
    Extent scene = view;
    for (const Disc& disc : frame.objects) {
      const glm::dvec2 a = glm::max(disc.centre - disc.radius, lo), b = glm::min(disc.centre + disc.radius, hi);
      if (a.x > b.x || a.y > b.y) continue;
      scene.add(a);
      scene.add(b);
    }
    view = scene;
  }
  const glm::dvec2 margin(0.05 * std::max(view.size(), 1e-9));
  frame.plane_min = view.lo - margin;
  frame.plane_max = view.hi + margin;
}

// The pixels' ticks: every pixel up to kMostTicks (the page thins them to 2 pt apart).
void add_ticks(Frame& frame, const Camera2D& camera, const glm::dmat3& m) {
  constexpr int kMostTicks = 2048;
  const int n = camera.pixel_count();
  const int every = std::max(1, (n + kMostTicks - 1) / kMostTicks);
  const glm::dvec2 across = glm::normalize(transform_vector(m, {0.0, 1.0}));
  for (int k = 0; k < n; ++k) {
    if (k % every != 0 && k != n - 1) continue;
    const glm::dvec2 pixel = transform_point(m, camera.canonical_pixel(k));
    frame.segments.push_back({pixel, pixel + across, Stroke::tick});
  }
}

// ---- 2D ------------------------------------------------------------------------------------------------

// The handout's first rotation. raycam takes ψ0 = +π/2 (the handout prints −π/2: docs/figures.md):
// R(φ_v)·R(+π/2) = R(θ + π + π/2) = R(θ − π/2), the core's α.
constexpr double kFirstRotation2D = glm::half_pi<double>();

std::string caption_2d(const Camera2D& camera, int index, Language lang) {
  const Orbit2D& orbit = camera.orbit();
  switch (index) {
    case 0:
      return figure_text(
          lang,
          "$M_d = I$: the canonical camera, screen $[−1, 1]$ on the $x$ axis centred at $Ω$, eye "
          "$E_0 = (0, 1)$, $\\vec{u}_0 = (0, −1)$");
    case 1:
      return figure_text(lang, "scaling $H(1, d_f)$, $d_f = ") + decimal(orbit.df, 3, lang) +
             figure_text(lang, "$: the eye moves back to $E = (0, d_f)$");
    case 2:
      return figure_text(lang, "rotation $R(α) = R(φ_v)·R(ψ_0)$, $ψ_0 = +π/2$, $φ_v = ") +
             degrees_text(std::remainder(view_angle_phi_v(camera), glm::two_pi<double>()), lang) +
             "$, $α = " + degrees_text(camera.placement().alpha, lang) +
             figure_text(lang, "$: $\\vec{u}$ is aligned with $\\vec{v} = \\vec{PC}/‖\\vec{PC}‖$");
    default:
      return figure_text(lang,
                         "translation $T(\\vec{ΩP})$: $M_d = T·R·H$, $P = C + d (cos θ, sin θ)$, $d = ") +
             decimal(orbit.d, 3, lang) + "$, $θ = " + degrees_text(orbit.theta, lang) + "$";
  }
}

Frame frame_2d(const Scene2D& scene, const Camera2D& camera, int index, const FigureOptions& options) {
  const Language lang = options.language;
  const glm::dmat3 m = frame_matrix_2d(camera, index);
  const Orbit2D& orbit = camera.orbit();
  const bool canonical = index == 0, placed = index == 3;
  Frame frame;
  static const char kLetters[] = "abcd";
  frame.id = std::string(1, kLetters[index]);
  frame.title = std::string(figure_text(lang, "frame (")) + frame.id + ")";
  frame.matrix = rows_of<3>(m);
  frame.matrix_size = 3;
  frame.caption = caption_2d(camera, index, lang) + mistakes_said(camera.mistakes(), 2, lang);

  for (const Circle& circle : scene.circles)
    frame.objects.push_back({circle.centre, circle.radius, circle.colour, circle.name});
  frame.objects_faded = !placed;

  // The camera: its screen with the pixels' ticks, the eye, the view vector.
  const glm::dvec2 centre = transform_point(m, kCanonicalScreenCentre2D);
  const glm::dvec2 eye = transform_point(m, kCanonicalEye2D);
  const auto ends = screen_corners_of(m);
  frame.segments.push_back({ends[0], ends[1], Stroke::camera});
  add_ticks(frame, camera, m);
  const int n = camera.pixel_count();
  frame.labels.push_back({transform_point(m, camera.canonical_pixel(0)), "$k = 0$"});
  frame.labels.push_back({transform_point(m, camera.canonical_pixel(n - 1)), "$k = " + std::to_string(n - 1) + "$"});
  const glm::dvec2 view = glm::normalize(transform_vector(m, kCanonicalView2D));
  frame.segments.push_back({centre, centre + view, Stroke::arrow});
  frame.labels.push_back({centre + view, canonical ? "$\\vec{u}_0$" : "$\\vec{u}$"});

  frame.markers.push_back({Point::eye, eye, canonical ? "$E_0$" : "$E$"});
  frame.markers.push_back({Point::screen_first_end, ends[0], ""});
  frame.markers.push_back({Point::screen_last_end, ends[1], ""});
  frame.markers.push_back({Point::screen_centre, centre, placed ? "$P$" : "$Ω$"});
  frame.markers.push_back({Point::target, orbit.target, "$C$"});

  // Where the camera must look: v = PC/‖PC‖, drawn at the camera once it has been turned.
  const glm::dvec2 v = glm::normalize(orbit.target - camera.screen_centre());
  if (index == 2) {
    frame.segments.push_back({centre, centre + 1.6 * v, Stroke::construction});
    frame.labels.push_back({centre + 1.6 * v, "$\\vec{v}$"});
  }
  if (placed) {
    frame.markers.push_back({Point::origin, glm::dvec2(0.0), "$Ω$"});  // the handout's Ω: the origin
    frame.segments.push_back({glm::dvec2(0.0), centre, Stroke::construction});  // the translation ΩP
    frame.segments.push_back({centre, orbit.target, Stroke::construction});      // d along v
  }

  // A few primary rays (exercise 2): from P_k along u_k = M·(P_k^0 − E0); the eye-to-pixel line dashed.
  // In frame d a ray stops at the object it hits; before, the camera is not placed yet and a ray is short.
  const double far = glm::length(glm::dvec2(1.0) + glm::abs(orbit.target)) + 4.0 * orbit.d;
  for (int k : ray_pixels(n, options.rays)) {
    const glm::dvec2 canonical_pixel = camera.canonical_pixel(k);
    const glm::dvec2 pixel = transform_point(m, canonical_pixel);
    const glm::dvec2 u = glm::normalize(transform_vector(m, canonical_pixel - kCanonicalEye2D));
    double t = placed ? far : 1.5;
    if (placed)
      for (const Circle& circle : scene.circles)
        t = std::min(t, nearest_hit_t<2, double>(pixel, u, circle.centre, circle.radius, IntersectFormula::stable));
    frame.segments.push_back({eye, pixel, Stroke::construction});
    frame.segments.push_back({pixel, pixel + t * u, Stroke::ray});
  }
  return frame;
}

// ---- 3D ------------------------------------------------------------------------------------------------

std::string caption_3d(const Orbit3D& orbit, int step, Language lang) {
  switch (step) {
    case 0:
      return figure_text(
          lang,
          "$M_d = I$: the canonical camera, screen $[−1, 1]^2$ centred at $Ω$, eye $E_0 = (0, 0, 1)$, "
          "$\\vec{u}_0 = (0, 0, −1)$");
    case 1:
      return figure_text(lang, "scaling $H(1, 1, d_f)$, $d_f = ") + decimal(orbit.df, 3, lang) +
             figure_text(lang, "$: the eye moves back to $E = (0, 0, d_f)$");
    case 2:
      return figure_text(lang, "rotation $R_z(ψ_0)$, $ψ_0 = +π/2$: the image's up turns within the screen");
    case 3:
      return "rotation $R_y(φ)$, $φ = " + degrees_text(orbit.phi, lang) + "$";
    case 4:
      return "rotation $R_z(θ)$, $θ = " + degrees_text(orbit.theta, lang) + "$";
    default:
      return figure_text(lang, "translation $T(\\vec{ΩP})$: $M_d = T·R_z(θ)·R_y(φ)·R_z(ψ_0)·H$, $d = ") +
             decimal(orbit.d, 3, lang) + "$";
  }
}

Frame frame_3d(const Scene3D& scene, const Camera3D& camera, int step, const FigureOptions& options) {
  const Language lang = options.language;
  const glm::dmat4 m = construction_step(camera.placement(), step);
  const Orbit3D& orbit = camera.orbit();
  Frame frame;
  frame.id = std::to_string(step);
  frame.title = std::string(figure_text(lang, "step ")) + frame.id;
  frame.matrix = rows_of<4>(m);
  frame.matrix_size = 4;
  frame.caption = caption_3d(orbit, step, lang) + mistakes_said(camera.mistakes(), 3, lang);
  for (const Sphere& sphere : scene.spheres)
    frame.objects.push_back({oblique_projection(sphere.centre), sphere.radius, sphere.colour, sphere.name});
  frame.objects_faded = step < kConstructionSteps3D;

  // The world axes, so that each rotation can be read off the drawing.
  const double axis = 1.5;
  const char* axis_names[] = {"$x$", "$y$", "$z$"};
  for (int i = 0; i < 3; ++i) {
    glm::dvec3 end(0.0);
    end[i] = axis;
    frame.segments.push_back({oblique_projection(glm::dvec3(0.0)), oblique_projection(end), Stroke::construction});
    frame.labels.push_back({oblique_projection(end), axis_names[i]});
  }
  const auto corners = screen_corners_of(m);  // top-left, top-right, bottom-right, bottom-left
  for (std::size_t i = 0; i < corners.size(); ++i)
    frame.segments.push_back(
        {oblique_projection(corners[i]), oblique_projection(corners[(i + 1) % 4]), Stroke::camera});
  const glm::dvec3 centre = transform_point(m, kCanonicalScreenCentre3D);
  const glm::dvec3 view = glm::normalize(transform_vector(m, kCanonicalView3D));
  const glm::dvec3 up = glm::normalize(transform_vector(m, {0.0, 1.0, 0.0}));
  frame.segments.push_back({oblique_projection(centre), oblique_projection(centre + view), Stroke::arrow});
  frame.labels.push_back({oblique_projection(centre + view), step == 0 ? "$\\vec{u}_0$" : "$\\vec{u}$"});
  frame.segments.push_back({oblique_projection(centre), oblique_projection(centre + 0.8 * up), Stroke::arrow});
  frame.labels.push_back({oblique_projection(centre + 0.8 * up), figure_text(lang, "up")});
  const glm::dvec3 eye = eye_of(m);
  for (const glm::dvec3& corner : corners)  // the field of view: eye to each corner
    frame.segments.push_back({oblique_projection(eye), oblique_projection(corner), Stroke::construction});

  const bool placed = step == kConstructionSteps3D;
  frame.markers.push_back({Point::eye, oblique_projection(eye), step == 0 ? "$E_0$" : "$E$"});
  frame.markers.push_back({Point::screen_first_end, oblique_projection(corners[0]), ""});
  frame.markers.push_back({Point::screen_last_end, oblique_projection(corners[2]), ""});
  frame.markers.push_back({Point::screen_centre, oblique_projection(centre), placed ? "$P$" : "$Ω$"});
  frame.markers.push_back({Point::target, oblique_projection(orbit.target), "$C$"});
  if (placed) {
    frame.markers.push_back({Point::origin, oblique_projection(glm::dvec3(0.0)), "$Ω$"});
    frame.segments.push_back({oblique_projection(centre), oblique_projection(orbit.target), Stroke::construction});
  }
  return frame;
}

}  // namespace

double view_angle_phi_v(const Camera2D& camera) { return camera.placement().alpha - kFirstRotation2D; }

glm::dmat3 frame_matrix_2d(const Camera2D& camera, int frame) {
  const Placement2D& placement = camera.placement();
  switch (frame) {
    case 0:
      return glm::dmat3(1.0);
    case 1:
      return placement.scale;
    case 2:
      return rotation_2d(view_angle_phi_v(camera)) * rotation_2d(kFirstRotation2D) * placement.scale;
    case 3:
      return placement.translation * rotation_2d(view_angle_phi_v(camera)) * rotation_2d(kFirstRotation2D) *
             placement.scale;
  }
  throw std::invalid_argument("frame: expected 0 … 3 (a … d), got " + std::to_string(frame));
}

glm::dvec2 oblique_projection(const glm::dvec3& p) {
  // Cavalier-like: the x axis recedes towards the lower left at 30°, at half length.
  constexpr double kDepth = 0.5, kCos = 0.8660254037844386, kSin = 0.5;
  return {p.y - kDepth * kCos * p.x, p.z - kDepth * kSin * p.x};
}

Figure construction_figure_2d(const Scene2D& scene, const Camera2D& camera, const FigureOptions& options) {
  Figure figure;
  figure.language = options.language;
  for (int i = 0; i < kFrames2D; ++i) {
    figure.frames.push_back(frame_2d(scene, camera, i, options));
    merge_coincident_labels(figure.frames.back());
    fit_viewport(figure.frames.back());
  }
  return figure;
}

Figure construction_figure_3d(const Scene3D& scene, const Camera3D& camera, const FigureOptions& options) {
  Figure figure;
  figure.language = options.language;
  for (int s = 0; s < kSteps3D; ++s) {
    figure.frames.push_back(frame_3d(scene, camera, s, options));
    merge_coincident_labels(figure.frames.back());
    fit_viewport(figure.frames.back());
  }
  return figure;
}

}  // namespace raycam::figure
