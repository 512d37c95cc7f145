// The control panel's sections, one function each, as functions of the app state (Dear ImGui style:
// widgets report "changed", and only then is anything recomputed).
#pragma once

#include "app_state.h"

namespace raycam::ui {

void camera_section(AppState& state);
void construction_section(AppState& state);
void inspector_section(const AppState& state);
void mistakes_section(AppState& state);
void caster_section(AppState& state);
void files_section(AppState& state);
void lecture_section(AppState& state);
void status_line(const AppState& state);
void help_overlay(AppState& state);
// Arrow keys, +/-, [ ], PgUp/PgDn, Tab, Esc (F1/F11/F12 come from the executable).
void handle_shortcuts(AppState& state);

}  // namespace raycam::ui
