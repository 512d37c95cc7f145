// The control panel's sections, one function each, as functions of the app state and the panels' own
// widget state (Dear ImGui style: widgets report "changed", and only then is anything recomputed). Each
// section is drawn in a file of its own, named for it (camera_section.cpp, …, status_line.cpp, help_overlay.cpp);
// the widgets they share are in panel_widgets.h. Every visible string goes through tr/trf (ui/words.h).
#pragma once

#include <imgui.h>

#include <glm/mat4x4.hpp>
#include <optional>
#include <string>
#include <utility>

#include "session/app_state.h"
#include "ui/panel_state.h"

namespace raycam::ui {

// Lecture-size widgets every section uses (also check_panel.cpp): a checkbox whose label wraps instead of
// being cut, and a section header that shows `brief` when `full` does not fit (flags: ImGuiTreeNodeFlags).
bool checkbox(const char* label, bool* value);
// A button whose label goes over several lines rather than be cut.
bool button(const char* label);
// Text wrapped at the panel's edge between words only, never inside a number or a word that fits a line.
void wrapped_between_words(const std::string& text);
// The full screen button's label (English, the table's key): "Fullscreen (F11)", or in full screen
// "Leave full screen (F11)".
inline const char* fullscreen_label(const session::HostLink& link) {
  return link.in_fullscreen ? "Leave full screen (F11)" : "Fullscreen (F11)";
}
bool section(const char* full, const char* brief, int flags = 0);

void camera_section(session::AppState& state, const PanelState& panels);
void construction_section(session::AppState& state, PanelState& panels);
void inspector_section(const session::AppState& state);
void mistakes_section(session::AppState& state, const PanelState& panels);
void caster_section(session::AppState& state, const PanelState& panels);
void files_section(session::AppState& state, PanelState& panels);
void lecture_section(session::AppState& state, PanelState& panels);
void status_line(session::AppState& state, const PanelState& panels);
// The status line's times in at most `room` pixels of the current font: the frame's and the cast's always
// (shorter forms where the long ones do not fit), the caster and a coarse preview where they fit.
std::string status_timing_line(Language language, double frame_ms, double cast_ms, const char* caster, bool coarse,
                               float room);
// The work counters (rays, pixels skipped, tests, culled): the status line's tooltip.
void status_counters(const session::AppState& state);
// In a panel section: shows the message here if it came from `source` (wrapped, red for errors, with a
// Dismiss button) and it fits wholly in the panel's view; otherwise leaves its room empty, and the frame's line
// above the status line shows it (never both: at 3× a message cut by the panel's edge showed twice). Returns
// whether it showed it.
bool show_message(session::AppState& state, const PanelState& panels, session::MessageSource source);
// The frame's line above the status line: the message whole, whatever its source.
void show_message_line(session::AppState& state, const PanelState& panels);
// Did a section show the message this frame? If not, the frame shows it above the status line.
bool message_shown_this_frame(const session::Messages& messages, const session::HostLink& link);
// Is a text field (or a slider typed into with ctrl+click) being edited now?
bool editing_text();
// Takes Tab away from ImGui's focus cycling (call before ImGui::NewFrame, after the backend set its keys).
void take_tab_key();
void help_overlay(session::Display& shown, Language language);
// Tab (always: 2D/3D), then, unless a text field is being edited: arrow keys, +/-, [ ], PgUp/PgDn, Esc
// (F1/F11/F12 come from the executable).
void handle_shortcuts(session::AppState& state);

}  // namespace raycam::ui
