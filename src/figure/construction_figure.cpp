#include "construction_figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>
#include <limits>
#include <stdexcept>

#include "raycam/intersect.h"
#include "raycam/transform.h"

namespace raycam::figure {

namespace {

// The figures' words, French and English side by side (one place for each).
struct Words {
  const char* fr;
  const char* en;
  const char* in(Language language) const { return language == Language::fr ? fr : en; }
};

}  // namespace

std::string decimal(double value, int decimals, Language language) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  std::string s = text;
  if (s.find_first_not_of("-0.") == std::string::npos && s[0] == '-') s.erase(0, 1);
  if (language == Language::fr)
    for (char& c : s)
      if (c == '.') c = ',';
  return s;
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

// Points drawn at the same place share one label, "Ω = C", rather than two labels printed over each other.
void merge_coincident_labels(Frame& frame) {
  for (std::size_t i = 0; i < frame.markers.size(); ++i)
    for (std::size_t j = i + 1; j < frame.markers.size(); ++j) {
      Marker &a = frame.markers[i], &b = frame.markers[j];
      if (b.label.empty() || glm::length(a.at - b.at) > 1e-9 * (1.0 + glm::length(a.at))) continue;
      a.label = a.label.empty() ? b.label : a.label + " = " + b.label;
      b.label.clear();
    }
}

// The viewport: the camera's segments, the markers, the labels' anchors, and the objects once the camera is
// placed (a placed frame's rays may leave it: the painter clips them).
void fit_viewport(Frame& frame) {
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  auto add = [&](glm::dvec2 p, double r = 0.0) {
    lo = glm::min(lo, p - r);
    hi = glm::max(hi, p + r);
  };
  if (!frame.objects_faded)
    for (const Disc& disc : frame.objects) add(disc.centre, disc.radius);
  for (const Marker& marker : frame.markers) add(marker.at);
  for (const Label& label : frame.labels) add(label.at);
  for (const Segment& segment : frame.segments)
    if (segment.stroke != Stroke::ray || frame.objects_faded) {
      add(segment.from);
      add(segment.to);
    }
  const glm::dvec2 extent = glm::max(hi - lo, glm::dvec2(1e-9));
  const glm::dvec2 margin = 0.08 * glm::dvec2(std::max(extent.x, extent.y));
  frame.plane_min = lo - margin;
  frame.plane_max = hi + margin;
}

// ---- 2D ------------------------------------------------------------------------------------------------

// The handout's first rotation. raycam takes ψ0 = +π/2 (the handout prints -π/2: see the note of frame b):
// R(φ_v)·R(+π/2) = R(θ + π + π/2) = R(θ - π/2), the core's α.
constexpr double kFirstRotation2D = glm::half_pi<double>();

double view_angle_phi_v(const Camera2D& camera) {  // the angle of v = PC/‖PC‖, i.e. θ + π
  return camera.placement().alpha - kFirstRotation2D;
}

Frame frame_2d(const Scene2D& scene, const Camera2D& camera, int index, const FigureOptions& options) {
  const Language lang = options.language;
  const glm::dmat3 m = frame_matrix_2d(camera, index);
  const Orbit2D& orbit = camera.orbit();
  const bool canonical = index == 0, placed = index == 3;
  Frame frame;
  static const char kLetters[] = "abcd";
  frame.id = std::string(1, kLetters[index]);
  frame.title = (lang == Language::fr ? "cadre (" : "frame (") + frame.id + ")";
  frame.matrix = rows_of<3>(m);
  frame.matrix_size = 3;
  const double phi_v = std::remainder(view_angle_phi_v(camera), glm::two_pi<double>());
  switch (index) {
    case 0:
      frame.caption = Words{"M_d = I : la caméra canonique, écran [−1, 1] sur l'axe x, œil E0 = (0, 1), u⃗0 = (0, −1)",
                            "M_d = I: the canonical camera, screen [−1, 1] on the x axis, eye E0 = (0, 1), u⃗0 = (0, −1)"}
                          .in(lang);
      break;
    case 1:
      frame.caption = Words{"homothétie H(1, d_f), d_f = ", "scaling H(1, d_f), d_f = "}.in(lang) +
                      decimal(orbit.df, 3, lang) +
                      Words{", puis rotation R(ψ0), ψ0 = +π/2", ", then the rotation R(ψ0), ψ0 = +π/2"}.in(lang);
      frame.note = Words{"Le TD imprime ψ0 = −π/2 : avec ce signe, u⃗ finirait sur −v⃗ et la caméra regarderait à "
                         "l'opposé de C.",
                         "The handout prints ψ0 = −π/2: with that sign u⃗ would end on −v⃗ and the camera would "
                         "look away from C."}
                       .in(lang);
      break;
    case 2:
      frame.caption = Words{"rotation R(φ_v), φ_v = ", "rotation R(φ_v), φ_v = "}.in(lang) +
                      decimal(glm::degrees(phi_v), 1, lang) + "° " +
                      Words{": u⃗ est aligné sur v⃗ = PC/‖PC‖", ": u⃗ is aligned with v⃗ = PC/‖PC‖"}.in(lang);
      break;
    default:
      frame.caption = Words{"translation T(ΩP) : M_d = T·R·H, P = C + d (cos θ, sin θ), d = ",
                            "translation T(ΩP): M_d = T·R·H, P = C + d (cos θ, sin θ), d = "}
                          .in(lang) +
                      decimal(orbit.d, 3, lang) + ", θ = " + decimal(glm::degrees(orbit.theta), 1, lang) + "°";
  }

  for (const Circle& circle : scene.circles)
    frame.objects.push_back({circle.centre, circle.radius, circle.colour, circle.name});
  frame.objects_faded = !placed;

  // The camera: its screen with the pixels' ticks, the eye, the view vector.
  const glm::dvec2 centre = transform_point(m, kCanonicalScreenCentre2D);
  const glm::dvec2 eye = transform_point(m, kCanonicalEye2D);
  const auto ends = screen_corners_of(m);
  frame.segments.push_back({ends[0], ends[1], Stroke::camera});
  const int n = camera.pixel_count();
  const int tick_every = n <= 64 ? 1 : (n + 31) / 32;
  for (int k = 0; k < n; ++k) {
    if (k % tick_every != 0 && k != n - 1) continue;
    const double x = camera.canonical_pixel(k).x;
    frame.segments.push_back({transform_point(m, {x, -0.05}), transform_point(m, {x, 0.05}), Stroke::camera});
  }
  const double first_x = camera.canonical_pixel(0).x, last_x = camera.canonical_pixel(n - 1).x;
  frame.labels.push_back({transform_point(m, {first_x, -0.3}), "k = 0"});
  frame.labels.push_back(
      {transform_point(m, {last_x, -0.65}),
       "k = " + std::to_string(n - 1) +
           Words{" : colonne 0, à gauche de l'œil", ": column 0, the eye's left"}.in(lang)});
  const glm::dvec2 view = glm::normalize(transform_vector(m, kCanonicalView2D));
  frame.segments.push_back({centre, centre + view, Stroke::arrow});
  frame.labels.push_back({centre + 1.1 * view, canonical ? "u⃗0" : "u⃗"});

  frame.markers.push_back({Point::eye, eye, canonical ? "E0" : "E"});
  frame.markers.push_back({Point::screen_first_end, ends[0], ""});
  frame.markers.push_back({Point::screen_last_end, ends[1], ""});
  frame.markers.push_back({Point::screen_centre, centre, placed ? "P" : "Ω"});
  frame.markers.push_back({Point::target, orbit.target, "C"});

  // Where the camera must look: v = PC/‖PC‖, drawn at the camera once it has been turned.
  const glm::dvec2 position = camera.screen_centre();
  const glm::dvec2 v = glm::normalize(orbit.target - position);
  if (index == 2) {
    frame.segments.push_back({centre, centre + 1.6 * v, Stroke::construction});
    frame.labels.push_back({centre + 1.75 * v, "v⃗"});
  }
  if (placed) {
    frame.markers.push_back({Point::origin, glm::dvec2(0.0), "O"});
    frame.segments.push_back({glm::dvec2(0.0), centre, Stroke::construction});  // the translation ΩP
    frame.segments.push_back({centre, orbit.target, Stroke::construction});      // d along v
  }

  // A few primary rays (exercise 2): from P_k along u_k = M·(P_k^0 - E0); the eye-to-pixel line dashed.
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

Frame frame_3d(const Scene3D& scene, const Camera3D& camera, int step, const FigureOptions& options) {
  const Language lang = options.language;
  const glm::dmat4 m = construction_step(camera.placement(), step);
  const Orbit3D& orbit = camera.orbit();
  Frame frame;
  frame.id = std::to_string(step);
  frame.title = (lang == Language::fr ? "étape " : "step ") + frame.id;
  frame.matrix = rows_of<4>(m);
  frame.matrix_size = 4;
  switch (step) {
    case 0:
      frame.caption = Words{"identité : la caméra canonique, écran [−1, 1]², œil E0 = (0, 0, 1), u⃗0 = (0, 0, −1)",
                            "identity: the canonical camera, screen [−1, 1]², eye E0 = (0, 0, 1), u⃗0 = (0, 0, −1)"}
                          .in(lang);
      break;
    case 1:
      frame.caption = Words{"homothétie H(1, 1, d_f), d_f = ", "scaling H(1, 1, d_f), d_f = "}.in(lang) +
                      decimal(orbit.df, 3, lang);
      break;
    case 2:
      frame.caption = Words{"rotation R_z(ψ0), ψ0 = +π/2 : le haut de l'image tourne dans l'écran",
                            "rotation R_z(ψ0), ψ0 = +π/2: the image's up turns within the screen"}
                          .in(lang);
      frame.note = Words{"Le TD imprime ψ0 = −π/2 : l'image serait à l'envers (haut vers −z).",
                         "The handout prints ψ0 = −π/2: the image would be upside down (its up towards −z)."}
                       .in(lang);
      break;
    case 3:
      frame.caption = "R_y(φ), φ = " + decimal(glm::degrees(orbit.phi), 1, lang) + "°";
      break;
    case 4:
      frame.caption = "R_z(θ), θ = " + decimal(glm::degrees(orbit.theta), 1, lang) + "°";
      break;
    default:
      frame.caption = Words{"translation T(OP) : M_d = T·R_z(θ)·R_y(φ)·R_z(ψ0)·H, d = ",
                            "translation T(OP): M_d = T·R_z(θ)·R_y(φ)·R_z(ψ0)·H, d = "}
                          .in(lang) +
                      decimal(orbit.d, 3, lang);
  }
  for (const Sphere& sphere : scene.spheres)
    frame.objects.push_back({oblique_projection(sphere.centre), sphere.radius, sphere.colour, sphere.name});
  frame.objects_faded = step < kConstructionSteps3D;

  // The world axes, so that each rotation can be read off the drawing.
  const double axis = 1.5;
  const char* axis_names[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    glm::dvec3 end(0.0);
    end[i] = axis;
    frame.segments.push_back({oblique_projection(glm::dvec3(0.0)), oblique_projection(end), Stroke::construction});
    frame.labels.push_back({oblique_projection(end * 1.12), axis_names[i]});
  }
  const auto corners = screen_corners_of(m);  // top-left, top-right, bottom-right, bottom-left
  for (std::size_t i = 0; i < corners.size(); ++i)
    frame.segments.push_back(
        {oblique_projection(corners[i]), oblique_projection(corners[(i + 1) % 4]), Stroke::camera});
  const glm::dvec3 centre = transform_point(m, kCanonicalScreenCentre3D);
  const glm::dvec3 view = glm::normalize(transform_vector(m, kCanonicalView3D));
  const glm::dvec3 up = glm::normalize(transform_vector(m, {0.0, 1.0, 0.0}));
  frame.segments.push_back({oblique_projection(centre), oblique_projection(centre + view), Stroke::arrow});
  frame.labels.push_back({oblique_projection(centre + 1.15 * view), step == 0 ? "u⃗0" : "u⃗"});
  frame.segments.push_back({oblique_projection(centre), oblique_projection(centre + 0.8 * up), Stroke::arrow});
  frame.labels.push_back({oblique_projection(centre + 0.95 * up), Words{"haut", "up"}.in(lang)});
  const glm::dvec3 eye = eye_of(m);
  for (const glm::dvec3& corner : corners)  // the field of view: eye to each corner
    frame.segments.push_back({oblique_projection(eye), oblique_projection(corner), Stroke::construction});

  const bool placed = step == kConstructionSteps3D;
  frame.markers.push_back({Point::eye, oblique_projection(eye), step == 0 ? "E0" : "E"});
  frame.markers.push_back({Point::screen_first_end, oblique_projection(corners[0]), ""});
  frame.markers.push_back({Point::screen_last_end, oblique_projection(corners[2]), ""});
  frame.markers.push_back({Point::screen_centre, oblique_projection(centre), placed ? "P" : "Ω"});
  frame.markers.push_back({Point::target, oblique_projection(orbit.target), "C"});
  if (placed) {
    frame.markers.push_back({Point::origin, oblique_projection(glm::dvec3(0.0)), "O"});
    frame.segments.push_back({oblique_projection(centre), oblique_projection(orbit.target), Stroke::construction});
  }
  return frame;
}

}  // namespace

glm::dmat3 frame_matrix_2d(const Camera2D& camera, int frame) {
  const Placement2D& placement = camera.placement();
  switch (frame) {
    case 0:
      return glm::dmat3(1.0);
    case 1:
      return rotation_2d(kFirstRotation2D) * placement.scale;
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
