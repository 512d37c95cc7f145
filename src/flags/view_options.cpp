#include "flags/view_options.h"

#include <cstddef>
#include <iterator>
#include <string>
#include <vector>

#include "flags/flag_values.h"
#include "raycam/limits.h"

namespace raycam::flags {

namespace {
std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    const std::size_t at = text.find(separator, start);
    parts.push_back(text.substr(start, at - start));
    if (at == std::string::npos) return parts;
    start = at + 1;
  }
}

// Comma-separated numbers, each accepted by `item`, between `fewest` and `most` of them.
std::optional<std::vector<double>> numbers_of(const std::string& text, const ValueRule<double>& item,
                                              std::size_t fewest, std::size_t most) {
  const std::vector<std::string> parts = split(text, ',');
  if (parts.size() < fewest || parts.size() > most) return std::nullopt;
  std::vector<double> values;
  for (const std::string& part : parts) {
    const std::optional<double> x = item.parse(part);
    if (!x) return std::nullopt;
    values.push_back(*x);
  }
  return values;
}

// --target x,y or x,y,z: whether 2 or 3 fits the scene is checked by make_view_setup.
ValueRule<std::vector<double>> target_rule() {
  const ValueRule<double> coordinate = number_in({-kMaxCoordinate, kMaxCoordinate});
  return {"x,y or x,y,z with each coordinate in [-1e12, 1e12]",
          [coordinate](const std::string& text) { return numbers_of(text, coordinate, 2, 3); }};
}

std::vector<std::string> method_names() {
  std::vector<std::string> names;
  for (CastMethod method : kCastMethods) names.push_back(cast_method_name(method));
  return names;
}
}  // namespace

ValueRule<std::vector<double>> res_rule() {
  const ValueRule<double> res = number_in({0.0, 1.0, true, false});
  return {"R or RC,RL (columns, rows) with each in ]0, 1]",
          [res](const std::string& text) { return numbers_of(text, res, 1, 2); },
          [res](const std::string& text) {
            return text.find(',') == std::string::npos ? res.expected
                                                       : "RC,RL (columns, rows) with each in ]0, 1]";
          }};
}

ValueRule<Language> language_rule() {
  const ValueRule<int> code = one_of(std::vector<std::string>(std::begin(kLanguageCodes), std::end(kLanguageCodes)));
  return {code.expected, [code](const std::string& text) -> std::optional<Language> {
            const std::optional<int> index = code.parse(text);
            return index ? std::optional<Language>(kLanguages[std::size_t(*index)]) : std::nullopt;
          }};
}

std::string language_metavar() {
  std::string metavar;
  for (const char* code : kLanguageCodes) metavar += (metavar.empty() ? "" : "|") + std::string(code);
  return metavar;
}

// --size N (2D, or a square 3D image) or WxH (3D).
ValueRule<std::vector<int>> size_rule() {
  const ValueRule<int> n = integer_in(1, kMaxPixels2D), side = integer_in(1, kMaxSide3D);
  return {"N in [1, " + std::to_string(kMaxPixels2D) + "] or WxH with W, H in [1, " +
              std::to_string(kMaxSide3D) + "] and W*H <= " + std::to_string(kMaxPixels3D),
          [n, side](const std::string& text) -> std::optional<std::vector<int>> {
            const std::vector<std::string> parts = split(text, 'x');
            if (parts.size() == 1) {
              const std::optional<int> count = n.parse(parts[0]);
              return count ? std::optional<std::vector<int>>(std::vector<int>{*count}) : std::nullopt;
            }
            if (parts.size() != 2) return std::nullopt;
            const std::optional<int> w = side.parse(parts[0]), h = side.parse(parts[1]);
            if (!w || !h || static_cast<long long>(*w) * *h > kMaxPixels3D) return std::nullopt;
            return std::vector<int>{*w, *h};
          }};
}

