// The status line under the views: the frame's and the cast's times (the work counters in its tooltip), the
// recording sign, the page's "Open a scene file…", and with the panel hidden its button and the message.
#include "ui/panels.h"

#include <imgui.h>

#include <algorithm>
#include <string>

#include "ui/image_header.h"  // ellipsized
#include "ui/panel_widgets.h"
#include "ui/theme.h"

namespace raycam::ui {

using namespace session;  // the state the window shows and edits

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

}  // namespace raycam::ui
