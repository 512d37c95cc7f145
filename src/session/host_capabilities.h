// What the program showing the window can do, said once by its host (src/app, src/web) and read by the
// panels and the checker: the desktop window and the browser page differ here and nowhere else.
#pragma once

namespace raycam::session {

struct HostCapabilities {
  // Check my camera runs the student's program; a page cannot start one: it offers the case as a download
  // and takes the answer file back.
  bool runs_programs = true;
  // A worker thread grades the checks; a page has one thread and grades at once (milliseconds).
  bool grades_in_background = true;
  // Scene files come from the browser's file picker (an Open button on the status line), not only from a
  // typed path.
  bool picks_files = false;
  // F11 and the panel's button toggle full screen (a page: the browser's Fullscreen API).
  bool fullscreen = true;
  // What the app writes becomes a download the browser keeps (no "replace?" question: the browser keeps
  // both), named after the scene, and messages name a file by its name alone: the page's folders
  // (/home/web_user, /picked, /scenes) are not the student's (shown_files.h).
  bool files_are_downloads = false;
  // SVG, PDF and PNG figures are drawn by cairo, a native library the page does not have; TikZ is text and
  // is offered everywhere.
  bool cairo_figures = true;
};

inline constexpr HostCapabilities kDesktopHost{};
inline constexpr HostCapabilities kPageHost{false, false, true, true, true, false};

}  // namespace raycam::session
