// The help window (F1): every key and mouse gesture, and what it does.
#include "ui/panels.h"

#include <imgui.h>

#include <algorithm>
#include <utility>

#include "ui/words.h"

namespace raycam::ui {

using namespace session;  // the state the window shows and edits

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

}  // namespace raycam::ui
