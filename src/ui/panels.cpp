// Section index: camera · construction of M_d · ray inspector · classic mistakes · files · lecture ·
// status line · help · shortcuts. Every visible string goes through tr(state.language, )/trf(state.language, ) (text.h).
#include "ui/panels.h"

#include <imgui.h>
#include <imgui_internal.h>  // ImGui::ClearActiveID: Tab leaves a text field
#include <imgui_stdlib.h>    // InputText on a std::string: a path is never cut

#include <algorithm>
#include <initializer_list>
#include <array>
#include <cfloat>
#include <filesystem>
#include <cmath>
#include <cstdio>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/trigonometric.hpp>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "session/camera_ranges.h"
#include "session/construction_view.h"
#include "session/figure_export.h"
#include "ui/image_header.h"  // ellipsized
#include "session/shown_files.h"
#include "session/inspection.h"
#include "ui/local_numbers.h"
#include "session/mistake_lessons.h"
#include "raycam/image_files.h"
#include "raycam/view_setup.h"
#include "ui/words.h"
#include "ui/theme.h"

namespace raycam::ui {

using namespace session;  // the state the window shows and edits

namespace {
// A label's shown text and the id ImGui sees: "Save###save" gives "Save" and "###save"; a label with no id
// gives itself and "###" + itself, so the id stays the same whatever text a widget shows for it.
struct LabelParts {
  std::string shown, id;
};
LabelParts label_parts(const char* label) {
  const std::string text = label;
  const std::size_t hidden = text.find("##"), id = text.find("###");
  return {text.substr(0, hidden), id != std::string::npos ? text.substr(id) : "###" + text.substr(0, hidden)};
}

// `text` in lines no wider than `width`, broken between words only (at spaces and newlines): ImGui's own
// wrapping also breaks after '.' and ',', inside numbers ("67." / "4°"). A word wider than a whole line
// keeps a line of its own.
std::vector<std::string> lines_between_words(const std::string& text, float width) {
  std::vector<std::string> lines;
  std::string line;
  bool open = false;  // a line has started (it may be empty: a blank line)
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t end = std::min(text.find_first_of(" \n", at), text.size());
    const std::string word = text.substr(at, end - at);
    const std::string longer = open ? line + " " + word : word;
    if (open && !line.empty() && ImGui::CalcTextSize(longer.c_str()).x > width) {
      lines.push_back(line);
      line = word;
    } else {
      line = longer;
    }
    open = true;
    if (end < text.size() && text[end] == '\n') {
      lines.push_back(line);
      line.clear();
      open = false;
    }
    at = end + 1;
  }
  if (open) lines.push_back(line);
  return lines;
}


int g_tab_key = -1;  // the host's key index of Tab, taken away from ImGui (take_tab_key)

// Where the last item is, for the tests (panels.widget_rects is null in the app).
void record_item_rect(const PanelState& panels, const std::string& id) {
  if (!panels.widget_rects) return;
  const ImVec2 low = ImGui::GetItemRectMin(), high = ImGui::GetItemRectMax();
  (*panels.widget_rects)[id] = {low.x, low.y, high.x, high.y};
}

// The label beside the widget when both fit (the widget keeps at least `widget_min_width`), else on its own
// line above a full-width widget: a label is never cut, in any language at any font scale. `label` may carry
// an ImGui "###id" (kept either way).
// Sliders read as one column (the camera's) have their labels all beside or all above (QA at 2× on 1024×768:
// θ's short label sat beside its slider while the longer ones sat above theirs): while a LabelGroup lives,
// its widest label decides for each (each slider then keeps the room its own label leaves).
float g_group_label_width = 0.0f;
struct LabelGroup {
  explicit LabelGroup(std::initializer_list<const char*> labels) {
    for (const char* label : labels)
      g_group_label_width = std::max(g_group_label_width, ImGui::CalcTextSize(label_parts(label).shown.c_str()).x +
                                                              ImGui::GetStyle().ItemInnerSpacing.x);
  }
  ~LabelGroup() { g_group_label_width = 0.0f; }
  LabelGroup(const LabelGroup&) = delete;
  LabelGroup& operator=(const LabelGroup&) = delete;
};

template <class Widget>
bool labelled(const PanelState& panels, const char* label, Widget widget, float widget_min_width = 0.0f) {
  const LabelParts parts = label_parts(label);
  const std::string& shown = parts.shown;
  const std::string& id = parts.id;
  const float avail = ImGui::GetContentRegionAvail().x;
  const float label_width = ImGui::CalcTextSize(shown.c_str()).x + ImGui::GetStyle().ItemInnerSpacing.x;
  const float deciding_width = std::max(g_group_label_width, label_width);  // its group's widest
  bool changed = false;
  if (deciding_width <= avail * 0.45f && avail - deciding_width >= widget_min_width) {
    ImGui::SetNextItemWidth(avail - label_width);
    changed = widget((shown + id).c_str());  // the same id as above its widget
  } else {
    wrapped_between_words(shown);
    ImGui::SetNextItemWidth(avail);
    changed = widget(id.c_str());
  }
  record_item_rect(panels, id);
  return changed;
}

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

// Puts the next item on this line if `width` pixels still fit, else on the next line.
void same_line_if_fits(float width) {
  const float right = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + width;
  if (right <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) ImGui::SameLine();
}

// A value as printed with `decimals` decimals, never "-0.000": a value that rounds to zero prints as 0.
double without_negative_zero(double value, int decimals) {
  return std::abs(value) < 0.5 * std::pow(10.0, -decimals) ? 0.0 : value;
}

void explain(const char* text) {
  // French typography (the core's texts, e.g. the mistakes', are written with plain spaces).
  const std::string shown = with_no_break_spaces(text);
  ImGui::PushStyleColor(ImGuiCol_Text, current_theme().hint);
  wrapped_between_words(shown);
  ImGui::PopStyleColor();
}

// Columns [first, first + count) of an N×N matrix as a grid of its own, right-aligned, in the panel's font
// times `scale`, every cell exactly as wide as computed here (an ImGui table sizes its columns from an earlier
// frame's text, wider at another scale); `stretch`: the columns share the panel's width. Returns where the
// grid starts on screen (x, y), its font size (z) and its height (w). Past the panel's width (only at the
// smallest scale) it scrolls sideways in its own strip.
template <int N, class Matrix>
ImVec4 matrix_grid(Language language, const char* id, const Matrix& m, int first, int count, int decimals, float scale,
                   bool stretch) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float avail = ImGui::GetContentRegionAvail().x - 1;  // the right border
  const float padding = style.CellPadding.x;
  double widest = 0;
  for (int row = 0; row < N; ++row)
    for (int column = 0; column < N; ++column) widest = std::max(widest, std::abs(m[column][row]));
  const float font_size = ImGui::GetFontSize() * scale;
  const float widest_text = ImGui::CalcTextSize(formatted(language, "%.*f", decimals, -widest).c_str()).x;
  ImVec2 cell{widest_text * scale + 2 * padding, font_size + 2 * style.CellPadding.y};
  const ImVec2 size{count * cell.x + 1, N * cell.y + 1};
  const bool fits = size.x <= avail + 1;
  if (fits && stretch) cell.x = std::floor(avail / count);  // no empty strip at the right
  if (!fits) ImGui::BeginChild(id, {0, size.y + style.ScrollbarSize}, false, ImGuiWindowFlags_HorizontalScrollbar);
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const float width = count * cell.x;
  ImGui::Dummy({width + 1, size.y});  // the grid's place in the layout
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImU32 inner = ImGui::GetColorU32(ImGuiCol_TableBorderLight), outer = ImGui::GetColorU32(ImGuiCol_TableBorderStrong);
  for (int i = 1; i <= count; ++i)
    draw->AddLine({at.x + i * cell.x, at.y}, {at.x + i * cell.x, at.y + N * cell.y}, inner);
  for (int i = 1; i < N; ++i) draw->AddLine({at.x, at.y + i * cell.y}, {at.x + width, at.y + i * cell.y}, inner);
  draw->AddRect(at, {at.x + width, at.y + N * cell.y + 1}, outer);
  for (int row = 0; row < N; ++row)
    for (int i = 0; i < count; ++i) {
      const int column = first + i;
      // The window's language's decimal mark (French: 0,500).
      const std::string text = formatted(language, "%.*f", decimals, without_negative_zero(m[column][row], decimals));
      const float text_w = ImGui::CalcTextSize(text.c_str()).x * scale;  // GLM is column-major: m[column][row]
      draw->AddText(ImGui::GetFont(), font_size,
                    {at.x + (i + 1) * cell.x - padding - text_w, at.y + row * cell.y + style.CellPadding.y},
                    ImGui::GetColorU32(ImGuiCol_Text), text.c_str());
    }
  if (!fits) ImGui::EndChild();
  return {at.x, at.y, font_size, size.y};
}

