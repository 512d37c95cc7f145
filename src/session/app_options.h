// The app's start-up options, shared by the GLFW app (`raycam`) and the headless twin (`raycam-cli shot`):
// the same options give the same frame. The command line fills them (src/flags/app/app_flags.h); the UI never
// sees argv.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "session/app_state.h"
#include "raycam/accuracy_options.h"
#include "raycam/view_setup.h"

namespace raycam::session {

// The font scale a start-up option accepts (--font-scale, the page's ?scale=); the slider spans 0.75–3.
inline constexpr double kFontScaleOptionMin = 0.5, kFontScaleOptionMax = 4.0;

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
  // --overhead-view X0,Y0,X1,Y1: the overhead view's world rectangle, held (else fitted to the scene and
  // camera); `record` passes the one it fits to a whole path, so that `shot` can give the same frame.
  std::optional<std::array<double, 4>> overhead_view;
  AccuracyFlags accuracy;    // --precision --intersect --spp --frame --exact (--placement: use --mistake arccos)
  CastOptions cast_options;  // --method
  bool demo_on_bad_scene =
      false;  // the app: a scene that cannot be opened gives the demo and an error message
};

// The initial state for these options (scene loaded, cameras placed). Throws std::invalid_argument.
AppState make_app_state(const AppOptions& options);

}  // namespace raycam::session
