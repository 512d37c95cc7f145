#include "session/app_options.h"

#include <cstdio>
#include <stdexcept>

#include "session/text.h"

namespace raycam::session {

namespace {
ViewSetup checked_view_setup(const ViewFlags& flags) {
  const ViewSetup setup = make_view_setup(flags);
  validate(views_from_setup(setup).on_screen);
  return setup;
}
}  // namespace

AppState make_app_state(const AppOptions& options) {
  AppState state;
  state.language = options.language.value_or(language_from_environment());
  std::optional<ViewSetup> setup;
  try {
    setup = checked_view_setup(options.view);
  } catch (const std::exception& error) {
    if (!options.demo_on_bad_scene || !options.view.scene_path) throw;
    // The app opens on the demo scene and says why the file did not open (a bad flag still stops it).
    ViewFlags without_file = options.view;
    without_file.scene_path.reset();
    setup = checked_view_setup(without_file);
    set_message(state, MessageSource::files, true, cannot_open_message(state.language, *options.view.scene_path, error.what()));
  }
  adopt_view_setup(state, state, *setup);
  state.mistakes = options.mistakes;
  state.arccos_route = options.arccos_route;
  if (options.step) {
    const int steps = construction_steps(state);
    if (*options.step > steps)
      throw std::invalid_argument("--step: expected an integer in [0, " + std::to_string(steps) + "] in " +
                                  std::to_string(dimension(state)) + "D");
    state.construction_step = *options.step;
  }
  if (options.accuracy.exact && !exact_bar_applies(state.view))
    throw std::invalid_argument("--exact: only for a 2D scene (3D: use --spp)");
  if (options.accuracy.placement != PlacementRoute::orbit)
    throw std::invalid_argument("--placement: the app places the camera by orbit; show the arccos route with "
                                "--mistake arccos");
  state.accuracy = options.accuracy;
  state.cast_options = options.cast_options;
  if (options.overhead_view) {
    const auto& r = *options.overhead_view;
    state.overhead_low = {r[0], r[1]};
    state.overhead_high = {r[2], r[3]};
    state.overhead_fit_pending = false;
  }
  state.font_scale = options.font_scale;
  state.high_contrast = options.high_contrast;
  place_cameras(state);  // throws on bad parameters before any window opens
  if (options.inspect) {
    const auto [columns, rows] = std::visit(
        [](const auto& view) { return std::pair(image_columns(view.camera), image_rows(view.camera)); }, state.view);
    if (options.inspect->column >= columns || options.inspect->row >= rows)
      throw std::invalid_argument("--inspect: pixel " + std::to_string(options.inspect->column) + "," +
                                  std::to_string(options.inspect->row) + " is outside the " + std::to_string(columns) +
                                  "x" + std::to_string(rows) + " image");
    state.pinned_pixel = options.inspect;
  }
  return state;
}

}  // namespace raycam::session