// A matrix in the panel's font, with three decimals where the panel has room for every column, else two.
// Where its N columns do not fit side by side (a 4×4 at lecture sizes: the table was drawn at about half the
// panel's font), as many as fit go in a grid and the others in grids under it, each named by its columns,
// all in the panel's font; only where not even one column fits is the table drawn in a smaller font (down
// to kMinTableFontScale of the panel's). `panels`: the tests' hook, the font size drawn.
constexpr float kMinTableFontScale = 0.55f;
template <int N, class Matrix>
void matrix_table(Language language, const char* id, const Matrix& m, const PanelState* panels = nullptr) {
  const ImGuiStyle& style = ImGui::GetStyle();
  double widest = 0;
  for (int row = 0; row < N; ++row)
    for (int column = 0; column < N; ++column) widest = std::max(widest, std::abs(m[column][row]));
  const float avail = ImGui::GetContentRegionAvail().x - 1;  // the right border
  auto column_width = [&](int decimals) {  // the widest value's, the sign included, with its padding
    return ImGui::CalcTextSize(formatted(language, "%.*f", decimals, -widest).c_str()).x + 2 * style.CellPadding.x;
  };
  const int decimals = N * column_width(3) <= avail ? 3 : 2;
  ImVec4 drawn;
  // How many columns fit side by side at the panel's font.
  const int per_grid = std::min(N, int(avail / column_width(decimals)));
  if (per_grid >= 1) {
    drawn = matrix_grid<N>(language, id, m, 0, per_grid, decimals, 1.0f, true);
    for (int first = per_grid; first < N; first += per_grid) {  // the others under it, named
      const int count = std::min(per_grid, N - first);
      ImGui::TextDisabled("%s", count == 1 ? trf(language, "column %d:", first + 1).c_str()
                                           : trf(language, "columns %d to %d:", first + 1, first + count).c_str());
      matrix_grid<N>(language, (std::string(id) + "_" + std::to_string(first)).c_str(), m, first, count, decimals, 1.0f, true);
    }
  } else {
    const float scale =
        std::clamp((avail / N - 2 * style.CellPadding.x) / (column_width(decimals) - 2 * style.CellPadding.x),
                   kMinTableFontScale, 1.0f);
    drawn = matrix_grid<N>(language, id, m, 0, N, decimals, scale, true);
  }
  if (panels && panels->widget_rects)
    (*panels->widget_rects)[std::string("###matrix/") + id] = {drawn.x, drawn.y, drawn.x + drawn.z, drawn.y + drawn.w};
}

