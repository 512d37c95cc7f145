// SVG, PDF and PNG figures are painted by cairo, which the page does not have: its Export figure offers TikZ
// alone (HostCapabilities::cairo_figures), so this answers only a call that should not happen.
#include <stdexcept>

#include "figure/cairo_files.h"

namespace raycam::figure {

void write_cairo_file(const Figure&, const std::vector<int>&, const FigureOutput&, const std::string&,
                      const std::string& shown_name, WrittenFigure&) {
  throw std::runtime_error(shown_name + ": SVG, PDF and PNG figures need the desktop app (or raycam-cli figure)");
}

}  // namespace raycam::figure
