// The page's Record control (F9, the panel's button, the status line's sign): the browser's MediaRecorder
// on the canvas's stream, saved as a WebM download named after the scene when it stops. The desktop window
// records through FFmpeg instead (src/app/glfw_host.cpp); the panel and the keys are the same.
#pragma once

#include "session/app_state.h"

namespace raycam::web {

// Starts recording the canvas, or stops and hands the video to the browser as a download. A browser with
// no MediaRecorder is said on the status line.
void toggle_page_recording(session::AppState& state);
// Keeps the status line's clock (state.recording_seconds) moving while the page records.
void update_page_recording(session::AppState& state);

}  // namespace raycam::web
