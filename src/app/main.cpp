// raycam: the interactive window (GLFW + Dear ImGui + OpenGL 3.3 core): options here, the window and its
// loop in glfw_host.cpp; the frame itself is raycam_ui's, shared with the headless `raycam-cli shot`.
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "app_options.h"
#include "glfw_host.h"

namespace {
using raycam::ui::AppState;

void print_help() {
  std::printf(
      "usage: raycam [SCENE.json] [--scene FILE] [camera flags] [--width W --height H] [--inspect COL,ROW]\n"
      "              [--step K] [--mistake NAME] [--font-scale S] [--frames N --screenshot out.png]\n\n"
      "The interactive raycam window. With no scene, a built-in demo scene opens. F1 lists the shortcuts.\n\n%s%s"
      "  --frames N          run N frames (no user input) and exit; N in [1, 100000]\n"
      "  --screenshot FILE   with --frames: save the last frame as PNG (the same image as raycam-cli shot)\n",
      raycam::view_flags_help(), raycam::ui::app_options_help());
}
}  // namespace

int main(int argc, char** argv) {
  raycam::ui::AppOptions options;
  options.demo_on_bad_scene = true;  // open on the demo scene and show why the file did not open
  raycam::app::ScriptedRun run;
  AppState state;
  try {
    const std::vector<std::string> args(argv + 1, argv + argc);
    for (std::size_t i = 0; i < args.size();) {
      if (args[i] == "--help" || args[i] == "-h") {
        print_help();
        return 0;
      }
      if (raycam::ui::parse_app_option(args, i, options)) continue;
      if (args[i] == "--frames" || args[i] == "--screenshot") {
        if (i + 1 >= args.size()) throw std::invalid_argument(args[i] + ": missing value");
        if (args[i] == "--screenshot") {
          run.screenshot = args[i + 1];
        } else {
          run.frames = raycam::parse_integer_flag(args[i + 1], "--frames", 1, 100000);
        }
        i += 2;
      } else if (args[i].rfind("--", 0) != 0 && !options.view.scene_path) {
        options.view.scene_path = args[i++];  // `raycam SCENE.json`
      } else {
        throw std::invalid_argument("unknown option '" + args[i] + "' (see raycam --help)");
      }
    }
    if (!run.screenshot.empty() && run.frames == 0) run.frames = 3;
    state = raycam::ui::make_app_state(options);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "raycam: error: %s\n", error.what());
    return 2;
  }
  return raycam::app::run_window(options, run, state);
}
