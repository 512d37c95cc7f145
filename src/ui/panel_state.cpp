#include "panel_state.h"

#include "text.h"

namespace raycam::ui {

using namespace session;

PanelState panel_state_for(const AppOptions& options, const Lesson& lesson) {
  PanelState panels;
  panels.check_command = options.check_command;
  panels.path_input = scene_path(lesson);
  panels.scene_opens_seen = lesson.scene_opens;
  // The colour map's default file name in the window's language too.
  panels.export_path = tr(lesson.language, "raycam-colour-map.png");
  return panels;
}

void follow_opened_scene(const Lesson& lesson, PanelState& panels) {
  if (panels.scene_opens_seen == lesson.scene_opens) return;
  panels.scene_opens_seen = lesson.scene_opens;
  panels.path_input = scene_path(lesson);
  panels.save_path.clear();  // Save as starts empty: never the file just opened unless the user types it
  panels.overwrite_pending.clear();
}

bool save_as(AppState& state, PanelState& panels, const std::string& path, bool overwrite) {
  // `path` may be panels.overwrite_pending itself (the Replace button): read before it is cleared.
  const std::string asked = path;
  panels.overwrite_pending.clear();
  const SaveAsOutcome outcome = save_preset_as(state, asked, overwrite);
  if (outcome == SaveAsOutcome::needs_yes) panels.overwrite_pending = asked;  // the panel asks
  return outcome == SaveAsOutcome::saved;
}

}  // namespace raycam::ui
