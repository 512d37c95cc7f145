// Command-line options shared by the GLFW app (`raycam`) and the headless twin (`raycam-cli shot`): the
// same flags give the same frame.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app_state.h"
#include "raycam/accuracy_options.h"
#include "raycam/view_setup.h"

namespace raycam::ui {

struct AppOptions {
  ViewFlags view;  // --scene --mode/--view --target --d --theta --phi --df --res --size
  int width = 1280, height = 720;
  std::optional<PixelIndex> inspect;  // --inspect COL,ROW (2D: COL is the bar column)
  std::optional<int> step;            // --step K
  ClassicMistakes mistakes;           // --mistake NAME (repeatable)
  bool arccos_route = false;
  float font_scale = 1.0f;
  bool high_contrast = false;
  std::string check_command;         // --check "CMD": the "Check my camera" panel's program
  std::optional<Language> language;  // --lang fr|en; default: the environment (LANGUAGE, LC_ALL, LANG)
  AccuracyFlags accuracy;    // --precision --intersect --spp --frame --exact (--placement: use --mistake arccos)
  CastOptions cast_options;  // --method
  bool demo_on_bad_scene =
      false;  // the app: a scene that cannot be opened gives the demo and an error message
};

// If args[i] is a shared option, consumes it (and its value) and returns true. Throws std::invalid_argument
// naming the flag and the accepted range.
bool parse_app_option(const std::vector<std::string>& args, std::size_t& i, AppOptions& options);

// The initial state for these options (scene loaded, cameras placed). Throws std::invalid_argument.
AppState make_app_state(const AppOptions& options);

// Help text for the shared options.
const char* app_options_help();

}  // namespace raycam::ui
