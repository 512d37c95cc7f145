#include "flags/app/app_flags.h"

#include <array>
#include <optional>
#include <stdexcept>
#include <string>

#include "flags/flag_values.h"
#include "raycam/classic_mistakes.h"
#include "session/text.h"
#include "flags/view_options.h"

namespace raycam::flags {

namespace {
// --inspect COL,ROW (2D: COL alone, the bar column). Whether the pixel is in the image is checked by
// make_app_state, which knows the image size.
ValueRule<session::PixelIndex> pixel_rule() {
  const ValueRule<int> index = integer_in(0, 1 << 20);
  return {"COL or COL,ROW with integers in [0, 1048576]",
          [index](const std::string& text) -> std::optional<session::PixelIndex> {
            const std::size_t comma = text.find(',');
            const std::optional<int> column = index.parse(text.substr(0, comma));
            const std::optional<int> row =
                comma == std::string::npos ? 0 : index.parse(text.substr(comma + 1));
            if (!column || !row) return std::nullopt;
            session::PixelIndex pixel;
            pixel.column = *column;
            pixel.row = *row;
            return pixel;
          }};
}

// --overhead-view X0,Y0,X1,Y1: a rectangle of the plane seen from above, with some width and height.
ValueRule<std::array<double, 4>> rectangle_rule() {
  const ValueRule<double> coordinate = number_in({-1e12, 1e12});
  return {"X0,Y0,X1,Y1 with X0 < X1, Y0 < Y1, each in [-1e12, 1e12]",
          [coordinate](const std::string& text) -> std::optional<std::array<double, 4>> {
            std::array<double, 4> r{};
            std::size_t start = 0;
            for (int i = 0; i < 4; ++i) {
              const std::size_t comma = text.find(',', start);
              if ((i < 3) != (comma != std::string::npos)) return std::nullopt;
              const std::optional<double> x = coordinate.parse(text.substr(start, comma - start));
              if (!x) return std::nullopt;
              r[std::size_t(i)] = *x;
              start = comma + 1;
            }
            if (!(r[0] < r[2] && r[1] < r[3])) return std::nullopt;
            return r;
          }};
}
}  // namespace

void add_app_options(CLI::App& command, session::AppOptions& options) {
  add_view_options(command, options.view);
  add_caster_options(command, options.cast_options, options.accuracy);
  CLI::Option_group* group = command.add_option_group("App", "The window, the inspector and lecture mode");
  add_checked_option<int>(*group, "--width", "W", "window width in pixels (default 1280; at most the screen's)",
                          integer_in(320, 7680), [&options](int w) { options.width = w; });
  add_checked_option<int>(*group, "--height", "H", "window height in pixels (default 720; at most the screen's)",
                          integer_in(240, 4320), [&options](int h) { options.height = h; });
  add_checked_option<session::PixelIndex>(
      *group, "--inspect", "COL,ROW", "pin the ray inspector on a pixel (2D: COL is the bar column)",
      pixel_rule(), [&options](session::PixelIndex pixel) { options.inspect = pixel; });
  add_checked_option<int>(*group, "--step", "K",
                          "show the construction of M_d up to step K (2D: 0..3, 3D: 0..5)", integer_in(0, 5),
                          [&options](int step) { options.step = step; });
  // Repeatable: each value is checked by the same rule (the one message format), then all are applied.
  // The handout's three printed mistakes keep their old names; every mistake also answers to its ID.
  std::vector<std::string> mistake_names{"printed-rotation", "pixel-edges", "no-renormalise", "arccos"};
  for (const MistakeInfo& known : kClassicMistakes) mistake_names.push_back(known.id);
  const ValueRule<int> mistake = one_of(mistake_names);
  group
      ->add_option_function<std::vector<std::string>>(
          "--mistake",
          [&options, mistake](const std::vector<std::string>& names) {
            ClassicMistakes& m = options.mistakes;
            for (const std::string& name : names) {
              const int index = *mistake.parse(name);
              if (index == 0) m.printed_rotation_sign = true;
              if (index == 1) m.pixel_edges = true;
              if (index == 2) m.skip_renormalise = true;
              if (index == 3) options.arccos_route = true;
              if (index >= 4) m.*kClassicMistakes[index - 4].flag = true;
            }
          },
          "show a classic mistake: arccos or an ID of docs/check.md's table of classic mistakes (repeatable)")
      ->type_name("NAME")
      ->check(checked(mistake));
  add_checked_option<std::array<double, 4>>(
      *group, "--overhead-view", "X0,Y0,X1,Y1",
      "the overhead view's world rectangle, held while the camera stays in it (default: fitted to the scene and "
      "camera; `record` prints the one it holds)",
      rectangle_rule(), [&options](std::array<double, 4> r) { options.overhead_view = r; });
  add_checked_option<double>(*group, "--font-scale", "S", "lecture mode: scale every font by S",
                             number_in({session::kFontScaleOptionMin, session::kFontScaleOptionMax}),
                             [&options](double scale) { options.font_scale = float(scale); });
  add_checked_option<Language>(
      *group, "--lang", language_metavar(),
      "language of the window (default: from LANGUAGE, LC_ALL, LC_MESSAGES, LANG)", language_rule(),
      [&options](Language language) { options.language = language; });
  add_checked_option<std::string>(*group, "--check", "\"CMD\"",
                                  "Check my camera: run your program on the camera whenever it changes",
                                  file_name(), [&options](std::string command) { options.check_command = command; });
  group->add_flag_callback(
      "--high-contrast", [&options] { options.high_contrast = true; },
      "lecture mode: light, high-contrast theme");
}

CLI::Option* add_scene_argument(CLI::App& command, std::string& scene) {
  return command.add_option("SCENE", scene, "scene file to open (same as --scene)");
}

void merge_scene_argument(const std::string& scene, session::AppOptions& options) {
  if (scene.empty()) return;
  if (options.view.scene_path) throw std::invalid_argument("SCENE: give the scene file once, as SCENE or --scene");
  options.view.scene_path = scene;
}

session::AppOptions parse_app_options(const std::vector<std::string>& args, session::AppOptions start) {
  session::AppOptions options = start;
  CLI::App command;
  add_app_options(command, options);
  std::string scene;
  add_scene_argument(command, scene);
  command.parse(std::vector<std::string>(args.rbegin(), args.rend()));  // CLI11 takes them last first
  merge_scene_argument(scene, options);
  return options;
}

}  // namespace raycam::flags