// The one "… already exists. Replace it?" of every export (Save as, Export colour map, Export figure): the
// files found when the user clicked (looked for once, not at every frame), Replace and Cancel under it, and
// scrolled into view in the frame it is asked (at 3× it fell below the panel's edge: the click seemed to do
// nothing). `id` names its buttons ("###ID_replace", "###ID_cancel").
enum class ReplaceAnswer { waiting, replace, cancel };
ReplaceAnswer replace_question(Language language, const PanelState& panels, const std::vector<std::string>& files,
                               const std::string& id, bool just_asked) {
  ImGui::PushStyleColor(ImGuiCol_Text, current_theme().error);
  ImGui::TextWrapped("%s", figure_replace_question(language, files).c_str());
  ImGui::PopStyleColor();
  ReplaceAnswer answer = ReplaceAnswer::waiting;
  if (button((tr(language, "Replace") + ("###" + id + "_replace")).c_str())) answer = ReplaceAnswer::replace;
  record_item_rect(panels, "###" + id + "_replace");
  same_line_if_fits(ImGui::CalcTextSize(tr(language, "Cancel")).x + 2 * ImGui::GetStyle().FramePadding.x);
  if (button((tr(language, "Cancel") + ("###" + id + "_cancel")).c_str())) answer = ReplaceAnswer::cancel;
  record_item_rect(panels, "###" + id + "_cancel");
  if (just_asked) ImGui::SetScrollHereY(1.0f);
  return answer;
}
}  // namespace

// A checkbox whose label wraps under itself when the line is too short for it (lecture sizes): the label
// is never cut. Clicking the label toggles too, as with ImGui's own checkbox.
// Text wrapped at the panel's edge between words; a word wider than the whole line wraps inside (rather
// than be cut).
void wrapped_between_words(const std::string& text) {
  const float width = ImGui::GetContentRegionAvail().x;
  for (const std::string& line : lines_between_words(text, width)) {
    if (ImGui::CalcTextSize(line.c_str()).x <= width) ImGui::TextUnformatted(line.c_str());
    else ImGui::TextWrapped("%s", line.c_str());
  }
}

bool checkbox(const char* label, bool* value) {
  const float box = ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x;
  if (box + ImGui::CalcTextSize(label, nullptr, true).x <= ImGui::GetContentRegionAvail().x)
    return ImGui::Checkbox(label, value);
  ImGui::PushID(label);
  bool changed = ImGui::Checkbox("##box", value);
  ImGui::PopID();
  ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
  ImGui::BeginGroup();  // the label's lines start beside the box, not under it
  wrapped_between_words(label_parts(label).shown);
  ImGui::EndGroup();
  if (ImGui::IsItemClicked()) {
    *value = !*value;
    changed = true;
  }
  return changed;
}

// A button whose label goes over several lines when it does not fit the panel's width (lecture sizes): a
// button's text is never cut. Its id stays the one of the label as given.
bool button(const char* label) {
  const LabelParts parts = label_parts(label);
  const float room = ImGui::GetContentRegionAvail().x - 2 * ImGui::GetStyle().FramePadding.x;
  std::string lines;
  for (const std::string& line : lines_between_words(parts.shown, room)) lines += (lines.empty() ? "" : "\n") + line;
  return ImGui::Button((lines + parts.id).c_str());
}


// A section header: the full title if it fits the panel's width, else the brief one (a header never wraps).
bool section(const char* full, const char* brief, int flags) {
  const std::string shown = label_parts(full).shown;
  const float room = ImGui::GetContentRegionAvail().x - ImGui::GetTreeNodeToLabelSpacing() -
                     ImGui::GetStyle().FramePadding.x;
  return ImGui::CollapsingHeader(ImGui::CalcTextSize(shown.c_str()).x <= room ? full : brief, flags);
}

// ---- camera --------------------------------------------------------------------------------------------
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

