// The panel's "Scene file" section: open a scene, save the camera preset, export the colour map, screenshot,
// record a video (on the page: the file picker and downloads).
#include "ui/panels.h"

#include <imgui.h>
#include <imgui_stdlib.h>  // InputText on a std::string: a path is never cut

#include <string>

#include "session/shown_files.h"
#include "ui/panel_widgets.h"

namespace raycam::ui {

using namespace session;  // the state the window shows and edits

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

}  // namespace raycam::ui
