// What the panels keep between frames: their widgets' own state (text boxes, a question waiting for the
// user's yes, a slider being dragged), never the lesson's. The frame owns it (FrameRenderer::panels), next to
// the session's AppState that the hosts own; the session never reads it.
#pragma once

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <map>
#include <string>
#include <vector>

#include "session/app_options.h"
#include "session/app_state.h"
#include "session/figure_export.h"

namespace raycam::ui {

// A widget's rectangle on screen, in pixels: (x0, y0) its top-left corner, (x1, y1) its bottom-right.
struct WidgetRect {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

using WidgetRects = std::map<std::string, WidgetRect>;  // by ImGui id ("###theta")

struct PanelState {
  glm::dmat4 shown_matrix{1.0};      // the last product the construction table showed (2D: its 3×3 top-left)
  float font_scale_editing = -1.0f;  // the font scale slider's value while dragged (applied on release)
  float font_scale_seen = -1.0f;     // by the Lecture mode section: a change scrolls its slider into view
  int font_scale_scroll_frames = 0;
  // A test hook, null in the app: where each labelled widget "###id" was last drawn (screen corners).
  WidgetRects* widget_rects = nullptr;
  // Check my camera (check_panel.h).
  std::string check_command;  // --check CMD: handed to the panel at the next frame, then cleared
  bool check_waiting = false;  // a verdict is on its way: the window keeps drawing (frame_needs_redraw)
  // Text inputs (Open and Save as have their own paths).
  std::string path_input;         // Open: the file last opened, or what the user typed
  std::uint64_t scene_opens_seen = 0;  // the session's scene_opens when path_input last followed an open
  int dimension_seen = 3;              // the dimension on screen then (a switch withdraws the questions too)
  std::string save_path;          // Save as: never filled with the opened file's path
  std::string overwrite_pending;  // Save as asked to replace this existing file: waiting for the user's yes
  // Export colour map's file: the default name (session::default_export_name) until the user types another.
  std::string export_path;
  std::string export_default;  // the default export_path was last given: while it still holds it, it follows
  std::vector<std::string> colour_map_replace_files;  // Export colour map asked to replace this file (full path)
  std::string figure_path;     // Export figure… (the construction panel); its default follows as export_path's
  std::string figure_default;
  int figure_format = 0;             // its format: 0 SVG, 1 PDF, 2 PNG, 3 TikZ (sets figure_path's extension)
  session::FigureContent figure;     // its rays per 2D frame and whether each frame's matrix is printed
  int figure_replace_pending = 0;  // Export figure asked to replace existing files: 1 the step, 2 every step
  std::vector<std::string> figure_replace_files;  // the files it asked about (full paths), found once when asked
};

// The panels at start-up for the app's options: --check CMD's program, the Open box showing the scene file
// opened, the colour map's default file name in the window's language.
PanelState panel_state_for(const session::AppOptions& options, const session::Lesson& lesson);

// After a scene file opened (the Open button, a dropped file, the page's picker: session::open_scene counts
// them) or the other dimension came on screen (Tab, the 2D/3D buttons): the Open box shows the file on screen,
// and no Replace question is left from the scene before (it would write another scene's camera, or other
// files than it named); after an open, Save as starts empty too.
void follow_scene_shown(const session::Lesson& lesson, PanelState& panels);

// The exports' default file names follow the window's language, the scene and the dimension on screen,
// unless the user typed another name (QA: the name stayed in the language the app started in, and 2D and 3D
// shared one, so the 2D bar replaced the 3D map).
void follow_default_names(const session::Lesson& lesson, PanelState& panels);

// Export colour map from the panel (the desktop's box, or the page's download name `path`): an existing file
// is replaced only with `overwrite`; otherwise panels.colour_map_replace_files names it and the panel asks,
// as Save as and Export figure do. Returns true if it wrote.
bool export_colour_map(session::AppState& state, PanelState& panels, const std::string& path, bool overwrite);

// Save as (session::save_preset_as) from the panel: an existing file is replaced only with `overwrite`;
// otherwise panels.overwrite_pending names it and the panel asks. Returns true if it saved.
bool save_as(session::AppState& state, PanelState& panels, const std::string& path, bool overwrite);

}  // namespace raycam::ui
