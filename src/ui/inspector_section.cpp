// The panel's "Ray inspector" section: the hovered or pinned pixel's ray (its canonical and placed origin and
// direction) and what it hits.
#include "ui/panels.h"

#include <imgui.h>

#include <string>

#include "session/inspection.h"
#include "ui/panel_widgets.h"

namespace raycam::ui {

using namespace session;  // the state the window shows and edits

void inspector_section(const AppState& state) {
  if (!section(tr(state.language, "Ray inspector###inspector"), tr(state.language, "Ray###inspector"), ImGuiTreeNodeFlags_DefaultOpen)) return;
  const auto pixel = active_pixel(state, state);
  if (!pixel) {
    explain(tr(state.language, "Hover a pixel of the colour bar or image to see its ray; click to pin it."));
    return;
  }
  const InspectedRay ray = inspect_pixel(state, state, *pixel);
  // Four decimals, no "-0.0000"; a tuple wraps between its numbers at lecture sizes.
  const int dimensions = dimension(state);
  // French writes 0,5000 and separates a tuple's numbers by " ; ".
  const Language language = state.language;
  const auto line = [dimensions, language](const char* name, const glm::dvec3& v) {
    std::string text = std::string(name) + " = (";
    for (int i = 0; i < dimensions; ++i)
      text += (i ? (language == Language::fr ? "\u00a0; " : ", ") : "") +
              formatted(language, "%.4f", without_negative_zero(v[i], 4));
    wrapped_between_words(text + ")");
  };
  std::visit(overloaded{[&](const View2D&) {  // the bar's pixel k, the handout's P_k and u_k
                          wrapped_between_words(
                              trf(state.language, "column %d = pixel k = %d (k = n−1−column)", pixel->column, ray.k));
                          line("P⁰ₖ", ray.canonical_pixel);
                          line("u⁰ₖ", ray.canonical_direction);
                          line("Pₖ", ray.origin);
                          line("uₖ", ray.direction);
                        },
                        [&](const View3D&) {
                          wrapped_between_words(trf(state.language, "row %d, column %d", pixel->row, pixel->column));
                          line("P⁰", ray.canonical_pixel);
                          line("u⁰", ray.canonical_direction);
                          line("P", ray.origin);
                          line("u", ray.direction);
                        }},
             state.view);
  if (ray.hit.id < 0) {
    wrapped_between_words(tr(state.language, "hit: nothing (background)"));
  } else {
    const std::string name = shown_object_name(state.language, state.view, std::size_t(ray.hit.id));
    wrapped_between_words(trf(state.language, "hit: object %d %s at t = %.4f", ray.hit.id, name.c_str(), ray.hit.t));
  }
}

}  // namespace raycam::ui
