#include "flags/app/path_flags.h"

#include <algorithm>

namespace raycam::flags {

ValueRule<session::Sweep> sweep_rule() {
  std::vector<std::string> names;
  for (const session::SliderInfo& slider : session::path_sliders()) names.push_back(slider.name);
  const ValueRule<int> name = one_of(names);
  // The expected text names every slider's range, so that a refused value says what each one takes.
  std::string ranges;
  for (const session::SliderInfo& s : session::path_sliders())
    ranges += (ranges.empty() ? "" : ", ") + std::string(s.name) + " in " + (s.low_open ? "]" : "[") +
              short_number(s.low) + ", " + short_number(s.high) + "]";
  return {"SLIDER=FROM:TO with " + ranges,
          [name](const std::string& text) -> std::optional<session::Sweep> {
            const std::size_t equals = text.find('='), colon = text.find(':', equals == std::string::npos ? 0 : equals);
            if (equals == std::string::npos || colon == std::string::npos) return std::nullopt;
            const std::optional<int> index = name.parse(text.substr(0, equals));
            if (!index) return std::nullopt;
            const session::SliderInfo& s = session::path_sliders()[std::size_t(*index)];
            const ValueRule<double> value = number_in({s.low, s.high, s.low_open, false});
            const std::optional<double> from = value.parse(text.substr(equals + 1, colon - equals - 1));
            const std::optional<double> to = value.parse(text.substr(colon + 1));
            if (!from || !to) return std::nullopt;
            return session::Sweep{s.slider, *from, *to};
          }};
}

CLI::Option_group* add_path_options(CLI::App& command, PathFlags& path) {
  CLI::Option_group* group = command.add_option_group("Path", "How the camera moves (one kind of path at a time)");
  const ValueRule<session::Sweep> sweep = sweep_rule();
  group
      ->add_option_function<std::vector<std::string>>(
          "--sweep",
          [&path, sweep](const std::vector<std::string>& texts) {
            for (const std::string& text : texts) path.sweeps.push_back(*sweep.parse(text));
          },
          "move a slider from FROM to TO (df, d, theta, phi in degrees, res); repeat for one sweep after "
          "another, each taking an equal share of --seconds")
      ->type_name("SLIDER=FROM:TO")
      ->check(checked(sweep));
  add_checked_option<std::string>(*group, "--path", "FILE",
                                  "key cameras with durations, JSON: {\"keys\": [{\"theta\": 0}, {\"theta\": 90, "
                                  "\"seconds\": 2}]} (docs/record.md)",
                                  file_name(), [&path](std::string file) { path.key_file = file; });
  group->add_flag_callback(
      "--construction", [&path] { path.construction = true; },
      "the construction of M_d: frame a, then each factor applied in turn (2D: H, R, T; 3D: H, Rz(90°), Ry(φ), "
      "Rz(θ), T), with the construction panel's caption");
  group->add_flag_callback("--ease", [&path] { path.ease = true; },
                           "ease in and out: each sweep, step or key starts and stops at rest (default: linear)");
  return group;
}

session::CameraPath make_camera_path(const PathFlags& flags, const session::Lesson& state, double seconds) {
  const int kinds = int(!flags.sweeps.empty()) + int(flags.key_file.has_value()) + int(flags.construction);
  if (kinds == 0)
    throw std::invalid_argument("--sweep: expected a path: --sweep SLIDER=FROM:TO, --path FILE or --construction, got nothing");
  if (kinds > 1)
    throw std::invalid_argument("--path: expected one kind of path (--sweep, --path or --construction), got " +
                                std::to_string(kinds));
  const session::Easing easing = flags.ease ? session::Easing::ease_in_out : session::Easing::linear;
  session::Pose start = session::current_pose(state);
  start.step = -1;  // the placed camera (--step sets the construction's start only through --construction)
  start.fraction = 1.0;
  if (flags.key_file) return session::key_camera_path(start, session::dimension(state), *flags.key_file, easing);
  if (flags.construction) return session::construction_path(start, session::construction_steps(state), seconds, easing);
  return session::sweep_path(start, session::dimension(state), flags.sweeps, seconds, easing);
}

}  // namespace raycam::flags
