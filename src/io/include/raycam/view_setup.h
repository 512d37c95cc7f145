// A scene and a placed camera, built from an optional scene file and command-line flags (shared by
// `raycam-cli render`, `raycam-cli shot` and the app's command line). Precedence: built-in defaults, then
// the scene file's camera preset, then flags. Angles are in DEGREES here, radians once in the cameras.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "raycam/accuracy_options.h"
#include "raycam/camera2d.h"
#include "raycam/camera3d.h"
#include "raycam/scene_file.h"

namespace raycam {

// What the command line sets (parsed and range-checked by src/flags' camera option group).
struct ViewFlags {
  std::optional<std::string> scene_path;
  std::optional<int> dimension;  // --mode 2d|3d
  CameraPreset camera;           // --target --d --theta --phi --df --res --size
};

// The built-in 2D demo's camera angle θ, in degrees (the core's default, 90°, stays for a file that sets
// none). At 90° the construction's rotation R(θ − 90°) is the identity, so its step c showed the very picture
// of step b; at 70° every step moves the camera, and the bar still shows all four circles.
inline constexpr double kDemoTheta2DDegrees = 70.0;
// The 2D demo's camera: the core's defaults but θ.
Camera2D demo_camera_2d();

struct ViewSetup {
  int dimension = 3;
  std::string scene_path;  // empty: the built-in demo scene
  SceneFile file;          // scene and the camera preset in effect (defaults ⊕ file ⊕ flags)
  Camera2D camera2d = demo_camera_2d();  // the other kind's camera when the setup is 3D: the 2D demo's
  Camera3D camera3d{256, 256};
};

inline constexpr int kDefaultSize2D = 256;
inline constexpr int kDefaultSize3D = 256;

// The image a camera casts: N × 1 in 2D (the colour bar), W × H in 3D.
inline int image_columns(const Camera2D& camera) { return camera.pixel_count(); }
inline int image_rows(const Camera2D&) { return 1; }
inline int image_columns(const Camera3D& camera) { return camera.columns(); }
inline int image_rows(const Camera3D& camera) { return camera.rows(); }

// Calls function(camera, scene) with the setup's placed camera and its scene, 2D or 3D, as std::visit does on
// a variant (visit_scene's pair for a whole view): the same in both dimensions is written once.
template <class Setup, class Function>
decltype(auto) visit_view_setup(Setup& setup, Function&& function) {
  if (setup.dimension == 2) return function(setup.camera2d, setup.file.scene2d);
  return function(setup.camera3d, setup.file.scene3d);
}

// Loads the scene (or the demo scene) and places the camera. Throws std::invalid_argument.
ViewSetup make_view_setup(const ViewFlags& flags);
// The same with the scene file already parsed (`parsed`, read from flags.scene_path; none: the demo scene):
// the page parses a big file over several frames first (src/web/scene_loading.cpp).
ViewSetup make_view_setup(const ViewFlags& flags, std::optional<SceneFile> parsed);

// The colour map with the accuracy knobs applied: the camera re-placed by the chosen route (same P, C, d_f)
// first, then render_with_accuracy(camera, scene, knobs) of the core.
ColourMap render_with_accuracy(const ViewSetup& setup, const AccuracyFlags& flags);

// The camera a preset places: the fields it sets over the defaults (Orbit2D{} / Orbit3D{}, res 1, size
// kDefaultSize2D / kDefaultSize3D; a 3D size N is N×N). Degrees become radians here and nowhere else. The
// core's rules apply (std::invalid_argument naming the field); a target or size with the wrong number of
// components is the caller's to report in its own words (also std::invalid_argument here).
Camera2D camera2d_from_preset(const CameraPreset& preset);
Camera3D camera3d_from_preset(const CameraPreset& preset);

// The camera preset equivalent to a camera's current state (for saving presets).
CameraPreset preset_of(const Camera2D& camera);
CameraPreset preset_of(const Camera3D& camera);

}  // namespace raycam
