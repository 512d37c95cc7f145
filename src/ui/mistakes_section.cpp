// The panel's "Classic mistakes" section: each mistake's checkbox, its "show me", what to look at and why,
// and the angle error of the handout's arccos.
#include "ui/panels.h"

#include <imgui.h>

#include <cmath>
#include <glm/gtc/constants.hpp>
#include <string>

#include "session/mistake_lessons.h"
#include "ui/panel_widgets.h"
#include "ui/theme.h"

namespace raycam::ui {

using namespace session;  // the state the window shows and edits

namespace {
// The angle recovered from the current CP by the handout's arccos and by atan2, against the slider's angle.
void arccos_error_line(const AppState& state) {
  std::string line;
  std::visit(
      overloaded{[&](const View2D& view) {  // θ: the 2D camera's one angle
                   const Orbit2D& o = view.orbit;
                   const glm::dvec2 cp = polar_direction(o.theta);
                   const double truth = std::remainder(o.theta, glm::two_pi<double>());
                   const auto error = [&](AngleRoute route) {
                     return std::abs(std::remainder(polar_angle(cp, route) - truth, glm::two_pi<double>()));
                   };
                   line = trf(state.language, "θ error now: arccos %.1e rad, atan2 %.1e rad", error(AngleRoute::handout_arccos),
                              error(AngleRoute::stable));
                 },
                 [&](const View3D& view) {  // φ: where the pole makes the arccos route fail
                   const Orbit3D& o = view.orbit;
                   const glm::dvec3 cp = spherical_direction(o.theta, o.phi);
                   const double truth = std::abs(std::remainder(o.phi, glm::two_pi<double>()));  // in [0, pi]
                   const auto error = [&](AngleRoute route) { return std::abs(spherical_angles(cp, route).phi - truth); };
                   line = trf(state.language, "φ error now: arccos %.1e rad, atan2 %.1e rad", error(AngleRoute::handout_arccos),
                              error(AngleRoute::stable));
                 }},
      state.view);
  explain(line.c_str());  // wrapped: at lecture sizes the line is wider than the panel
}
}  // namespace

void mistakes_section(AppState& state, const PanelState& panels) {
  const bool any = !mistakes_on(state).empty();
  if (!section(tr(state.language, "Classic mistakes###mistakes"), tr(state.language, "Mistakes###mistakes"), any ? ImGuiTreeNodeFlags_DefaultOpen : 0))
    return;
  bool changed = false, look_at_shown = false;
  for (const MistakeLesson& lesson : mistake_lessons()) {
    if (!mistake_applies(state, lesson)) continue;
    ImGui::PushID(lesson.id);
    changed |= checkbox(mistake_label(state, lesson), &mistake_flag(state, lesson));
    if (lesson.show_me) {
      same_line_if_fits(ImGui::CalcTextSize(tr(state.language, "show me")).x + 2 * ImGui::GetStyle().FramePadding.x);
      if (ImGui::SmallButton(tr(state.language, "show me"))) show_mistake(state, lesson);
      record_item_rect(panels, std::string("###show_me/") + lesson.id);
    }
    // What to look at, right under the button that changed it (after the explanation it was two screens
    // below at 3×), while that mistake is on (two mistakes share one show-me: the one on says it).
    const bool looking = !state.mistake_look_at.empty() && state.mistake_look_at == lesson.look_at &&
                         mistake_is_on(state, lesson);
    look_at_shown |= looking;
    if (looking) {
      ImGui::PushStyleColor(ImGuiCol_Text, current_theme().look_at);  // wrapped: not cut at the panel's edge
      ImGui::TextWrapped("%s", trf(state.language, "Look: %s", tr(state.language, lesson.look_at)).c_str());
      ImGui::PopStyleColor();
      record_item_rect(panels, "###look_at");
    }
    explain(mistake_text(state, state, lesson).c_str());
    if (!lesson.info) arccos_error_line(state);
    ImGui::PopID();
  }
  if (!look_at_shown) state.mistake_look_at.clear();  // its mistake was turned off
  if (changed) state.cameras_dirty = true;
}

}  // namespace raycam::ui
