// A section's message (what an open, a save or an export did, or its error) under the section that made it,
// or on the line above the status line when it does not fit the panel's view.
#include "ui/panels.h"

#include <imgui.h>
#include <imgui_internal.h>  // the window's InnerClipRect: where the panel's inside is on screen

#include <string>

#include "ui/panel_widgets.h"
#include "ui/theme.h"

namespace raycam::ui {

using namespace session;  // the state the window shows and edits

namespace {
void draw_message(AppState& state, const PanelState& panels, const std::string& id) {
  const ThemeColours& theme = current_theme();
  ImGui::PushStyleColor(ImGuiCol_Text, state.message_is_error ? theme.error : theme.confirmation);
  ImGui::TextWrapped("%s", state.message.c_str());  // wrapped: never clipped
  ImGui::PopStyleColor();
  record_item_rect(panels, id);
  if (ImGui::SmallButton(tr(state.language, "Dismiss###dismiss_message"))) state.message.clear();
}
}  // namespace

bool show_message(AppState& state, const PanelState& panels, MessageSource source) {
  if (state.message.empty() || state.message_source != source) return false;
  // Whether the wrapped text fits between the panel's top and bottom edges, decided before drawing it: below
  // the fold (lecture sizes) or scrolled past, the line above the status line shows it, where the eye is.
  const float wrap = ImGui::GetContentRegionAvail().x;
  const float height = ImGui::CalcTextSize(state.message.c_str(), nullptr, false, wrap).y;
  // The window's visible inside: below its title bar (a text scrolled under it is cut, QA at 3×).
  const ImRect inside = ImGui::GetCurrentWindow()->InnerClipRect;
  const float top = ImGui::GetCursorScreenPos().y;
  if (top < inside.Min.y || top + height > inside.Max.y) {
    ImGui::Dummy(ImVec2(wrap, height));  // its room kept: the panel's scroll range does not jump
    return false;
  }
  draw_message(state, panels, "###message/section");
  state.message_shown_frame = state.frame_count;
  return true;
}

void show_message_line(AppState& state, const PanelState& panels) {
  if (!state.message.empty()) draw_message(state, panels, "###message/line");
}

bool message_shown_this_frame(const Messages& messages, const HostLink& link) {
  return messages.message_shown_frame == link.frame_count;
}

}  // namespace raycam::ui
