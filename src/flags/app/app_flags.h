// The app's command line, shared by the GLFW app (`raycam`) and its headless twin (`raycam-cli shot`): the
// camera and caster groups (view_options.h) plus the window, inspection and lecture flags. The same flags
// give the same frame. The UI itself only ever sees the parsed session::AppOptions.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "session/app_options.h"

namespace raycam::flags {

// Adds the three option groups (Camera, Caster, App) to `command`, writing into `options`.
void add_app_options(CLI::App& command, session::AppOptions& options);

// A positional SCENE file, as `raycam SCENE.json` takes it (same as --scene): call merge_scene_argument after
// the parse (giving both is an error).
CLI::Option* add_scene_argument(CLI::App& command, std::string& scene);
void merge_scene_argument(const std::string& scene, session::AppOptions& options);

// The options for `args` (without the program name) on top of `start`, as the app parses them (groups and
// SCENE), for tests and scripted starts. Throws CLI::ParseError (message: flags::usage_error_message) or
// std::invalid_argument.
session::AppOptions parse_app_options(const std::vector<std::string>& args, session::AppOptions start = {});

}  // namespace raycam::flags
