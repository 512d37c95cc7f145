// The figure files cairo paints (figure_files.cpp): SVG, PDF (all `frames` as pages) or PNG, written to
// `file`; errors name `shown_name` (the final name, not the temporary one). The web page has no cairo: its
// version throws, naming the desktop app (src/web/cairo_files_web.cpp).
#pragma once

#include <string>
#include <vector>

#include "figure/figure_files.h"

namespace raycam::figure {

void write_cairo_file(const Figure& figure, const std::vector<int>& frames, const FigureOutput& output,
                      const std::string& file, const std::string& shown_name, WrittenFigure& written);

}  // namespace raycam::figure
