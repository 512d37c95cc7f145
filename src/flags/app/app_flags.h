// The app's command line, shared by the GLFW app (`raycam`) and its headless twin (`raycam-cli shot`): the
// camera and caster groups (view_options.h) plus the window, inspection and lecture flags. The same flags
// give the same frame. The UI itself only ever sees the parsed ui::AppOptions.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "app_options.h"

namespace raycam::flags {

// Adds the three option groups (Camera, Caster, App) to `command`, writing into `options`.
void add_app_options(CLI::App& command, ui::AppOptions& options);

// The options for `args` (without the program name), for tests and scripted starts. Throws CLI::ParseError
// (message: flags::usage_error_message).
ui::AppOptions parse_app_options(const std::vector<std::string>& args);

}  // namespace raycam::flags
