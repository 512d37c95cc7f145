// Construction figures written to files: SVG, PDF and PNG drawn with cairo (one drawing code for the three),
// TikZ written as LaTeX (tikz_file.h); all from the same page layout (figure_layout.h). Drawing happens in
// page points (1/72 inch) with an identity transform, so an SVG's coordinates are the page's; a PNG scales
// the whole page to its pixel size and records its dpi.
//
// The marked points (construction_figure.h's Point) are crosses stroked in near-black shades, one per kind:
// rgb(0, 0, k+1) for kind k. The eye cannot tell them apart; a test reading the SVG back can.
#pragma once

#include <string>
#include <vector>

#include "figure/construction_figure.h"
#include "figure/figure_layout.h"

namespace raycam::figure {

struct WrittenFigure {
  std::vector<std::string> files;
  std::vector<int> objects_drawn;  // per frame written: the objects that reach the drawing area, all drawn
};

// Writes the frames listed (indices into figure.frames) to `path`: one file when there is one frame or with
// `pages`, otherwise one file per frame named STEM-ID.EXT (figure-a.svg, …). Every file is written under a
// temporary name and renamed once all are complete; on failure nothing is left. Throws std::runtime_error
// naming the file when it cannot be written.
WrittenFigure write_figure(const Figure& figure, const std::vector<int>& frames, const FigureOutput& output,
                           const std::string& path);

// The files write_figure would write, in order (to ask before replacing them).
std::vector<std::string> figure_files(const Figure& figure, const std::vector<int>& frames,
                                      const FigureOutput& output, const std::string& path);

const char* extension(Format format);  // "svg", "pdf", "png", "tex"

}  // namespace raycam::figure