// ---- construction of M_d -------------------------------------------------------------------------------
namespace {
// M_d's factors and their product up to `step`, as the handout writes them in each dimension.
void placement_tables(AppState& state, PanelState& panels, const View2D& view, int step, int steps) {
  const Placement2D& p = view.camera.placement();
  ImGui::TextWrapped("%s", trf(state.language, "M_d = T(ΩP)·R(α)·H(1, d_f), α = φᵥ + ψ₀ = %.1f°", glm::degrees(p.alpha)).c_str());
  if (ImGui::TreeNode("H(1, d_f)")) { matrix_table<3>(state.language, "H", p.scale); ImGui::TreePop(); }
  if (ImGui::TreeNode("R(α)")) {
    matrix_table<3>(state.language, "R", p.rotation);
    ImGui::TreePop();
  }
  if (ImGui::TreeNode("T(ΩP)")) { matrix_table<3>(state.language, "T", p.translation); ImGui::TreePop(); }
  wrapped_between_words(step == steps ? std::string("M_d") : trf(state.language, "product of the first %d {{factor|factors}}", step));
  panels.shown_matrix = glm::dmat4(construction_step(p, step));
  matrix_table<3>(state.language, "M", construction_step(p, step), &panels);
}
void placement_tables(AppState& state, PanelState& panels, const View3D& view, int step, int steps) {
  if (step < steps)  // the last step is the placed camera itself, drawn as always (nothing in orange)
    explain(tr(state.language,
        "Drawn in orange in both views: the screen (its top edge green), the eye, and the axes image right "
        "(red), image up (green), view (blue)."));
  if (step >= 2) {  // the roll: why raycam's sign differs from the handout's
    explain(tr(state.language,
        "Why ψ₀ = +π/2: after Ry(φ)·Rz(ψ₀) the image's up R·(0, 1, 0) must have z > 0. With +π/2 it is "
        "(−cos θ cos φ, −sin θ cos φ, sin φ), and sin φ > 0. The handout prints −π/2, the opposite vector: "
        "world up points down and the image is upside down."));
    if (checkbox(tr(state.language, "show the handout's ψ₀ = −π/2"), &state.mistakes.upside_down))
      state.cameras_dirty = true;
  }
  const Placement3D& p = view.camera.placement();
  ImGui::TextWrapped("M_d = T(ΩP)·Rz(θ)·Ry(φ)·Rz(ψ₀)·H(1, 1, d_f)");
  if (ImGui::TreeNode("H(1, 1, d_f)")) { matrix_table<4>(state.language, "H", p.scale); ImGui::TreePop(); }
  if (ImGui::TreeNode("Rz(ψ₀ = 90°)")) {
    matrix_table<4>(state.language, "Roll", p.roll);
    ImGui::TreePop();
  }
  if (ImGui::TreeNode("Ry(φ)")) {
    matrix_table<4>(state.language, "Ry", p.polar);
    ImGui::TreePop();
  }
  if (ImGui::TreeNode("Rz(θ)")) {
    matrix_table<4>(state.language, "Rz", p.azimuth);
    ImGui::TreePop();
  }
  if (ImGui::TreeNode("T(ΩP)")) { matrix_table<4>(state.language, "T", p.translation); ImGui::TreePop(); }
  wrapped_between_words(step == steps ? std::string("M_d") : trf(state.language, "product of the first %d {{factor|factors}}", step));
  panels.shown_matrix = construction_step(p, step);
  matrix_table<4>(state.language, "M", construction_step(p, step), &panels);
}
}  // namespace

// The course figures of this camera (raycam-cli figure): the step shown, or every step, in the format, with
// the rays and the matrix chosen here; existing files are replaced only after asking, as Save as does.
void export_figure_now(AppState& state, const PanelState& panels, bool all) {
  try {
    const std::vector<std::string> files = export_construction_figure(state, panels.figure, panels.figure_path, all);
    if (state.host.files_are_downloads && files.size() > 1) {  // the page: one download, an archive
      const std::string archive = as_one_download(files, named_after_scene(state, "-steps.zip"));
      set_message(state, MessageSource::construction, false,
                  trf(state.language, "asked the browser to save %s (%d {{figure|figures}})",
                      shown_file_name(state.host, archive).c_str(), int(files.size())));
    } else if (state.host.files_are_downloads) {
      set_message(state, MessageSource::construction, false, written_message(state.host, state.language, files.front()));
    } else {
      set_message(state, MessageSource::construction, false, figure_files_message(state.language, files));
    }
  } catch (const std::exception& error) {
    set_message(state, MessageSource::construction, true, tr_reason(state.language, error.what()));
  }
}

