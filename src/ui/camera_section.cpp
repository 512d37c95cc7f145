// The panel's "Camera" section: 2D or 3D, the orbit's sliders (d_f, d, θ, φ), the resolution, the target C,
// the image's size, Reset camera.
#include "ui/panels.h"

#include <imgui.h>
#include <imgui_internal.h>  // PushMultiItemsWidths, FindRenderedTextEnd: one drag field a coordinate

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>
#include <glm/trigonometric.hpp>
#include <optional>
#include <string>

#include "session/camera_ranges.h"
#include "ui/local_numbers.h"
#include "ui/panel_widgets.h"

namespace raycam::ui {

using namespace session;  // the state the window shows and edits

namespace {
// The slider edits the double itself (no float round trip): what the student sets is what the core gets.
// Its number in the window's language (LocalNumber: a decimal comma in French).
bool slider_double(Language language, const PanelState& panels, const char* label, double& value, double lo,
                   double hi, const char* format, bool logarithmic = false) {
  const ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp | (logarithmic ? ImGuiSliderFlags_Logarithmic : 0);
  return labelled(panels, label, [&](const char* l) {
    const LocalNumber number(language, l, format);
    const bool changed = ImGui::SliderScalar(l, ImGuiDataType_Double, &value, &lo, &hi, number.format(), flags);
    if (changed) value = number.shown(value);
    else number.shown(value);
    return changed;
  });
}

// The width drag_doubles' `count` fields need to show a coordinate such as -10.00 whole.
float drag_doubles_width(int count) {
  const ImGuiStyle& style = ImGui::GetStyle();
  return count * (ImGui::CalcTextSize("-10.00").x + 2 * style.FramePadding.x) + (count - 1) * style.ItemInnerSpacing.x;
}

// `count` doubles dragged in one widget, clamped to ±1000 (the target C).
// ImGui's DragScalarN, one field at a time so that each shows its number in the window's language.
bool drag_doubles(Language language, const char* label, double* values, int count) {
  static const double lo = -1000.0, hi = 1000.0;
  bool changed = false;
  ImGui::BeginGroup();
  ImGui::PushID(label);
  ImGui::PushMultiItemsWidths(count, ImGui::CalcItemWidth());
  for (int i = 0; i < count; ++i) {
    ImGui::PushID(i);
    if (i > 0) ImGui::SameLine(0, ImGui::GetStyle().ItemInnerSpacing.x);
    const LocalNumber number(language, "", "%.2f");
    if (ImGui::DragScalar("", ImGuiDataType_Double, values + i, 0.05f, &lo, &hi, number.format(),
                          ImGuiSliderFlags_AlwaysClamp)) {
      values[i] = number.shown(values[i]);
      changed = true;
    } else {
      number.shown(values[i]);
    }
    ImGui::PopID();
    ImGui::PopItemWidth();
  }
  ImGui::PopID();
  const char* label_end = ImGui::FindRenderedTextEnd(label);
  if (label != label_end) {
    ImGui::SameLine(0, ImGui::GetStyle().ItemInnerSpacing.x);
    ImGui::TextUnformatted(label, label_end);
  }
  ImGui::EndGroup();
  return changed;
}

// The target C's coordinates: side by side where each shows -10.00 whole, else (1024 px at 3×) the label
// above and one full-width field a line ("###target0", "###target1", ...).
bool target_fields(Language language, const PanelState& panels, double* values, int count) {
  const char* label = tr(language, "target C###target");
  const float needed = drag_doubles_width(count);
  if (ImGui::GetContentRegionAvail().x >= needed)
    return labelled(panels, label, [&](const char* l) { return drag_doubles(language, l, values, count); }, needed);
  wrapped_between_words(label_parts(label).shown);
  bool changed = false;
  for (int i = 0; i < count; ++i) {
    const std::string id = "###target" + std::to_string(i);
    ImGui::SetNextItemWidth(-FLT_MIN);
    changed |= drag_doubles(language, id.c_str(), values + i, 1);
    record_item_rect(panels, id);
    if (i == 0) record_item_rect(panels, "###target");
  }
  return changed;
}

// radians: the model's angle; lo_deg, hi_deg: the slider's range in degrees (degrees only on screen).
bool slider_degrees(Language language, const PanelState& panels, const char* label, double& radians, double lo_deg,
                    double hi_deg) {
  double degrees = glm::degrees(radians);
  if (lo_deg < 0) degrees = std::remainder(degrees, 360.0);  // show theta in [-180, 180]
  if (!slider_double(language, panels, label, degrees, lo_deg, hi_deg, "%.1f°")) return false;
  radians = glm::radians(degrees);
  return true;
}
}  // namespace

void camera_section(AppState& state, const PanelState& panels) {
  if (!section(tr(state.language, "Camera###camera"), tr(state.language, "Camera###camera"), ImGuiTreeNodeFlags_DefaultOpen)) return;
  int wanted = dimension(state);
  bool mode_changed = ImGui::RadioButton(tr(state.language, "2D camera"), &wanted, 2);
  same_line_if_fits(ImGui::GetFrameHeight() + ImGui::CalcTextSize(tr(state.language, "3D camera")).x);
  mode_changed |= ImGui::RadioButton(tr(state.language, "3D camera"), &wanted, 3);
  if (mode_changed) switch_dimension(state, wanted);

  const SharedOrbit<double> orbit = active_orbit(state);
  double &df = orbit.df, &d = orbit.d, &theta = orbit.theta;
  bool changed = false;
  {
    const LabelGroup column{tr(state.language, "d_f focal distance###df"), tr(state.language, "d distance to C###d"),
                            tr(state.language, "θ azimuth###theta"), tr(state.language, "φ polar angle###phi")};
    changed |= slider_double(state.language, panels, tr(state.language, "d_f focal distance###df"), df, kFocalRange.low, kFocalRange.high,
                             "%.3f", true);
    changed |= slider_double(state.language, panels, tr(state.language, "d distance to C###d"), d, kDistanceRange.low, kDistanceRange.high,
                             "%.2f", true);
    changed |= slider_degrees(state.language, panels, tr(state.language, "θ azimuth###theta"), theta, -180.0, 180.0);
    std::visit(overloaded{[](View2D&) {},  // the plane has no polar angle
                          [&](View3D& view) {
                            changed |= slider_degrees(state.language, panels, tr(state.language, "φ polar angle###phi"), view.orbit.phi,
                                                      glm::degrees(kPolarRange.low), glm::degrees(kPolarRange.high));
                          }},
               state.view);
  }
  const int max_size = active_max_side(state);
  // The handout's one or two resolution variables (two in 3D, "non-square" on).
  if (dimension(state) == 2 || !state.res_rows) {
    changed |= slider_double(state.language, panels, tr(state.language, "res resolution###res"), state.res, 1.0 / max_size, 1.0, "%.4f", true);
  } else {  // the handout's two resolution variables: nbc = round(res_c·W), nbl = round(res_l·H)
    changed |= slider_double(state.language, panels, tr(state.language, "res_c columns###res"), state.res, 1.0 / max_size, 1.0, "%.4f", true);
    changed |= slider_double(state.language, panels, tr(state.language, "res_l rows###res_rows"), *state.res_rows, 1.0 / max_size, 1.0, "%.4f",
                             true);
  }
  bool non_square = state.res_rows.has_value();
  if (dimension(state) == 3 && checkbox(tr(state.language, "non-square: res per side"), &non_square)) {
    state.res_rows = non_square ? std::optional<double>(state.res) : std::nullopt;
    changed = true;
  }
  // The target's coordinates are doubles in the widget too, as the sliders'.
  std::visit([&](auto& view) {
    changed |= target_fields(state.language, panels, glm::value_ptr(view.orbit.target), view.kDimension);
  }, state.view);
  std::visit(overloaded{[&](View2D& view) {
                          int n = view.max_pixels;
                          if (labelled(panels, tr(state.language, "N max pixels###N"),
                                       [&](const char* l) { return ImGui::InputInt(l, &n, 16, 256); })) {
                            view.max_pixels = std::clamp(n, 1, kMaxPixels2DInApp);
                            changed = true;
                          }
                        },
                        [&](View3D& view) {
                          int size[2] = {view.max_columns, view.max_rows};
                          if (labelled(panels, tr(state.language, "max size W, H###size"),
                                       [&](const char* l) { return ImGui::InputInt2(l, size); })) {
                            view.max_columns = std::clamp(size[0], 1, kMaxSideInApp);
                            view.max_rows = std::clamp(size[1], 1, kMaxSideInApp);
                            changed = true;
                          }
                        }},
             state.view);
  const double fov = std::visit([](const auto& view) { return view.camera.field_of_view(); }, state.view);
  ImGui::TextWrapped("%s", trf(state.language, "n = %d × %d, field of view %.1f°", state.map.width, state.map.height,
                               glm::degrees(fov)).c_str());
  if (button(tr(state.language, "Reset camera"))) reset_camera(state, state);  // the scene file's preset
  explain(tr(state.language, "drag in a view: orbit; wheel: d; shift+wheel: d_f; double-click an object: target"));
  show_message(state, panels, MessageSource::camera);
  if (changed) state.cameras_dirty = true;
}

}  // namespace raycam::ui
