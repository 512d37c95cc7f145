// "Export figure…" in the construction panel: the figures of `raycam-cli figure` (src/figure) for the camera
// and scene on screen, in the window's language. The format follows the file name's extension.
#pragma once

#include <string>
#include <vector>

#include "app_state.h"

namespace raycam::session {

// The construction step shown (or, with `all_steps`, every step) written to `path` (.svg, .pdf or .png; all
// steps go to PATH-a.svg … or to one PDF of pages). Returns the files written; throws std::invalid_argument
// for a name without one of those extensions, std::runtime_error when a file cannot be written.
std::vector<std::string> export_construction_figure(const Lesson& state, const std::string& path,
                                                    bool all_steps);

}  // namespace raycam::session
