#include "app_options.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace raycam::ui {

namespace {
std::string next_value(const std::vector<std::string>& args, std::size_t& i) {
  if (i + 1 >= args.size()) throw std::invalid_argument(args[i] + ": missing value (see --help)");
  i += 2;
  return args[i - 1];
}
}  // namespace

bool parse_app_option(const std::vector<std::string>& args, std::size_t& i, AppOptions& options) {
  if (args[i] == "--view") {  // a synonym of --mode, as in the issue's `shot --view 2d|3d`
    std::vector<std::string> as_mode{"--mode", i + 1 < args.size() ? args[i + 1] : ""};
    std::size_t j = 0;
    if (i + 1 >= args.size()) throw std::invalid_argument("--view: missing value (2d or 3d)");
    parse_view_flag(as_mode, j, options.view);
    i += 2;
    return true;
  }
  if (parse_view_flag(args, i, options.view) || parse_accuracy_flag(args, i, options.accuracy)) return true;
  const std::string flag = args[i];
  if (flag == "--method") {
    options.cast_options.method = parse_cast_method(next_value(args, i), flag);
  } else if (flag == "--width") {
    options.width = parse_integer_flag(next_value(args, i), flag, 320, 7680);
  } else if (flag == "--height") {
    options.height = parse_integer_flag(next_value(args, i), flag, 240, 4320);
  } else if (flag == "--inspect") {
    const std::string value = next_value(args, i);
    const std::size_t comma = value.find(',');
    PixelIndex pixel;
    pixel.column = parse_integer_flag(value.substr(0, comma), flag + " (column)", 0, 1 << 20);
    pixel.row = comma == std::string::npos ? 0 : parse_integer_flag(value.substr(comma + 1), flag + " (row)", 0, 1 << 20);
    options.inspect = pixel;
  } else if (flag == "--step") {
    options.step = parse_integer_flag(next_value(args, i), flag, 0, 5);
  } else if (flag == "--mistake") {
    const std::string name = next_value(args, i);
    if (name == "printed-rotation") options.mistakes.printed_rotation_sign = true;
    else if (name == "pixel-edges") options.mistakes.pixel_edges = true;
    else if (name == "no-renormalise") options.mistakes.skip_renormalise = true;
    else if (name == "arccos") options.arccos_route = true;
    else if (const MistakeInfo* info = find_mistake(name))
      options.mistakes.*info->flag = true;
    else {
      std::string ids;
      for (const MistakeInfo& known : kClassicMistakes) ids += std::string(", ") + known.id;
      throw std::invalid_argument(
          "--mistake: expected printed-rotation, pixel-edges, no-renormalise, arccos" + ids + ", got '" +
          name + "'");
    }
  } else if (flag == "--font-scale") {
    const std::string value = next_value(args, i);
    char* end = nullptr;
    const double scale = std::strtod(value.c_str(), &end);
    if (value.empty() || *end != '\0' || !(scale >= 0.5 && scale <= 4.0))
      throw std::invalid_argument("--font-scale: expected a number in [0.5, 4], got '" + value + "'");
    options.font_scale = float(scale);
  } else if (flag == "--lang") {
    options.language = parse_language_flag(next_value(args, i), flag);
  } else if (flag == "--check") {
    options.check_command = next_value(args, i);
  } else if (flag == "--high-contrast") {
    options.high_contrast = true;
    ++i;
  } else {
    return false;
  }
  return true;
}

namespace {
ViewSetup checked_view_setup(const ViewFlags& flags) {
  const ViewSetup setup = make_view_setup(flags);
  if (setup.dimension == 2) validate(setup.file.scene2d);
  else validate(setup.file.scene3d);
  return setup;
}
}  // namespace

AppState make_app_state(const AppOptions& options) {
  AppState state;
  state.language = options.language.value_or(language_from_environment());
  set_language(state.language);  // the messages made below are in the window's language
  std::optional<ViewSetup> setup;
  try {
    setup = checked_view_setup(options.view);
  } catch (const std::exception& error) {
    if (!options.demo_on_bad_scene || !options.view.scene_path) throw;
    // The app opens on the demo scene and says why the file did not open (a bad flag still stops it).
    ViewFlags without_file = options.view;
    without_file.scene_path.reset();
    setup = checked_view_setup(without_file);
    const std::string& path = *options.view.scene_path;
    const std::string reason = error.what();
    set_message(state, MessageSource::files, true,
                reason.find(path) == std::string::npos
                    ? trf("cannot open %s: %s", path.c_str(), reason.c_str())
                    : trf("cannot open: %s", reason.c_str()));
  }
  adopt_view_setup(state, *setup);
  state.mistakes = options.mistakes;
  state.arccos_route = options.arccos_route;
  if (options.step) {
    const int steps = construction_steps(state);
    if (*options.step > steps)
      throw std::invalid_argument("--step: expected an integer in [0, " + std::to_string(steps) + "] in " +
                                  std::to_string(state.dimension) + "D");
    state.construction_step = *options.step;
  }
  if (options.accuracy.placement != PlacementRoute::orbit)
    throw std::invalid_argument("--placement: the app places the camera by orbit; show the arccos route with "
                                "--mistake arccos");
  state.accuracy = options.accuracy;
  state.cast_options = options.cast_options;
  state.font_scale = options.font_scale;
  state.high_contrast = options.high_contrast;
  state.check_command = options.check_command;
  place_cameras(state);  // throws on bad parameters before any window opens
  if (options.inspect) {
    const int columns = state.dimension == 2 ? state.camera2d.pixel_count() : state.camera3d.columns();
    const int rows = state.dimension == 2 ? 1 : state.camera3d.rows();
    if (options.inspect->column >= columns || options.inspect->row >= rows)
      throw std::invalid_argument("--inspect: pixel " + std::to_string(options.inspect->column) + "," +
                                  std::to_string(options.inspect->row) + " is outside the " + std::to_string(columns) +
                                  "x" + std::to_string(rows) + " image");
    state.pinned_pixel = options.inspect;
  }
  if (!state.scene_path.empty()) std::snprintf(state.path_input, sizeof state.path_input, "%s", state.scene_path.c_str());
  return state;
}

const char* app_options_help() {
  return "  --view 2d|3d        same as --mode\n"
         "  --width W --height H  window size in pixels (default 1280x720)\n"
         "  --inspect COL,ROW   pin the ray inspector on a pixel (2D: COL is the bar column, ROW 0)\n"
         "  --step K            show the construction of M_d up to step K (2D: 0..3, 3D: 0..5)\n"
         "  --mistake NAME      show a classic mistake: arccos or an ID of README \"Classic mistakes\"\n"
         "                      (repeatable)\n"
         "  --font-scale S      lecture mode: scale every font by S in [0.5, 4]\n"
         "  --high-contrast     lecture mode: light, high-contrast theme\n"
         "  --lang fr|en        language of the window (default: from LANGUAGE, LC_ALL, LC_MESSAGES, LANG)\n"
         "  --check \"CMD\"       Check my camera: run your program on the camera whenever it changes\n"
         "  --method M          the caster: automatic (default), plain, culled, footprint, binned (same "
         "image)\n"
         "  --precision P --intersect F --spp N --frame F --exact\n"
         "                      accuracy knobs, as in raycam-cli render --help (README, \"Accuracy\")\n";
}

}  // namespace raycam::ui
