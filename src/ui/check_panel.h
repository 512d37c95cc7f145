// "Check my camera" on screen: the panel section that edits the command and shows the verdict of the
// session's CameraCheck (session/camera_check.h), and the wrong pixels in red over the image.
#pragma once

#include <imgui.h>

#include <string>
#include <vector>

#include "session/camera_check.h"

struct ImDrawList;

namespace raycam::ui {

// The panel section: the command, the verdict, the diagnosis, the program's stderr.
// `mistakes`: the names of the classic mistakes on (the verdict is the case's camera's, not the image's).
void check_section(session::CameraCheck& check, const session::HostCapabilities& host, double now, Language language,
                   const std::string& mistakes = "");
// Where the panel last drew a verdict (x0, y0, x1, y1 in screen pixels), for the tests.
ImVec4 drawn_verdict_rect();
// The same rectangle down to the verdict's next step (the first diagnosis line, else the clear button): what
// an arriving verdict is scrolled to show.
ImVec4 drawn_next_step_rect();
// What the section last said under the verdict about the diagnosis (its heading, its bullets, or that no
// classic mistake makes the image), for the tests.
std::vector<std::string> drawn_diagnosis_lines();
// Translucent red over the wrong pixels of the image drawn in [x0, x1] × [y0, y1] (only while the verdict
// is for the image on screen).
void check_overlay(const session::CameraCheck& check, const session::Lesson& state, const session::CastCache& cast,
                   ImDrawList* list, float x0, float y0,
                   float x1, float y1);

}  // namespace raycam::ui
