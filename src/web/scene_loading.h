// Opening a scene file in the page in steps, with progress in the status line, for any route a file takes into
// the page (the picker, a drop, a path): a big file is read in slices (the page keeps answering: its script
// awaits each slice), then parsed and checked in slices of 50 ms, one a frame (SceneFileReader), then packed
// and cast in one step, each step announced by the frame drawn before it. The steps and their figures:
// docs/web.md ("Big files").
#pragma once

#include <string>

#include "session/app_state.h"

namespace raycam::web {

// Defines Module.raycamReadFile(file, path) for the page's script: reads a browser File into the page's file
// system at `path` in slices, the status line showing the bytes read, then opens it with open_scene_in_steps.
void install_scene_reader();

// Opens the scene file at `path` (in the page's file system) as the desktop's Open does (the same checks and
// messages), over the next frames: first a frame saying what is parsed, then the parse, a slice a frame, the
// status line counting the objects read, then a frame saying what is packed, then the first image.
void open_scene_in_steps(session::AppState& state, const std::string& path);

// The next step, once a frame (the one saying what comes) has been drawn; returns true while steps remain
// (the page then keeps drawing frames).
bool scene_loading_step(session::AppState& state);

}  // namespace raycam::web
