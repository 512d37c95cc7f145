// Export figure in the page: the figures are drawn by cairo (src/figure/), which is not built for
// WebAssembly here, so the page's session answers with a message the construction panel shows.
#include <stdexcept>

#include "figure_export.h"

namespace raycam::session {

std::vector<std::string> export_construction_figure(const AppState&, const std::string&, bool) {
  throw std::runtime_error("Export figure needs the desktop app (or raycam-cli figure)");
}

std::vector<std::string> existing_figure_files(const AppState&, const std::string&, bool) { return {}; }

}  // namespace raycam::session
