#include "raycam/view_setup.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <glm/trigonometric.hpp>
#include <stdexcept>

#include "raycam/limits.h"

namespace raycam {

namespace {

[[noreturn]] void bad_flag(const std::string& flag, const std::string& expected, const std::string& got) {
  throw std::invalid_argument(flag + ": expected " + expected + ", got '" + got + "'");
}

double parse_number(const std::string& text, const std::string& flag, const std::string& expected) {
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(value))
    bad_flag(flag, expected, text);
  return value;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t at = text.find(separator, start);
    parts.push_back(text.substr(start, at - start));
    if (at == std::string::npos) return parts;
    start = at + 1;
  }
}

int parse_size_component(const std::string& text, const std::string& flag, int max) {
  const std::string expected = "an integer in [1, " + std::to_string(max) + "]";
  const double value = parse_number(text, flag, expected);
  if (value < 1 || value > max || std::floor(value) != value) bad_flag(flag, expected, text);
  return int(value);
}
}  // namespace

int parse_integer_flag(const std::string& text, const std::string& flag, int lo, int hi) {
  errno = 0;
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno == ERANGE || value < lo || value > hi)
    bad_flag(flag, "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]", text);
  return int(value);
}

bool parse_view_flag(const std::vector<std::string>& args, std::size_t& i, ViewFlags& flags) {
  static const char* const kFlags[] = {"--scene", "--mode", "--target", "--d",   "--theta",
                                       "--phi",   "--df",   "--res",    "--size"};
  const std::string& flag = args[i];
  bool known = false;
  for (const char* f : kFlags) known = known || flag == f;
  if (!known) return false;
  if (i + 1 >= args.size()) throw std::invalid_argument(flag + ": missing value (see --help)");
  const std::string& value = args[++i];
  ++i;
  CameraPreset& camera = flags.camera;
  if (flag == "--scene") {
    flags.scene_path = value;
  } else if (flag == "--mode") {
    if (value != "2d" && value != "3d") bad_flag(flag, "2d or 3d", value);
    flags.dimension = value == "2d" ? 2 : 3;
  } else if (flag == "--target") {
    const std::vector<std::string> parts = split(value, ',');
    if (parts.size() != 2 && parts.size() != 3) bad_flag(flag, "x,y (2D) or x,y,z (3D)", value);
    std::vector<double> target;
    for (const std::string& part : parts) {
      const double x = parse_number(part, flag, "finite numbers with |x| <= 1e12");
      if (std::abs(x) > kMaxCoordinate) bad_flag(flag, "finite numbers with |x| <= 1e12", value);
      target.push_back(x);
    }
    camera.target = target;
  } else if (flag == "--d") {
    const double x = parse_number(value, flag, "a number in ]0, 1e12]");
    if (x <= 0.0 || x > kMaxCoordinate) bad_flag(flag, "a number in ]0, 1e12]", value);
    camera.d = x;
  } else if (flag == "--df") {
    const double x = parse_number(value, flag, "a number in [1e-9, 1e9]");
    if (!(x >= kMinFocalDistance && x <= kMaxFocalDistance)) bad_flag(flag, "a number in [1e-9, 1e9]", value);
    camera.df = x;
  } else if (flag == "--theta" || flag == "--phi") {
    const double x = parse_number(value, flag, "an angle in degrees in [-1e6, 1e6]");
    if (std::abs(x) > 1e6) bad_flag(flag, "an angle in degrees in [-1e6, 1e6]", value);
    (flag == "--theta" ? camera.theta_deg : camera.phi_deg) = x;
  } else if (flag == "--res") {
    const double x = parse_number(value, flag, "a number in ]0, 1]");
    if (!(x > 0.0 && x <= 1.0)) bad_flag(flag, "a number in ]0, 1]", value);
    camera.res = x;
  } else {  // --size N | WxH
    const std::vector<std::string> parts = split(value, 'x');
    if (parts.size() == 1) {
      camera.size = std::vector<int>{
          parse_size_component(parts[0], flag, kMaxSide3D > kMaxPixels2D ? kMaxSide3D : kMaxPixels2D)};
    } else if (parts.size() == 2) {
      const int w = parse_size_component(parts[0], flag, kMaxSide3D),
                h = parse_size_component(parts[1], flag, kMaxSide3D);
      if (static_cast<long long>(w) * h > kMaxPixels3D)
        bad_flag(flag, "W x H <= " + std::to_string(kMaxPixels3D) + " pixels", value);
      camera.size = std::vector<int>{w, h};
    } else {
      bad_flag(flag, "N or WxH", value);
    }
  }
  return true;
}

namespace {
// Fields set in `over` replace those in `base`.
CameraPreset merged(CameraPreset base, const CameraPreset& over) {
  if (over.target) base.target = over.target;
  if (over.d) base.d = over.d;
  if (over.theta_deg) base.theta_deg = over.theta_deg;
  if (over.phi_deg) base.phi_deg = over.phi_deg;
  if (over.df) base.df = over.df;
  if (over.res) base.res = over.res;
  if (over.size) base.size = over.size;
  return base;
}
}  // namespace

