#include "raycam/view_setup.h"

#include <cmath>

#include <glm/trigonometric.hpp>
#include <stdexcept>

#include "raycam/limits.h"

namespace raycam {

namespace {
// Fields set in `over` replace those in `base`.
CameraPreset merged(CameraPreset base, const CameraPreset& over) {
  if (over.target) base.target = over.target;
  if (over.d) base.d = over.d;
  if (over.theta_deg) base.theta_deg = over.theta_deg;
  if (over.phi_deg) base.phi_deg = over.phi_deg;
  if (over.df) base.df = over.df;
  if (over.res) {  // the flag's res replaces the file's pair: --res 0.5 makes the image square again
    base.res = over.res;
    base.res_rows = over.res_rows;
  }
  if (over.size) base.size = over.size;
  return base;
}

// Each dimension's own rules for the flags, then its camera from the preset.
void place(Camera2D& camera, const CameraPreset& preset, const CameraPreset& flags) {
  if (flags.phi_deg) throw std::invalid_argument("--phi: only for 3D scenes (this one is 2D)");
  if (flags.res_rows) throw std::invalid_argument("--res: expected one number R for a 2D scene (RC,RL is for 3D)");
  if (preset.size && preset.size->size() != 1) throw std::invalid_argument("--size: expected N for a 2D scene");
  if (preset.size && (*preset.size)[0] > kMaxPixels2D)
    throw std::invalid_argument("--size: expected N in [1, " + std::to_string(kMaxPixels2D) + "] for a 2D scene");
  camera = camera2d_from_preset(preset);
}
void place(Camera3D& camera, const CameraPreset& preset, const CameraPreset&) {
  if (preset.size && preset.size->size() == 1 && (*preset.size)[0] > kMaxSide3D)
    throw std::invalid_argument("--size: expected N or WxH with sides in [1, " + std::to_string(kMaxSide3D) + "]");
  camera = camera3d_from_preset(preset);
}
}  // namespace

ViewSetup make_view_setup(const ViewFlags& flags) {
  if (flags.scene_path) return make_view_setup(flags, load_scene_file(*flags.scene_path));
  return make_view_setup(flags, std::nullopt);
}

ViewSetup make_view_setup(const ViewFlags& flags, std::optional<SceneFile> parsed) {
  ViewSetup setup;
  if (parsed) {
    setup.scene_path = flags.scene_path.value_or("");
    setup.file = std::move(*parsed);
    if (flags.dimension && *flags.dimension != setup.file.dimension)
      throw std::invalid_argument("--mode: " + std::to_string(*flags.dimension) +
                                  "d does not match the scene file " + setup.scene_path + ", which is " +
                                  std::to_string(setup.file.dimension) + "D");
  } else {
    setup.file.dimension = flags.dimension.value_or(3);
    setup.file.scene2d = demo_scene_2d();
    setup.file.scene3d = demo_scene_3d();
    if (setup.file.dimension == 2) setup.file.camera.theta_deg = kDemoTheta2DDegrees;  // --theta still wins
  }
  setup.dimension = setup.file.dimension;
  CameraPreset& preset = setup.file.camera;
  preset = merged(preset, flags.camera);

  if (preset.target && preset.target->size() != std::size_t(setup.dimension))
    throw std::invalid_argument("--target: expected " + std::string("x,y,z").substr(0, 2 * setup.dimension - 1) +
                                " for a " + std::to_string(setup.dimension) + "D scene");
  visit_view_setup(setup, [&](auto& camera, const auto&) { place(camera, preset, flags.camera); });
  return setup;
}

Camera2D demo_camera_2d() {
  CameraPreset preset;
  preset.theta_deg = kDemoTheta2DDegrees;
  return camera2d_from_preset(preset);
}

Camera2D camera2d_from_preset(const CameraPreset& preset) {
  if ((preset.target && preset.target->size() != 2) || (preset.size && preset.size->size() != 1) ||
      preset.res_rows)
    throw std::invalid_argument("camera: expected a 2-component target, size [N] and one res in 2D");
  Camera2D camera(preset.size ? (*preset.size)[0] : kDefaultSize2D);
  Orbit2D orbit;
  if (preset.target) orbit.target = {(*preset.target)[0], (*preset.target)[1]};
  if (preset.d) orbit.d = *preset.d;
  if (preset.theta_deg) orbit.theta = glm::radians(*preset.theta_deg);
  if (preset.df) orbit.df = *preset.df;
  camera.set_orbit(orbit);
  if (preset.res) camera.set_res(*preset.res);
  return camera;
}

Camera3D camera3d_from_preset(const CameraPreset& preset) {
  if ((preset.target && preset.target->size() != 3) ||
      (preset.size && preset.size->size() != 1 && preset.size->size() != 2))
    throw std::invalid_argument("camera: expected a 3-component target and size [N] or [columns, rows] in 3D");
  int columns = kDefaultSize3D, rows = kDefaultSize3D;
  if (preset.size) {
    columns = (*preset.size)[0];
    rows = preset.size->size() == 2 ? (*preset.size)[1] : columns;
  }
  Camera3D camera(columns, rows);
  Orbit3D orbit;
  if (preset.target) orbit.target = {(*preset.target)[0], (*preset.target)[1], (*preset.target)[2]};
  if (preset.d) orbit.d = *preset.d;
  if (preset.theta_deg) orbit.theta = glm::radians(*preset.theta_deg);
  if (preset.phi_deg) orbit.phi = glm::radians(*preset.phi_deg);
  if (preset.df) orbit.df = *preset.df;
  camera.set_orbit(orbit);
  if (preset.res) camera.set_res(*preset.res, preset.res_rows.value_or(*preset.res));
  return camera;
}

namespace {
// An angle as a file keeps it: the degrees the user set (30, not 29.999999999999996 from 30° → radians →
// degrees), to 1e-9 of a degree, far below any slider's or flag's step.
double degrees_for_file(double radians) {
  const double degrees = glm::degrees(radians);
  const double rounded = std::round(degrees * 1e9) / 1e9;
  return std::abs(rounded - degrees) <= 1e-9 ? rounded : degrees;
}
}  // namespace

CameraPreset preset_of(const Camera2D& camera) {
  CameraPreset preset;
  const Orbit2D& orbit = camera.orbit();
  preset.target = std::vector<double>{orbit.target.x, orbit.target.y};
  preset.d = orbit.d;
  preset.theta_deg = degrees_for_file(orbit.theta);
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
  preset.theta_deg = degrees_for_file(orbit.theta);
  preset.phi_deg = degrees_for_file(orbit.phi);
  preset.df = orbit.df;
  preset.res = camera.res_columns();
  if (camera.res_rows() != camera.res_columns()) preset.res_rows = camera.res_rows();
  preset.size = std::vector<int>{camera.max_columns(), camera.max_rows()};
  return preset;
}

namespace {
AngleRoute route_of(PlacementRoute placement) {
  return placement == PlacementRoute::arccos ? AngleRoute::handout_arccos : AngleRoute::stable;
}
}  // namespace

ColourMap render_with_accuracy(const ViewSetup& setup, const AccuracyFlags& flags) {
  return visit_view_setup(setup, [&](auto camera, const auto& scene) {
    if (flags.placement != PlacementRoute::orbit) {
      const auto orbit = camera.orbit();
      camera.set_free(camera.screen_centre(), orbit.target, orbit.df, route_of(flags.placement));
    }
    return render_with_accuracy(camera, scene, flags);
  });
}

}  // namespace raycam