void figure_export_row(AppState& state, PanelState& panels) {
  const bool downloads = state.host.files_are_downloads;
  if (!state.host.cairo_figures) panels.figure_format = kTikzFigureFormat;  // the one format without cairo
  if (downloads)  // named after the scene, as the other downloads
    panels.figure_path = named_after_scene(state, std::string("-figure") + kFigureExtensions[panels.figure_format]);
  // A name edited while the question shows: the question was about other files.
  else if (labelled(panels, tr(state.language, "figure###figure_path"), [&](const char* l) { return ImGui::InputText(l, &panels.figure_path); }))
    panels.figure_replace_pending = 0;
  static const char* const kFormats[] = {"SVG", "PDF", "PNG", "TikZ"};  // figure_export.h's order
  if (figure_format_of(panels.figure_path) >= 0) panels.figure_format = figure_format_of(panels.figure_path);
  if (!state.host.cairo_figures)
    explain(tr(state.language, "TikZ (.tex, for LaTeX) only: SVG, PDF and PNG need the desktop app (drawn by cairo)."));
  else if (labelled(panels, tr(state.language, "format###figure_format"),
                    [&](const char* l) { return ImGui::Combo(l, &panels.figure_format, kFormats, 4); })) {
    panels.figure_path = with_figure_extension(panels.figure_path, panels.figure_format);
    panels.figure_replace_pending = 0;
  }
  if (dimension(state) == 2)  // the 3D steps draw no rays: a slider there would change nothing
    labelled(panels, tr(state.language, "rays###figure_rays"),
             [&](const char* l) { return ImGui::SliderInt(l, &panels.figure.rays, 0, 64); });
  checkbox(tr(state.language, "matrix###figure_matrix"), &panels.figure.matrix);
  int asked = button(tr(state.language, "Export figure…")) ? 1 : 0;
  record_item_rect(panels, "###figure_export");
  same_line_if_fits(ImGui::CalcTextSize(tr(state.language, "Export every step")).x + 2 * ImGui::GetStyle().FramePadding.x);
  if (button(tr(state.language, "Export every step"))) asked = 2;
  record_item_rect(panels, "###figure_export_all");
  if (asked != 0) {
    panels.figure_path = with_figure_extension(panels.figure_path, panels.figure_format);
    panels.figure_replace_pending = 0;
    try {
      // Found once, here: the question below is drawn every frame from this list (drawing the figure again
      // each frame to find them cost a whole figure build per frame, and threw on a name edited meanwhile).
      // A download replaces nothing: the browser keeps both.
      panels.figure_replace_files =
          downloads ? std::vector<std::string>{} : existing_figure_files(state, panels.figure, panels.figure_path, asked == 2);
      if (panels.figure_replace_files.empty())
        export_figure_now(state, panels, asked == 2);
      else
        panels.figure_replace_pending = asked;
    } catch (const std::exception& error) {
      set_message(state, MessageSource::construction, true, tr_reason(state.language, error.what()));
    }
  }
  const bool just_asked = asked != 0 && panels.figure_replace_pending != 0;
  if (panels.figure_replace_pending != 0) {  // asked before replacing, as every export
    // The question replaces the last export's "wrote …": beside "… already exists. Replace it?" (here or at
    // the panel's foot at lecture sizes) it read as done.
    if (state.message_source == MessageSource::construction) state.message.clear();
    const bool all = panels.figure_replace_pending == 2;
    const std::vector<std::string> asked_about =
        panels.figure_replace_files.empty() ? std::vector<std::string>{panels.figure_path} : panels.figure_replace_files;
    const ReplaceAnswer answer = replace_question(state.language, panels, asked_about, "figure", just_asked);
    if (answer != ReplaceAnswer::waiting) panels.figure_replace_pending = 0;
    if (answer == ReplaceAnswer::replace) export_figure_now(state, panels, all);
  }
  show_message(state, panels, MessageSource::construction);  // right under the buttons, where the eye is
  explain(tr(state.language, "The step shown or every step: the camera and its screen after each factor of M_d, one "
                           "figure a step, for a handout or slides."));
}

void construction_section(AppState& state, PanelState& panels) {
  if (!section(tr(state.language, "Construction of M_d###construction"), "M_d###construction", ImGuiTreeNodeFlags_DefaultOpen))
    return;
  const int steps = construction_steps(state);
  int step = state.construction_step < 0 ? steps : state.construction_step;
  if (labelled(panels, tr(state.language, "step###step"), [&](const char* l) { return ImGui::SliderInt(l, &step, 0, steps, "%d"); }))
    state.construction_step = step == steps ? -1 : step;
  explain(tr(state.language, construction_caption(dimension(state), step)));
  std::visit([&](const auto& view) { placement_tables(state, panels, view, step, steps); }, state.view);
  figure_export_row(state, panels);
}

// ---- ray inspector -------------------------------------------------------------------------------------
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

// ---- classic mistakes ----------------------------------------------------------------------------------
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

// ---- caster and accuracy -------------------------------------------------------------------------------
namespace {
// What a combo shows of its choice: the whole name where it fits the combo, else the name without its
// parenthesis ("stable (Ray Tracing Gems)" → "stable"), else that cut with "…" (its list shows every name
// whole). Recorded for the tests as "<id>/preview", its width in x1.
std::string combo_preview(const PanelState& panels, const std::string& id, const char* name) {
  const float room = ImGui::CalcItemWidth() - ImGui::GetFrameHeight() - 2 * ImGui::GetStyle().FramePadding.x;
  const std::string whole = name;
  const std::string shown = ImGui::CalcTextSize(name).x <= room ? whole : ellipsized(whole.substr(0, whole.find(" (")), room);
  if (panels.widget_rects) (*panels.widget_rects)[id + "/preview"] = {0, 0, ImGui::CalcTextSize(shown.c_str()).x, 0};
  return shown;
}

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
}  // namespace

