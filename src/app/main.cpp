// raycam: the interactive window (GLFW + Dear ImGui + OpenGL 3.3 core): the command line here (CLI11, the
// same option groups as `raycam-cli shot`), the window and its loop in glfw_host.cpp; the frame itself is
// raycam_ui's, shared with the headless `raycam-cli shot`.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "flags/app/app_flags.h"
#include "session/app_options.h"
#include "flags/flag_values.h"
#include "app/glfw_host.h"

int main(int argc, char** argv) {
  raycam::session::AppOptions options;
  options.demo_on_bad_scene = true;  // open on the demo scene and show why the file did not open
  raycam::app::ScriptedRun run;
  CLI::App cli(
      "raycam: the interactive camera window. With no scene, a built-in demo scene opens; F1 lists "
      "the shortcuts.",
      "raycam");
  raycam::flags::add_app_options(cli, options);
  std::string positional_scene;
  raycam::flags::add_scene_argument(cli, positional_scene);
  raycam::flags::add_checked_option<int>(cli, "--frames", "N", "run N frames (no user input) and exit",
                                         raycam::flags::integer_in(1, 100000),
                                         [&run](int n) { run.frames = n; });
  raycam::flags::add_checked_option<std::string>(
      cli, "--screenshot", "FILE",
      "with --frames: save the last frame as PNG (the same image as raycam-cli shot)",
      raycam::flags::file_name(), [&run](std::string path) { run.screenshot = path; });
  if (const auto usage_exit = raycam::flags::parse_command_line(cli, argc, argv)) return *usage_exit;
  if (!run.screenshot.empty() && run.frames == 0) run.frames = 3;
  raycam::session::AppState state;
  try {
    raycam::flags::merge_scene_argument(positional_scene, options);
    state = raycam::session::make_app_state(options);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "raycam: error: %s\n", error.what());
    return 2;
  }
  return raycam::app::run_window(options, run, state);
}
