#include "panel_state.h"

#include "text.h"

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
  // The colour map's default file name in the window's language too.
  panels.export_path = tr(lesson.language, "raycam-colour-map.png");
  panels.language_seen = lesson.language;
  return panels;
}

void follow_language(const Lesson& lesson, PanelState& panels) {
  if (panels.language_seen == lesson.language) return;
  if (panels.export_path == tr(panels.language_seen, "raycam-colour-map.png"))
    panels.export_path = tr(lesson.language, "raycam-colour-map.png");
  panels.language_seen = lesson.language;
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