void caster_section(AppState& state, const PanelState& panels) {
  if (!section(tr(state.language, "Caster and accuracy###caster"), tr(state.language, "Caster###caster"),
                               uses_reference_caster(state) ? ImGuiTreeNodeFlags_DefaultOpen : 0))
    return;
  static constexpr std::pair<Scalar, const char*> kScalars[] = {{Scalar::float32, tr_later("float")},
                                                                {Scalar::float64, tr_later("double")},
                                                                {Scalar::extended, tr_later("long double")}};
  static constexpr std::pair<IntersectFormula, const char*> kFormulas[] = {
      {IntersectFormula::stable, tr_later("stable (Ray Tracing Gems)")},
      {IntersectFormula::naive, tr_later("naive (b² − c)")}};
  static constexpr std::pair<int, const char*> kSamples[] = {{1, "1"}, {4, "4"}, {16, "16"}, {64, "64"}};
  ReferenceOptions& knobs = state.accuracy.options;
  static const auto kMethods = [] {  // the core's list and names
    std::array<std::pair<CastMethod, const char*>, std::size(kCastMethods)> methods;
    for (std::size_t i = 0; i < methods.size(); ++i) methods[i] = {kCastMethods[i], cast_method_name(kCastMethods[i])};
    return methods;
  }();
  bool changed = choice(state.language, panels, tr(state.language, "method###method"), state.cast_options.method, kMethods);
  explain(
      tr(state.language, "Every method gives the plain loop's image; the faster ones skip objects behind the screen or out "
         "of view and test each object only on the pixels its projection can cover. The status line's "
         "tooltip shows the work done and skipped."));
  changed |= choice(state.language, panels, tr(state.language, "precision###precision"), knobs.scalar, kScalars);
  changed |= choice(state.language, panels, tr(state.language, "intersection###intersection"), knobs.formula, kFormulas);
  changed |= choice(state.language, panels, tr(state.language, "samples per pixel###spp"), knobs.samples_per_pixel, kSamples);
  changed |= checkbox(tr(state.language, "camera-relative rays"), &knobs.camera_relative);
  if (exact_bar_applies(state.view))
    changed |= checkbox(tr(state.language, "exact bar (area-weighted)"), &state.accuracy.exact);
  explain(uses_reference_caster(state)
              ? tr(state.language, "These knobs use the reference caster: slower, and the method above is not used. For "
                   "the handout's image keep double, stable, 1 sample; float needs the stable formula and "
                   "camera-relative rays.")
              : tr(state.language, "double, 1 sample, world coordinates: the fast caster."));
  show_message(state, panels, MessageSource::caster);
  if (changed) state.cameras_dirty = true;
}

// ---- files ---------------------------------------------------------------------------------------------
void files_section(AppState& state, PanelState& panels) {
  // The question "replace?" opens the section; a message does not (it shows at the panel's foot while
  // the section is closed), so the section can be closed while a message shows.
  if (!panels.overwrite_pending.empty() || !panels.colour_map_replace_files.empty()) ImGui::SetNextItemOpen(true);
  const bool open_section = section(tr(state.language, "Scene file###files"), tr(state.language, "Files###files"));
  record_item_rect(panels, "###files");
  if (!open_section) return;
  // Open and Save as have their own boxes: saving never goes to the opened file unless the user types it.
  const auto path_box = [&](const char* label, std::string& path) {
    return labelled(panels, label, [&](const char* l) {
      return ImGui::InputText(l, &path, ImGuiInputTextFlags_EnterReturnsTrue);
    });
  };
  const bool downloads = state.host.files_are_downloads;
  if (state.host.picks_files) {  // the page: the browser's file picker, or a file dropped on the page
    if (button(tr(state.language, "Open a scene file…###files_open"))) state.requests.ask(HostRequestKind::pick_scene_file);
    record_item_rect(panels, "###files_open");
    explain(tr(state.language, "or drop a scene file on the page"));
  } else {
    bool open = path_box(tr(state.language, "open###open_path"), panels.path_input);
    open |= button(tr(state.language, "Open"));
    if (open && open_scene(state, panels.path_input)) follow_scene_shown(state, panels);
    explain(tr(state.language, "or drop a scene file on the window"));
  }
  bool save = false;
  if (downloads) {  // a download named after the scene; the browser asks where, if it is set to
    const std::string name = named_after_scene(state, ".json");
    if (button(trf(state.language, "Download the camera preset (%s)###save_download", name.c_str()).c_str()))
      save_as(state, panels, name, true);
    record_item_rect(panels, "###save_download");
  } else {
    save = path_box(tr(state.language, "save as###save_path"), panels.save_path);
    save |= button(tr(state.language, "Save camera preset as…"));
    if (save) save_as(state, panels, panels.save_path, false);
  }
  if (!panels.overwrite_pending.empty()) {  // asked before replacing a file
    const ReplaceAnswer answer =
        replace_question(state.language, panels, {panels.overwrite_pending}, "save_as", save && !downloads);
    if (answer == ReplaceAnswer::replace) save_as(state, panels, panels.overwrite_pending, true);
    if (answer == ReplaceAnswer::cancel) panels.overwrite_pending.clear();
  }
  // A name edited while the question shows: the question was about another file.
  if (!downloads && labelled(panels, tr(state.language, "export###export"),
                             [&](const char* l) { return ImGui::InputText(l, &panels.export_path); }))
    panels.colour_map_replace_files.clear();
  const std::string export_path = downloads ? named_after_scene(state, "-colour-map.png") : panels.export_path;
  const bool export_png = button(tr(state.language, "Export colour map PNG"));
  record_item_rect(panels, "###export_png");
  if (export_png) export_colour_map(state, panels, export_path, false);
  if (!panels.colour_map_replace_files.empty()) {
    const ReplaceAnswer answer =
        replace_question(state.language, panels, panels.colour_map_replace_files, "colour_map", export_png);
    if (answer == ReplaceAnswer::replace) export_colour_map(state, panels, panels.colour_map_replace_files.front(), true);
    if (answer == ReplaceAnswer::cancel) panels.colour_map_replace_files.clear();
  }
  same_line_if_fits(ImGui::CalcTextSize(tr(state.language, "Screenshot (F12)")).x + 2 * ImGui::GetStyle().FramePadding.x);
  if (button(tr(state.language, "Screenshot (F12)"))) request_screenshot(state, state.language);
  // The window as a video while the user works (the course page's), stopped by the same button, F9 or the
  // status line's sign.
  if (button(tr(state.language, state.recording ? "Stop recording (F9)###record" : "Record a video (F9)###record")))
    state.requests.ask(HostRequestKind::toggle_recording);
  record_item_rect(panels, "###record");
  show_message(state, panels, MessageSource::files);
}

