// A frame laid out on its page, in page points (y down), before any drawing: the bands (title, caption,
// drawing area, matrix), the plane's primitives moved to the page, the pixel ticks thinned to 2 pt apart, and
// every label placed where it hits no other label, arrow, ray, tick, cross or disc (a greedy choice among
// positions around its anchor, farther with a leader line when nothing near is free). An object's name sits
// by its own object, on no other and nearer to its own than to any other; else on a leader from a free place
// to a dot on the object; else in a key beside the drawing (place_names). The cairo painter and the TikZ
// writer both draw this, so every format has the same layout.
#pragma once

#include <string>
#include <vector>

#include "figure/construction_figure.h"
#include "figure/math_text.h"

namespace raycam::figure {

enum class Format { svg, pdf, png, tikz };

struct PageSize {
  double width_pt = 0.0, height_pt = 0.0;
  double pixels_per_point = 300.0 / 72.0;  // a PNG's resolution: --dpi for a size in mm, exact for px
  int width_px() const;
  int height_px() const;
  double dpi() const { return 72.0 * pixels_per_point; }
};

// A size of `width` × `height` millimetres (a PNG at `dpi`), or pixels (1 px = 0.75 pt, the CSS pixel).
PageSize page_in_mm(double width, double height, double dpi = 300.0);
PageSize page_in_px(int width, int height);

struct FigureOutput {
  Format format = Format::svg;
  PageSize page = page_in_mm(160.0, 120.0);
  double font_size_pt = 9.0;  // labels, caption and matrix; the title 1.3×; whatever the page size
  bool matrix = true;         // print each frame's matrix
  bool title = true, caption = true;
  bool pages = false;       // PDF: every frame as a page of one file; TikZ: one file of Beamer overlays
  bool standalone = false;  // TikZ: a `standalone` document that compiles on its own
};

// The page point where a plane point of a frame lands (its drawing area, uniform scale, y up).
struct PageTransform {
  double scale = 1.0;
  double x0 = 0.0, y0 = 0.0;  // page position of the plane's origin
  double x(double plane_x) const { return x0 + scale * plane_x; }
  double y(double plane_y) const { return y0 - scale * plane_y; }
  glm::dvec2 operator()(glm::dvec2 p) const { return {x(p.x), y(p.y)}; }
};

struct Box {
  double left = 0.0, top = 0.0, right = 0.0, bottom = 0.0;
  double width() const { return right - left; }
  double height() const { return bottom - top; }
};
double overlap_area(const Box& a, const Box& b);

// A line of markup text at a page position: `at` is the left end of its baseline.
struct PlacedText {
  std::string markup;
  glm::dvec2 at{0.0};
  double size = 9.0;
  bool bold = false;
  Box box;                  // the font's extent (ascent to descent, the arrows over vectors, the scripts)
  bool leader = false;      // a thin line from `anchor` to the box: placed away from its point
  glm::dvec2 anchor{0.0};   // the point the label names
  bool dot = false;         // an object's name on a leader: a darker line ending in a dot on the object
};

inline constexpr double kNameLeaderWidth = 0.7;  // pt: a name's leader, and the dot it ends in
inline constexpr double kNameDotRadius = 1.4;

// An object's name that found no place by its object nor on a leader: a swatch of its colour and the name,
// in a column beside the drawing.
struct KeyEntry {
  PlacedText text;
  glm::dvec2 swatch{0.0};
  double swatch_radius = 0.0;
  Rgb8 colour;
};

struct PageDisc {
  glm::dvec2 centre{0.0};
  double radius = 0.0;
  Rgb8 colour;
  // A disc far bigger than the page, as the polygon of its part near the page (cairo's fixed point and TeX's
  // dimensions overflow on its centre and radius); empty for the others.
  std::vector<glm::dvec2> outline;
};

struct PageMarker {
  Point point = Point::eye;
  glm::dvec2 at{0.0};
};

struct MatrixCell {
  std::string markup;
  double right = 0.0, baseline = 0.0;  // right-aligned in its column
};

// A small framed overview of the whole scene in a corner of the drawing area, when the final frame's zoom on
// the camera shows too little of the scene (less than kInsetBelowShare of its extent, or an object's centre
// out of view): the objects as discs, the screen, the eye, C, and the zoomed region as a rectangle.
inline constexpr double kInsetBelowShare = 0.5;
inline constexpr double kInsetSize = 0.3;  // of the drawing area's width and height
inline constexpr double kInsetBackground[3] = {0.96, 0.96, 0.93};  // light: it reads as an inset
inline constexpr double kInsetArm = 2.0;                             // pt: its crosses' half length
struct PageInset {
  Box box;                       // on the page; zero width: no inset
  PageTransform to_inset;        // plane point → page point inside the box
  std::vector<PageDisc> discs;   // every object (at least a dot)
  std::vector<Segment> screen;   // the camera's screen
  std::vector<glm::dvec2> crosses;  // the eye and C
  Box zoom;                      // the main drawing's region
  bool shown() const { return box.width() > 0.0; }
};

struct PageFrame {
  PageTransform to_page;
  Box area;  // the drawing area: everything of the plane is clipped to it
  bool objects_faded = false;
  std::vector<PageDisc> discs;  // those that reach the drawing area
  std::vector<Segment> segments;  // in page points, cut to the drawing area; a tick at its page length
  std::vector<PageMarker> markers;
  std::vector<PlacedText> labels;  // the plane's labels, placed (clipped with the drawing)
  PlacedText title;                   // empty markup: none
  std::vector<PlacedText> caption;    // its lines, wrapped to the drawing's width
  PlacedText matrix_name;             // "M_d =" (empty markup: no matrix)
  std::vector<MatrixCell> cells;      // row by row
  Box matrix_brackets;             // the brackets' extent (empty without a matrix)
  double font_size = 9.0;
  double arm = 3.0;  // a cross's half length
  PageInset inset;
  std::vector<KeyEntry> key;  // empty: every name is in the drawing
  bool names_fit = true;      // false: even the key has no room (raycam-cli figure refuses the page)
};

// The page layout of frame `index` of `figure`. The bands are the same for every frame of the figure, so
// every frame has the same drawing area.
PageFrame lay_out_frame(const Figure& figure, int index, const FigureOutput& output);

// The drawing's height the title, the caption and the matrix leave on the page, in points; below
// kLeastDrawingShare of the page's height the layout gives the drawing that much anyway and the text runs
// over it (raycam-cli figure refuses such a page).
inline constexpr double kLeastDrawingShare = 0.2;
double room_for_drawing_pt(const Figure& figure, const FigureOutput& output);

// Whether every frame of `frames` names all its objects in view (by the object, on a leader or in the key).
bool names_fit(const Figure& figure, const std::vector<int>& frames, const FigureOutput& output);
// The smallest page bigger than `output`'s, of the same proportions, in whole `unit_pt` (a mm, a px), on which
// the names fit and the drawing has its room (room_for_drawing_pt); the page itself when none up to
// `largest_width_pt` does.
PageSize smallest_page_for_names(const Figure& figure, const std::vector<int>& frames, const FigureOutput& output,
                                 double unit_pt, double largest_width_pt);

// The width and the font's height (ascent, descent: a PDF reader's word box) above and below the baseline of a markup string set at `size` points.
struct TextExtent {
  double width = 0.0, above = 0.0, below = 0.0;
};
TextExtent measure_text(const std::string& markup, double size, bool bold = false);

// The scripts' size and shift, shared by the measure and the painter.
inline constexpr double kScriptScale = 0.7, kSubscriptDrop = 0.22, kSuperscriptRise = 0.38;
extern const char* const kFont;  // DejaVu Sans, the app's font: it has θ, φ, ψ, Ω and ‖

}  // namespace raycam::figure
