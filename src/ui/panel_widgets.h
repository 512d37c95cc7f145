// The widgets the control panel's sections draw with (internal to src/ui: each section's file includes it,
// and the ui tests that check a widget's rule; the frame and the hosts see the sections through ui/panels.h).
#pragma once

#include <imgui.h>

#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

#include "session/app_state.h"
#include "ui/panel_state.h"
#include "ui/panels.h"  // checkbox, button, wrapped_between_words, section: the frame's and the check panel's too
#include "ui/words.h"

namespace raycam::ui {

// A label's shown text and the id ImGui sees: "Save###save" gives "Save" and "###save"; a label with no id
// gives itself and "###" + itself, so the id stays the same whatever text a widget shows for it.
struct LabelParts {
  std::string shown, id;
};
LabelParts label_parts(const char* label);

// Where the last item is, for the tests (panels.widget_rects is null in the app).
void record_item_rect(const PanelState& panels, const std::string& id);

// The label beside the widget when both fit (the widget keeps at least `widget_min_width`), else on its own
// line above a full-width widget: a label is never cut, in any language at any font scale. `label` may carry
// an ImGui "###id" (kept either way).
// Sliders read as one column (the camera's) have their labels all beside or all above (QA at 2× on 1024×768:
// θ's short label sat beside its slider while the longer ones sat above theirs): while a LabelGroup lives,
// its widest label decides for each (each slider then keeps the room its own label leaves).
struct LabelGroup {
  explicit LabelGroup(std::initializer_list<const char*> labels);
  ~LabelGroup();
  LabelGroup(const LabelGroup&) = delete;
  LabelGroup& operator=(const LabelGroup&) = delete;
};
bool labelled(const PanelState& panels, const char* label, const std::function<bool(const char*)>& widget,
              float widget_min_width = 0.0f);

// Puts the next item on this line if `width` pixels still fit, else on the next line.
void same_line_if_fits(float width);

// A value as printed with `decimals` decimals, never "-0.000": a value that rounds to zero prints as 0.
double without_negative_zero(double value, int decimals);

// A hint in the theme's hint colour, wrapped between words.
void explain(const char* text);

// The one "… already exists. Replace it?" of every export (Save as, Export colour map, Export figure): the
// files found when the user clicked (looked for once, not at every frame), Replace and Cancel under it, and
// scrolled into view in the frame it is asked (at 3× it fell below the panel's edge: the click seemed to do
// nothing). `id` names its buttons ("###ID_replace", "###ID_cancel").
enum class ReplaceAnswer { waiting, replace, cancel };
ReplaceAnswer replace_question(Language language, const PanelState& panels, const std::vector<std::string>& files,
                               const std::string& id, bool just_asked);

// What a combo shows of its choice: the whole name where it fits the combo, else the name without its
// parenthesis ("stable (Ray Tracing Gems)" → "stable"), else that cut with "…" (its list shows every name
// whole). Recorded for the tests as "<id>/preview", its width in x1.
std::string combo_preview(const PanelState& panels, const std::string& id, const char* name);

// A combo over a fixed list of (value, name); returns true when the user picked another value.
template <class T, class Options>  // Options: a range of std::pair<T, const char*>
bool choice(Language language, const PanelState& panels, const char* label, T& value, const Options& options) {
  const char* current = "?";
  for (const auto& [v, name] : options)
    if (v == value) current = name;
  bool changed = false;
  const std::string id = label_parts(label).id;
  if (labelled(panels, label,
               [&](const char* l) { return ImGui::BeginCombo(l, combo_preview(panels, id, tr(language, current)).c_str()); })) {
    for (const auto& [v, name] : options)
      if (ImGui::Selectable(tr(language, name), v == value) && v != value) {
        value = v;
        changed = true;
      }
    ImGui::EndCombo();
  }
  return changed;
}

}  // namespace raycam::ui