CLI::Option_group* add_view_options(CLI::App& command, ViewFlags& view) {
  CLI::Option_group* group = command.add_option_group(
      "Camera", "The camera (flags override the scene file's preset; angles in degrees)");
  CameraPreset& camera = view.camera;
  add_checked_option<std::string>(*group, "--scene", "FILE",
                                  "scene file (JSON, docs/cli.md); default: a built-in demo scene",
                                  file_name(), [&view](std::string path) { view.scene_path = path; });
  add_checked_option<int>(*group, "--mode,--view", "2d|3d",
                          "camera kind when no scene file is given (default 3d)", one_of({"2d", "3d"}),
                          [&view](int index) { view.dimension = index + 2; });
  add_checked_option<std::vector<double>>(
      *group, "--target", "x,y[,z]", "the point C the camera looks at (default: the origin)", target_rule(),
      [&camera](std::vector<double> c) { camera.target = c; });
  add_checked_option<double>(*group, "--d", "D", "distance from C to the screen centre (2D default 6, 3D 8)",
                             number_in({0.0, kMaxCoordinate, true, false}),
                             [&camera](double d) { camera.d = d; });
  add_checked_option<double>(
      *group, "--theta", "DEG", "azimuth of CP around C, degrees (default: the 2D demo 70, a 2D file 90, 3D 30)",
      number_in({-1e6, 1e6}, "an angle in degrees"), [&camera](double a) { camera.theta_deg = a; });
  add_checked_option<double>(
      *group, "--phi", "DEG", "3D: polar angle of CP from +z, degrees (default 60; 0 = above, 180 = below)",
      number_in({-1e6, 1e6}, "an angle in degrees"), [&camera](double a) { camera.phi_deg = a; });
  add_checked_option<double>(
      *group, "--df", "F", "focal distance; field of view 2*atan(1/F) (2D default 1.5, 3D 2)",
      number_in({kMinFocalDistance, kMaxFocalDistance}), [&camera](double f) { camera.df = f; });
  add_checked_option<std::vector<double>>(
      *group, "--res", "R|RC,RL",
      "resolution factor; n = round(R*N), at least 1 (default 1); 3D: RC,RL for the columns and the rows",
      res_rule(), [&camera](std::vector<double> r) {
        camera.res = r[0];
        camera.res_rows = r.size() == 2 ? std::optional<double>(r[1]) : std::nullopt;
      });
  add_checked_option<std::vector<int>>(*group, "--size", "N|WxH",
                                       "maximum pixels: N in 2D, WxH in 3D (default 256, 256x256)",
                                       size_rule(), [&camera](std::vector<int> s) { camera.size = s; });
  return group;
}

CLI::Option_group* add_caster_options(CLI::App& command, CastOptions& cast, AccuracyFlags& accuracy) {
  CLI::Option_group* group = command.add_option_group(
      "Caster",
      "The caster and the accuracy knobs (docs/speed.md and docs/accuracy.md; any knob renders with "
      "the reference caster)");
  add_checked_option<int>(*group, "--method", "M",
                          "the caster; every method gives the plain loop's ids (default automatic)",
                          one_of(method_names()), [&cast](int index) { cast.method = kCastMethods[index]; });
  add_checked_option<int>(*group, "--threads", "T",
                          "worker threads for a 3D image (default: every hardware thread)",
                          integer_in(1, 256), [&cast](int threads) { cast.threads = threads; });
  ReferenceOptions& knobs = accuracy.options;
  add_checked_option<int>(*group, "--precision", "P", "arithmetic per ray (default double)",
                          one_of({"float", "double", "long-double"}),
                          [&knobs](int index) { knobs.scalar = kScalars[index]; });
  add_checked_option<int>(*group, "--intersect", "F",
                          "naive (textbook b^2 - c) or stable (Ray Tracing Gems; default)",
                          one_of({"naive", "stable"}), [&knobs](int index) {
                            knobs.formula = index == 0 ? IntersectFormula::naive : IntersectFormula::stable;
                          });
  add_checked_option<int>(
      *group, "--spp", "N", "stratified samples per pixel, colours averaged (3D: a square: 1, 4, 9, 16...)",
      integer_in(1, kMaxSamplesPerPixel), [&knobs](int spp) { knobs.samples_per_pixel = spp; });
  add_checked_option<int>(
      *group, "--frame", "F", "world (default) or relative: coordinates relative to the eye",
      one_of({"world", "relative"}), [&knobs](int index) { knobs.camera_relative = index == 1; });
  add_checked_option<int>(*group, "--placement", "R",
                          "orbit (default), arccos (handout) or stable (atan2): free placement from P and C",
                          one_of({"orbit", "arccos", "stable"}),
                          [&accuracy](int index) { accuracy.placement = PlacementRoute(index); });
  group->add_flag_callback(
      "--exact", [&accuracy] { accuracy.exact = true; },
      "2D: the exact bar, each pixel's colour weighted by its exact coverage");
  return group;
}

}  // namespace raycam::flags