ViewSetup make_view_setup(const ViewFlags& flags) {
  ViewSetup setup;
  if (flags.scene_path) {
    setup.scene_path = *flags.scene_path;
    setup.file = load_scene_file(*flags.scene_path);
    if (flags.dimension && *flags.dimension != setup.file.dimension)
      throw std::invalid_argument("--mode: " + std::to_string(*flags.dimension) +
                                  "d does not match the scene file " + *flags.scene_path + ", which is " +
                                  std::to_string(setup.file.dimension) + "D");
  } else {
    setup.file.dimension = flags.dimension.value_or(3);
    setup.file.scene2d = demo_scene_2d();
    setup.file.scene3d = demo_scene_3d();
  }
  setup.dimension = setup.file.dimension;
  const bool is_2d = setup.dimension == 2;
  CameraPreset& preset = setup.file.camera;
  preset = merged(preset, flags.camera);

  if (preset.target && preset.target->size() != std::size_t(setup.dimension))
    throw std::invalid_argument("--target: expected " + std::string(is_2d ? "x,y" : "x,y,z") + " for a " +
                                std::to_string(setup.dimension) + "D scene");
  if (is_2d && flags.camera.phi_deg)
    throw std::invalid_argument("--phi: only for 3D scenes (this one is 2D)");

  if (is_2d) {
    if (preset.size && preset.size->size() != 1)
      throw std::invalid_argument("--size: expected N for a 2D scene");
    if (preset.size && (*preset.size)[0] > kMaxPixels2D)
      throw std::invalid_argument("--size: expected N in [1, " + std::to_string(kMaxPixels2D) +
                                  "] for a 2D scene");
    setup.camera2d = Camera2D(preset.size ? (*preset.size)[0] : kDefaultSize2D);
    Orbit2D orbit;
    if (preset.target) orbit.target = {(*preset.target)[0], (*preset.target)[1]};
    if (preset.d) orbit.d = *preset.d;
    if (preset.theta_deg) orbit.theta = glm::radians(*preset.theta_deg);
    if (preset.df) orbit.df = *preset.df;
    setup.camera2d.set_orbit(orbit);
    if (preset.res) setup.camera2d.set_res(*preset.res);
  } else {
    int columns = kDefaultSize3D, rows = kDefaultSize3D;
    if (preset.size) {
      if (preset.size->size() == 1 && (*preset.size)[0] > kMaxSide3D)
        throw std::invalid_argument("--size: expected N or WxH with sides in [1, " +
                                    std::to_string(kMaxSide3D) + "]");
      columns = (*preset.size)[0];
      rows = preset.size->size() == 2 ? (*preset.size)[1] : columns;
    }
    setup.camera3d = Camera3D(columns, rows);
    Orbit3D orbit;
    if (preset.target) orbit.target = {(*preset.target)[0], (*preset.target)[1], (*preset.target)[2]};
    if (preset.d) orbit.d = *preset.d;
    if (preset.theta_deg) orbit.theta = glm::radians(*preset.theta_deg);
    if (preset.phi_deg) orbit.phi = glm::radians(*preset.phi_deg);
    if (preset.df) orbit.df = *preset.df;
    setup.camera3d.set_orbit(orbit);
    if (preset.res) setup.camera3d.set_res(*preset.res);
  }
  return setup;
}

CameraPreset preset_of(const Camera2D& camera) {
  CameraPreset preset;
  const Orbit2D& orbit = camera.orbit();
  preset.target = std::vector<double>{orbit.target.x, orbit.target.y};
  preset.d = orbit.d;
  preset.theta_deg = glm::degrees(orbit.theta);
  preset.df = orbit.df;
  preset.res = camera.res();
  preset.size = std::vector<int>{camera.max_pixels()};
  return preset;
}

CameraPreset preset_of(const Camera3D& camera) {
  CameraPreset preset;
  const Orbit3D& orbit = camera.orbit();
  preset.target = std::vector<double>{orbit.target.x, orbit.target.y, orbit.target.z};
  preset.d = orbit.d;
  preset.theta_deg = glm::degrees(orbit.theta);
  preset.phi_deg = glm::degrees(orbit.phi);
  preset.df = orbit.df;
  preset.res = camera.res_columns();
  preset.size = std::vector<int>{camera.max_columns(), camera.max_rows()};
  return preset;
}

const char* view_flags_help() {
  return "  --scene FILE        scene file (JSON, see README); default: a built-in demo scene\n"
         "  --mode 2d|3d        camera kind when no scene file is given (default 3d)\n"
         "  --target x,y[,z]    the point the camera looks at, C (default: the origin)\n"
         "  --d D               distance from C to the screen centre, D in ]0, 1e12] (2D default 6, 3D 8)\n"
         "  --theta DEG         azimuth of the camera around C, degrees (2D default 90, 3D 30)\n"
         "  --phi DEG           3D polar angle from +z, degrees (default 60; 0 = above, 180 = below)\n"
         "  --df F              focal distance, F in [1e-9, 1e9]; field of view 2*atan(1/F) (2D 1.5, 3D 2)\n"
         "  --res R             resolution factor in ]0, 1]; n = round(R*N), at least 1 (default 1)\n"
         "  --size N | WxH      maximum pixels: N for 2D (<= 1048576), WxH for 3D (sides <= 16384, W*H <= "
         "2^26)\n";
}

}  // namespace raycam
