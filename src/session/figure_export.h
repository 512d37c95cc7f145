// "Export figure…" in the construction panel: the figures of `raycam-cli figure` (src/figure) for the camera
// and scene on screen, in the window's language. The format follows the file name's extension, which the
// panel's format choice sets.
#pragma once

#include <string>
#include <vector>

#include "session/app_state.h"

namespace raycam::session {

// What a figure shows besides the camera and the scene: raycam-cli figure's --rays and --matrix.
struct FigureContent {
  int rays = 5;         // primary rays per 2D frame
  bool matrix = true;   // each frame's matrix printed
};

// The construction step shown (or, with `all_steps`, every step) of the lesson's view on screen, written to
// `path` (.svg, .pdf, .png or .tex for TikZ; all steps go to PATH-a.svg … or to one PDF of pages) with
// `content`'s rays and matrix. Returns the files written, as absolute paths; throws std::invalid_argument
// for a name without one of those extensions, std::runtime_error when a file cannot be written.
std::vector<std::string> export_construction_figure(const Lesson& lesson, const FigureContent& content,
                                                    const std::string& path, bool all_steps);

// The files among those the export would write that exist already (the panel asks before replacing them).
std::vector<std::string> existing_figure_files(const Lesson& lesson, const FigureContent& content,
                                               const std::string& path, bool all_steps);

// What the panel says after an export, short (at 3× a message above the status line of six paths covered
// half the views): one file by its full path; several by their count and one full path that spans them
// ("wrote 6 files: /home/x/figs/steps-0…5.svg").
std::string figure_files_message(Language language, const std::vector<std::string>& files);
// The question before replacing `existing` (full paths of one export's files), as short.
std::string figure_replace_question(Language language, const std::vector<std::string>& existing);

// The extensions of the formats, in the order of the panel's format choice (raycam-cli figure's --format).
inline constexpr const char* kFigureExtensions[] = {".svg", ".pdf", ".png", ".tex"};
inline constexpr int kTikzFigureFormat = 3;  // the one format that needs no native library (the page's)

// The index of `path`'s figure extension, or -1.
inline int figure_format_of(const std::string& path) {
  for (int i = 0; i < 4; ++i) {
    const std::string ext = kFigureExtensions[i];
    if (path.size() > ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0) return i;
  }
  return -1;
}

// `path` with the extension of format `format`, replacing a figure extension (or added to the name).
inline std::string with_figure_extension(const std::string& path, int format) {
  const int now = figure_format_of(path);
  const std::string stem = now < 0 ? path : path.substr(0, path.size() - std::string(kFigureExtensions[now]).size());
  return stem + kFigureExtensions[format];
}

}  // namespace raycam::session
