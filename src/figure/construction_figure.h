// The handout's construction of M_d as figures for course notes and slides: the 2D frames (a) → (d) and the
// 3D steps 0 → 5, each as a list of plane primitives (no drawing library here: construction_figure_painter.h
// draws them with cairo). The positions are the core's own numbers: each frame's matrix is a product of the
// camera's placement factors, and every point drawn is that matrix applied to a canonical point.
#pragma once

#include <array>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "raycam/camera2d.h"
#include "raycam/camera3d.h"
#include "raycam/languages.h"  // Language and LocalText: the core's one language type, as everywhere
#include "raycam/scene.h"

namespace raycam::figure {

enum class Stroke {
  camera,        // the screen, thick black
  arrow,         // a vector (u⃗, v⃗): a line with a head
  construction,  // dashed grey: eye-to-pixel lines, P → C, world axes
  ray,           // a primary ray, thin
  tick,          // a pixel's tick: `from` the pixel, `to` - `from` the direction across the screen (the page
                 // draws it at a fixed length, and thins the ticks to 2 pt apart)
  pointer,       // dashed with a head: towards a target too far to be in the drawing
};

struct Segment {
  glm::dvec2 from{0.0}, to{0.0};
  Stroke stroke = Stroke::camera;
};

struct Disc {  // an object of the scene (3D: the sphere's projected centre and its radius)
  glm::dvec2 centre{0.0};
  double radius = 1.0;
  Rgb8 colour;
  std::string name;
};

// The points a figure marks (and a test finds again in the drawing): each is a small cross.
enum class Point { eye, screen_first_end, screen_last_end, screen_centre, target, origin };
inline constexpr int kPointKinds = 6;

struct Marker {
  Point point = Point::eye;
  glm::dvec2 at{0.0};
  std::string label;  // math_text.h's markup, as every text of a frame
};

struct Label {  // free text anchored at a plane point (pixel indices, vector names); placed by the layout
  glm::dvec2 at{0.0};
  std::string text;
};

struct Frame {
  std::string id;       // "a" … "d" (2D), "0" … "5" (3D): the --frames value and the file name's suffix
  std::string title;    // "cadre (a)" / "frame (a)", "étape 2" / "step 2"
  std::string caption;  // what the step applies, in the handout's symbols (and a classic mistake, when on)
  std::vector<std::array<double, 4>> matrix;  // the frame's product of factors, rows (3 or 4 used)
  int matrix_size = 3;
  std::vector<Disc> objects;
  bool objects_faded = false;  // before M_d is complete the camera is not in the scene yet: objects in grey
  glm::dvec2 plane_min{0.0}, plane_max{0.0};  // the frame's viewport: the camera, and C and O when near,
                                              // plus the objects around them once the camera is placed
  std::vector<Segment> segments;
  std::vector<Marker> markers;
  std::vector<Label> labels;
};

struct Figure {
  Language language = Language::en;
  std::vector<Frame> frames;
};

struct FigureOptions {
  Language language = Language::en;
  int rays = 5;  // primary rays drawn per frame (evenly spread over the pixels, both ends included)
};

// The 2D frames of the handout, in order, the app's construction steps 0 … 3: (a) identity; (b) H(1, d_f);
// (c) then the rotations R(φ_v)·R(ψ0) = R(α), which turn u0 onto v = PC/‖PC‖; (d) then T(ΩP): M_d.
inline constexpr int kFrames2D = 4;
Figure construction_figure_2d(const Scene2D& scene, const Camera2D& camera, const FigureOptions& options);

// The 3D steps 0 (identity) … 5 (M_d), as the app's step-by-step view, in a fixed oblique projection.
inline constexpr int kSteps3D = kConstructionSteps3D + 1;
Figure construction_figure_3d(const Scene3D& scene, const Camera3D& camera, const FigureOptions& options);
// Either, for code written once over both dimensions.
inline Figure construction_figure(const Scene2D& scene, const Camera2D& camera, const FigureOptions& options) {
  return construction_figure_2d(scene, camera, options);
}
inline Figure construction_figure(const Scene3D& scene, const Camera3D& camera, const FigureOptions& options) {
  return construction_figure_3d(scene, camera, options);
}

// The 2D frames' matrices: frame 0 … 3 (a … d), the core's construction_step(0 … 3): (c) reached through
// the handout's two rotations, R(φ_v)·R(ψ0) = R(α).
glm::dmat3 frame_matrix_2d(const Camera2D& camera, int frame);

// A number as the figures print it: French with the decimal comma, the minus sign U+2212; never "−0".
std::string decimal(double value, int decimals, Language language);

// A matrix entry: 3 decimals, or in scientific notation when wider than 9 characters ("1,235·10^{5}",
// math_text.h's markup).
std::string matrix_entry(double value, Language language);

// An angle in degrees with one decimal, as printed: 359.99° is "0.0°", not "360.0°".
std::string degrees_text(double radians, Language language);

// The angle φ_v of v = PC/‖PC‖ that frame (c) prints: θ + π (of the camera drawn, mistakes included).
double view_angle_phi_v(const Camera2D& camera);

// The fixed oblique projection of the 3D figures (x towards the viewer, y to the right, z up).
glm::dvec2 oblique_projection(const glm::dvec3& point);

}  // namespace raycam::figure