// ---- lecture -------------------------------------------------------------------------------------------
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

// ---- messages ------------------------------------------------------------------------------------------
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

// ---- status line ---------------------------------------------------------------------------------------
namespace {
// With the panel hidden: its button, then the message on one line (cut with "…", whole under the mouse)
// and its Dismiss, in place of the timings. Returns whether the message took the line.
bool hidden_panel_line(AppState& state, const PanelState& panels) {
  if (ImGui::SmallButton(tr(state.language, "Panel (P)###show_panel"))) state.panel_hidden = false;  // the line's height
  record_item_rect(panels, "###show_panel");
  if (state.message.empty()) {
    ImGui::SameLine();
    return false;
  }
  const char* dismiss = tr(state.language, "Dismiss###dismiss_message");
  const float dismiss_w = ImGui::CalcTextSize(dismiss, nullptr, true).x + 2 * ImGui::GetStyle().FramePadding.x;
  ImGui::SameLine();
  const float room = ImGui::GetContentRegionAvail().x - dismiss_w - ImGui::GetStyle().ItemSpacing.x;
  const ThemeColours& theme = current_theme();
  ImGui::PushStyleColor(ImGuiCol_Text, state.message_is_error ? theme.error : theme.confirmation);
  ImGui::TextUnformatted(ellipsized(state.message, room).c_str());
  ImGui::PopStyleColor();
  record_item_rect(panels, "###message/status");
  if (ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(0.6f * ImGui::GetIO().DisplaySize.x);
    ImGui::TextUnformatted(state.message.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
  ImGui::SameLine();
  if (ImGui::SmallButton(dismiss)) state.message.clear();
  return true;
}

// While the window records: a red sign with the time recorded, first on the status line (seen with the
// panel hidden too), and a click on it stops.
void recording_sign(AppState& state, const PanelState& panels) {
  if (!state.recording) return;
  const ThemeColours& theme = current_theme();
  const int seconds = int(state.recording_seconds);
  ImGui::PushStyleColor(ImGuiCol_Button, theme.error);
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 1, 1, 1));
  std::string label = trf(state.language, "REC %d:%02d (F9 stops)###recording_sign", seconds / 60, seconds % 60);
  // At lecture sizes the sign alone leaves the line its room for the message or the times.
  if (ImGui::CalcTextSize(label.c_str(), nullptr, true).x > 0.3f * ImGui::GetContentRegionAvail().x)
    label = trf(state.language, "REC %d:%02d###recording_sign", seconds / 60, seconds % 60);
  if (ImGui::SmallButton(label.c_str())) state.requests.ask(HostRequestKind::toggle_recording);
  ImGui::PopStyleColor(2);
  record_item_rect(panels, "###recording_sign");
  ImGui::SameLine();
}
}  // namespace

void status_line(AppState& state, const PanelState& panels) {
  recording_sign(state, panels);
  if (state.panel_hidden && hidden_panel_line(state, panels)) return;
  float room = ImGui::GetContentRegionAvail().x;
  // The page's file picker, at the line's right end in the app's font and language: the browser's own
  // button stays small, and covered the line's text at 1.5× and 2×.
  // Shortened where the line's shortest text and it would not fit (1024 px at 3×, in French).
  const bool picker = state.host.picks_files;
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  const char* open_label = tr(state.language, "Open a scene file…###open_scene_file");
  float open_width = 0.0f;
  if (picker) {
    // A text's height (no vertical padding): the line keeps the desktop's height, so the page's layout is
    // the desktop's.
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(ImGui::GetStyle().FramePadding.x, 0.0f));
    const auto width_of = [](const char* label) {
      return ImGui::CalcTextSize(label, nullptr, true).x + 2 * ImGui::GetStyle().FramePadding.x;
    };
    if (ImGui::CalcTextSize(trf(state.language, "%.0f ms · %.1f ms", state.frame_ms, state.cast_ms).c_str()).x + spacing +
            width_of(open_label) > room)
      open_label = tr(state.language, "Open…###open_scene_file");
    open_width = width_of(open_label);
    room -= open_width + spacing;
  }
  const char* caster = tr(state.language, uses_reference_caster(state) ? tr_later("reference caster")
                                                       : cast_method_name(state.cast_options.method));
  const std::string line = status_timing_line(state.language, state.frame_ms, state.cast_ms, caster, state.refine_pending, room);
  ImGui::TextUnformatted(line.c_str());
  record_item_rect(panels, "###status_text");
  if (ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    // Wrapped within the window (at 3× on 1024 px its lines ran past the right edge); the times first, named.
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 0.6f * ImGui::GetIO().DisplaySize.x);
    ImGui::TextUnformatted(trf(state.language, "frame %.1f ms · cast %.2f ms", state.frame_ms, state.cast_ms).c_str());
    status_counters(state);
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
  if (picker) {
    const float text_end = ImGui::GetItemRectMax().x - ImGui::GetWindowPos().x;
    ImGui::SameLine(std::max(text_end + spacing, ImGui::GetWindowContentRegionMax().x - open_width));
    if (ImGui::Button(open_label)) state.requests.ask(HostRequestKind::pick_scene_file);
    record_item_rect(panels, "###open_scene_file");
    ImGui::PopStyleVar();
  }
}

