// The keyboard shortcuts the panel's sliders have (arrows, +/-, PgUp/PgDn, [ ], Tab, F, P, 1/2/3, Esc): no
// drawing, the keys the help window lists.
#include "ui/panels.h"

#include <imgui.h>
#include <imgui_internal.h>  // ImGui::ClearActiveID: Tab leaves a text field

#include <algorithm>
#include <glm/trigonometric.hpp>

#include "session/camera_ranges.h"

namespace raycam::ui {

using namespace session;  // the state the window shows and edits

namespace {
int g_tab_key = -1;  // the host's key index of Tab, taken away from ImGui (take_tab_key)
}  // namespace

bool editing_text() {
  // ImGui 1.86 keeps io.WantTextInput true after a field was left with Esc: ask which widget is active.
  const ImGuiContext& g = *GImGui;
  return g.ActiveId != 0 && g.InputTextState.ID == g.ActiveId;
}

void take_tab_key() {
  ImGuiIO& io = ImGui::GetIO();
  if (io.KeyMap[ImGuiKey_Tab] >= 0) {  // ImGui moves the focus between text fields on Tab: Tab is ours
    g_tab_key = io.KeyMap[ImGuiKey_Tab];
    io.KeyMap[ImGuiKey_Tab] = -1;
  }
}

void handle_shortcuts(AppState& state) {
  ImGuiIO& io = ImGui::GetIO();
  if (g_tab_key >= 0 && ImGui::IsKeyPressed(g_tab_key, false) &&
      !io.KeyCtrl) {  // always 2D/3D, even in a field
    ImGui::ClearActiveID();
    switch_dimension(state, dimension_of(state.other_view));
    return;
  }
  if (editing_text()) return;  // the arrows, + and - belong to the text field being edited
  const SharedOrbit<double> orbit = active_orbit(state);
  double &theta = orbit.theta, &d = orbit.d, &df = orbit.df;
  auto pressed = [](ImGuiKey key) { return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key)); };
  bool changed = false;
  const double kStep = glm::radians(5.0);  // one key press turns the camera by 5 degrees
  if (pressed(ImGuiKey_LeftArrow)) theta -= kStep, changed = true;
  if (pressed(ImGuiKey_RightArrow)) theta += kStep, changed = true;
  if (auto* view = std::get_if<View3D>(&state.view)) {  // the polar angle: 3D only
    double& phi = view->orbit.phi;
    if (pressed(ImGuiKey_UpArrow)) phi = std::max(kPolarRange.low, phi - kStep), changed = true;
    if (pressed(ImGuiKey_DownArrow)) phi = std::min(kPolarRange.high, phi + kStep), changed = true;
  }
  if (pressed(ImGuiKey_PageUp)) df = std::min(kFocalRange.high, df * 1.1), changed = true;
  if (pressed(ImGuiKey_PageDown)) df = std::max(kFocalRange.low, df / 1.1), changed = true;
  if (pressed(ImGuiKey_Escape)) state.pinned_pixel.reset();
  const int steps = construction_steps(state);
  for (ImWchar c : io.InputQueueCharacters) {
    if (c == '+' || c == '=') d = std::max(kDistanceRange.low, d / 1.1), changed = true;
    if (c == '-') d = std::min(kDistanceRange.high, d * 1.1), changed = true;
    int step = state.construction_step < 0 ? steps : state.construction_step;
    if (c == '[') step = std::max(0, step - 1);
    if (c == ']') step = std::min(steps, step + 1);
    if (c == '[' || c == ']') state.construction_step = step == steps ? -1 : step;
    if (c == 'f' || c == 'F') state.overhead_fit_pending = true;
    if (c == 'p' || c == 'P') state.panel_hidden = !state.panel_hidden;
    if (c == '1') toggle_maximised(state, ShownView::image);
    if (c == '2') toggle_maximised(state, ShownView::overhead);
    if (c == '3') toggle_maximised(state, ShownView::observer);
  }
  if (changed) state.cameras_dirty = true;
}

}  // namespace raycam::ui
