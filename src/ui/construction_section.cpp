// The panel's "Construction of M_d" section: the step slider, M_d's factors and their product as tables,
// and the row that exports the construction's figures.
#include "ui/panels.h"

#include <imgui.h>
#include <imgui_stdlib.h>  // InputText on a std::string: a path is never cut

#include <algorithm>
#include <cmath>
#include <glm/trigonometric.hpp>
#include <string>
#include <vector>

#include "session/construction_view.h"
#include "session/figure_export.h"
#include "session/shown_files.h"
#include "ui/panel_widgets.h"

namespace raycam::ui {

using namespace session;  // the state the window shows and edits

namespace {
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

}  // namespace raycam::ui