std::string status_timing_line(Language language, double frame_ms, double cast_ms, const char* caster, bool coarse,
                               float room) {
  // Short enough for 1280 px at 3× font; the work counters are in the tooltip.
  std::string line = trf(language, "frame %.1f ms · cast %.2f ms (%s)", frame_ms, cast_ms, caster);
  if (coarse) line += std::string(" · ") + tr(language, "coarse preview while dragging");
  // Shorter and shorter until it fits; the frame time stays in the shortest too (1024 px at 3× showed the
  // cast's time alone, nothing of what the window costs).
  for (const std::string& shorter : {trf(language, "frame %.1f ms · cast %.2f ms", frame_ms, cast_ms),
                                     trf(language, "frame %.0f · cast %.1f ms", frame_ms, cast_ms),
                                     trf(language, "%.0f ms · %.1f ms", frame_ms, cast_ms)})
    if (ImGui::CalcTextSize(line.c_str()).x > room) line = shorter;
  return line;
}

void status_counters(const AppState& state) {
  // Work skipped, against what the handout's plain loop would do (every object for every pixel).
  const char* caster = tr(state.language, uses_reference_caster(state) ? tr_later("reference caster")
                                                       : cast_method_name(state.cast_options.method));
  const CastStats& w = state.stats;
  const double objects = double(active_object_count(state));
  const double plain_tests = double(w.rays) * objects;
  ImGui::TextUnformatted(trf(state.language, "caster: %s", caster).c_str());
  ImGui::TextUnformatted(trf(state.language, "%lld {{cast|casts}} in %lld {{frame|frames}}", state.cast_count, state.frame_count).c_str());
  ImGui::TextUnformatted(trf(state.language, "rays %lld, %lld {{pixel|pixels}} skipped", w.rays, w.pixels_skipped).c_str());
  ImGui::TextUnformatted(trf(state.language, "intersection tests %lld (%.1f%% of the plain loop)", w.intersection_tests,
                             plain_tests > 0 ? 100.0 * double(w.intersection_tests) / plain_tests : 0.0)
                             .c_str());
  ImGui::TextUnformatted(trf(state.language, "objects culled %lld", w.objects_culled).c_str());
}

// ---- help ----------------------------------------------------------------------------------------------
void help_overlay(Display& shown, Language language) {
  if (!shown.show_help) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos({display.x * 0.5f, display.y * 0.5f}, ImGuiCond_Always, {0.5f, 0.5f});
  // Never wider or taller than the window at any font scale: the descriptions wrap, the list scrolls.
  ImGui::SetNextWindowSize({std::min(display.x * 0.95f, 42.0f * ImGui::GetFontSize()), 0.0f}, ImGuiCond_Always);
  ImGui::SetNextWindowSizeConstraints({0.0f, 0.0f}, {display.x * 0.95f, display.y * 0.95f});
  if (ImGui::Begin(tr(language, "Keyboard and mouse (F1 closes)###help"), &shown.show_help,
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    // {key, what it does}: two columns, so that the translation never breaks an alignment made of spaces.
    static const std::pair<const char*, const char*> kLines[] = {
        {tr_later("F1"), tr_later("this help")},
        {tr_later("F11"), tr_later("fullscreen")},
        {tr_later("F12"), tr_later("numbered screenshot (raycam-screenshot-NNN.png)")},
        {tr_later("F9"), tr_later("record the window as a video, F9 again stops (SCENE-recording-NNN.mp4; the page: a WebM download)")},
        {tr_later("← / →"), tr_later("θ −/+ 5°")},
        {tr_later("↑ / ↓"), tr_later("φ −/+ 5° (3D)")},
        {tr_later("+ / −"), tr_later("d closer / further")},
        {tr_later("PgUp / PgDn"), tr_later("d_f larger / smaller")},
        {tr_later("[ / ]"), tr_later("construction step back / forward")},
        {tr_later("Tab"), tr_later("2D / 3D")},
        {tr_later("F"), tr_later("fit the overhead view to the scene and the camera")},
        {tr_later("P"), tr_later("hide / show the panel: the views take its room")},
        {tr_later("1 / 2 / 3"), tr_later("the image / overhead / observer view fills the views' room; again: back (or double-click its title)")},
        {tr_later("Esc"), tr_later("leave a text field; else unpin the inspected pixel")},
        {tr_later("mouse drag"), tr_later("orbit the camera (overhead: around the target)")},
        {tr_later("wheel"), tr_later("d;  shift+wheel: d_f;  ctrl+wheel (observer): zoom")},
        {tr_later("right drag"), tr_later("turn the observer (3D)")},
        {tr_later("double-click"), tr_later("make an object the target")},
        {tr_later("click a pixel"), tr_later("pin the ray inspector")}};
    if (ImGui::BeginTable("##keys", 2, ImGuiTableFlags_SizingStretchProp)) {
      ImGui::TableSetupColumn("##key", ImGuiTableColumnFlags_WidthFixed);
      ImGui::TableSetupColumn("##what", ImGuiTableColumnFlags_WidthStretch);
      for (const auto& [key, what] : kLines) {
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(tr(language, key));
        ImGui::TableNextColumn();
        ImGui::TextWrapped("%s", tr(language, what));
      }
      ImGui::EndTable();
    }
  }
  ImGui::End();
}

// ---- shortcuts -----------------------------------------------------------------------------------------
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
