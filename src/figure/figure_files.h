// Construction figures drawn with cairo into SVG, PDF or PNG: one drawing code for the three formats.
// Drawing happens in page points (1/72 inch) with an identity transform, so an SVG's coordinates are the
// page's; a PNG scales the whole page to its pixel size.
//
// The marked points (construction_figure.h's Point) are crosses stroked in near-black shades, one per kind:
// rgb(0, 0, k+1) for kind k. The eye cannot tell them apart; a test reading the SVG back can.
#pragma once

#include <string>
#include <vector>

#include "construction_figure.h"

namespace raycam::figure {

enum class Format { svg, pdf, png };

struct PageSize {
  double width_pt = 0.0, height_pt = 0.0;
  double pixels_per_point = 300.0 / 72.0;  // a PNG's resolution: 300 dpi for a size in mm, exact for px
  int width_px() const;
  int height_px() const;
};

// A size of `width` × `height` millimetres, or pixels (then 1 px = 0.75 pt, the CSS pixel).
PageSize page_in_mm(double width, double height);
PageSize page_in_px(int width, int height);

// The page point where a plane point of a frame lands (its drawing area, uniform scale, y up).
struct PageTransform {
  double scale = 1.0;
  double x0 = 0.0, y0 = 0.0;  // page position of the plane's origin
  double x(double plane_x) const { return x0 + scale * plane_x; }
  double y(double plane_y) const { return y0 - scale * plane_y; }
};
PageTransform page_transform(const Frame& frame, const PageSize& page, bool with_matrix);

struct FigureOutput {
  Format format = Format::svg;
  PageSize page = page_in_mm(160.0, 120.0);
  bool matrix = true;  // print each frame's matrix
  bool pages = false;  // PDF only: every frame as a page of one file
};

struct WrittenFigure {
  std::vector<std::string> files;
  std::vector<int> objects_drawn;  // per frame written: every object of the scene is drawn, never culled
};

// Writes the frames listed (indices into figure.frames) to `path`: one file when there is one frame or with
// `pages`, otherwise one file per frame named STEM-ID.EXT (figure-a.svg, …). Throws std::runtime_error
// naming the file when cairo cannot write it.
WrittenFigure write_figure(const Figure& figure, const std::vector<int>& frames, const FigureOutput& output,
                           const std::string& path);

const char* extension(Format format);

}  // namespace raycam::figure
