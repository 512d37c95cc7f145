// The panel's "Lecture mode" section: the font scale, high contrast, the language, full screen, help, hiding
// the panel.
#include "ui/panels.h"

#include <imgui.h>

#include <utility>

#include "ui/local_numbers.h"
#include "ui/panel_widgets.h"

namespace raycam::ui {

using namespace session;  // the state the window shows and edits

void lecture_section(AppState& state, PanelState& panels) {
  const bool open = section(tr(state.language, "Lecture mode###lecture"), tr(state.language, "Lecture###lecture"));
  record_item_rect(panels, "###lecture");
  const bool scale_changed = state.font_scale != panels.font_scale_seen;
  panels.font_scale_seen = state.font_scale;
  if (!open) return;
  // Everything above the slider grows or shrinks with the text: kept at the panel's middle for the two frames
  // the new size takes to lay out, the slider stays where the instructor's pointer is (it left the view).
  if (scale_changed) panels.font_scale_scroll_frames = 2;
  // Applied when the slider is released: the font atlas is rebuilt for each new size, not at every drag step.
  float& editing = panels.font_scale_editing;
  float scale = editing > 0 ? editing : state.font_scale;
  labelled(panels, tr(state.language, "font scale###font_scale"), [&](const char* l) {
    const LocalNumber number(state.language, l, "%.2f");
    const bool changed = ImGui::SliderFloat(l, &scale, 0.75f, 3.0f, number.format(), ImGuiSliderFlags_AlwaysClamp);
    scale = float(number.shown(scale));
    return changed;
  });
  if (panels.font_scale_scroll_frames > 0) {
    ImGui::SetScrollHereY(0.5f);
    --panels.font_scale_scroll_frames;
  }
  if (ImGui::IsItemActive()) {
    editing = scale;
  } else {
    state.font_scale = scale;
    editing = -1.0f;
  }
  checkbox(tr(state.language, "high contrast"), &state.high_contrast);
  static constexpr std::pair<Language, const char*> kLanguages[] = {{Language::en, tr_later("English")},
                                                                    {Language::fr, tr_later("Français")}};
  choice(state.language, panels, tr(state.language, "Language / Langue###language"), state.language, kLanguages);
  if (button(tr(state.language, fullscreen_label(state)))) state.requests.ask(HostRequestKind::toggle_fullscreen);
  record_item_rect(panels, "###fullscreen");
  same_line_if_fits(ImGui::CalcTextSize(tr(state.language, "Help (F1)")).x + 2 * ImGui::GetStyle().FramePadding.x);
  if (button(tr(state.language, "Help (F1)"))) state.show_help = !state.show_help;
  // At 3× the views are strips beside the panel: hidden, it gives them its width (the status line brings it back).
  if (button(tr(state.language, "Hide the panel (P)###hide_panel"))) state.panel_hidden = true;
  record_item_rect(panels, "###hide_panel");
}

}  // namespace raycam::ui
