#include "ui/panel_state.h"

#include <filesystem>
#include <system_error>

#include "raycam/image_files.h"
#include "session/shown_files.h"
#include "ui/words.h"

namespace raycam::ui {

using namespace session;

PanelState panel_state_for(const AppOptions& options, const Lesson& lesson) {
  PanelState panels;
  panels.check_command = options.check_command;
  panels.path_input = scene_path(lesson);
  // A scene file that could not be opened (the demo shows, with the error): its path stays in the box, to be
  // fixed in place as a typed one is.
  if (panels.path_input.empty() && options.view.scene_path) panels.path_input = *options.view.scene_path;
  panels.scene_opens_seen = lesson.scene_opens;
  panels.dimension_seen = dimension(lesson);
  // The exports' default file names, after the scene, in the window's language.
  follow_default_names(lesson, panels);
  return panels;
}

void follow_default_names(const Lesson& lesson, PanelState& panels) {
  const std::string map = default_export_name(lesson, ExportKind::colour_map);
  if (map != panels.export_default) {
    if (panels.export_path == panels.export_default) {  // never typed over: the new default
      panels.export_path = map;
      panels.colour_map_replace_files.clear();  // the question was about the other name
    }
    panels.export_default = map;
  }
  const std::string figure = default_export_name(lesson, ExportKind::figure);  // .svg: compared whatever the format
  if (figure != panels.figure_default) {
    if (panels.figure_path.empty() || with_figure_extension(panels.figure_path, 0) == panels.figure_default)
      panels.figure_path = with_figure_extension(figure, panels.figure_format);
    panels.figure_default = figure;
  }
}

bool export_colour_map(AppState& state, PanelState& panels, const std::string& path, bool overwrite) {
  const std::string asked = path;  // `path` may be the question's own string (the Replace button)
  panels.colour_map_replace_files.clear();
  // The whole path, as the screenshot and the figure exports name it (a relative name says nothing of where).
  const std::string whole = std::filesystem::absolute(asked).lexically_normal().string();
  std::error_code ignored;
  if (!overwrite && !state.host.files_are_downloads && std::filesystem::exists(asked, ignored)) {
    panels.colour_map_replace_files = {whole};
    // No "wrote …" beside the question (it read as done).
    if (state.message_source == MessageSource::files) state.message.clear();
    return false;
  }
  try {
    write_png(state.map, asked, 1, image_is_bar(state.view) ? 32 : 1);
    set_message(state, MessageSource::files, false, written_message(state.host, state.language, whole));
    return true;
  } catch (const std::exception& error) {
    set_message(state, MessageSource::files, true, with_file_shown(state.host, tr_reason(state.language, error.what()), asked));
    return false;
  }
}

void follow_scene_shown(const Lesson& lesson, PanelState& panels) {
  const int shown_dimension = dimension(lesson);
  const bool opened = panels.scene_opens_seen != lesson.scene_opens;
  const bool switched = panels.dimension_seen != shown_dimension;
  panels.scene_opens_seen = lesson.scene_opens;
  panels.dimension_seen = shown_dimension;
  if (!opened && !switched) return;
  // Both questions were about the scene that was on screen: Replace must never write another scene's camera
  // (Save as) or other files than it named (Export figure: 2D frames a … d, 3D steps 0 … 5).
  panels.overwrite_pending.clear();
  panels.colour_map_replace_files.clear();
  panels.figure_replace_pending = 0;
  panels.figure_replace_files.clear();
  panels.path_input = scene_path(lesson);  // the file on screen (empty: the demo)
  if (opened) panels.save_path.clear();  // Save as starts empty: never the file just opened unless typed
}

bool save_as(AppState& state, PanelState& panels, const std::string& path, bool overwrite) {
  // `path` may be panels.overwrite_pending itself (the Replace button): read before it is cleared.
  const std::string asked = path;
  panels.overwrite_pending.clear();
  const SaveAsOutcome outcome = save_preset_as(state, asked, overwrite);
  if (outcome == SaveAsOutcome::needs_yes) {  // the panel asks
    panels.overwrite_pending = asked;
    // An earlier "saved the camera preset to …" beside "… already exists. Replace it?" read as done, and
    // stayed after Cancel as if it had saved.
    if (state.message_source == MessageSource::files) state.message.clear();
  }
  return outcome == SaveAsOutcome::saved;
}

}  // namespace raycam::ui
