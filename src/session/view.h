// One view of the lesson: a scene, the camera that looks at it and what places that camera, in 2D or in 3D.
// The app keeps one per dimension (AppState::view on screen, AppState::other_view kept for switching back).
// Code that does the same in both dimensions is written once over View, with std::visit and the overloads
// below; only where 2D and 3D really differ (the 3D observer, a bar against an image) does it pick one.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "raycam/camera2d.h"
#include "raycam/languages.h"
#include "raycam/camera3d.h"
#include "raycam/ray_caster.h"
#include "raycam/scene.h"
#include "raycam/scene_file.h"
#include "raycam/view_setup.h"

namespace raycam::session {

struct View2D {
  static constexpr int kDimension = 2;
  static constexpr int kConstructionSteps = kConstructionSteps2D;  // the handout's frames a → d
  std::string scene_path;  // the file the scene came from; empty: the built-in demo
  Scene2D scene;
  Orbit2D orbit;   // the sliders' model: the camera is placed from it (place_cameras)
  Orbit2D preset;  // what the scene file and the command line opened with: "Reset camera" returns here
  int max_pixels = kDefaultSize2D;  // N
  Camera2D camera{kDefaultSize2D};
};

struct View3D {
  static constexpr int kDimension = 3;
  static constexpr int kConstructionSteps = kConstructionSteps3D;
  std::string scene_path;
  Scene3D scene;
  Orbit3D orbit;
  Orbit3D preset;
  int max_columns = kDefaultSize3D, max_rows = kDefaultSize3D;
  Camera3D camera{kDefaultSize3D, kDefaultSize3D};
};

using View = std::variant<View2D, View3D>;

// std::visit with one lambda per kind: std::visit(overloaded{[](View2D&) {…}, [](View3D&) {…}}, view).
template <class... Kinds>
struct overloaded : Kinds... {
  using Kinds::operator()...;
};
template <class... Kinds>
overloaded(Kinds...) -> overloaded<Kinds...>;

inline int dimension_of(const View& view) {
  return std::visit([](const auto& v) { return v.kDimension; }, view);
}

// ---- what generic code calls on either view (overloads, so that a generic lambda reads the same) ----
// The longest side the camera may use: N in 2D, max(W, H) in 3D.
inline int max_side(const View2D& view) { return view.max_pixels; }
inline int max_side(const View3D& view) { return std::max(view.max_columns, view.max_rows); }
// The scene's objects: objects_of(scene) (raycam/scene.h).
// The image a camera casts: image_columns/image_rows(camera) (raycam/view_setup.h).
// The primary rays one cast sends.
template <class Camera>
double ray_count(const Camera& camera) {
  return double(image_columns(camera)) * image_rows(camera);
}
// res as the sliders show it (3D: the columns' res).
inline double res_of(const Camera2D& camera) { return camera.res(); }
inline double res_of(const Camera3D& camera) { return camera.res_columns(); }
// How much res changes for a ratio of rays: one side in 2D, both in 3D.
// res on a camera: 2D has one; 3D has the columns' and, "non-square" on, the rows' (else the same).
inline void set_res_of(Camera2D& camera, double res, std::optional<double>) { camera.set_res(res); }
inline void set_res_of(Camera3D& camera, double res, std::optional<double> rows) {
  camera.set_res(res, rows.value_or(res));
}
inline double side_factor(const View2D&, double ray_ratio) { return ray_ratio; }
inline double side_factor(const View3D&, double ray_ratio) { return std::sqrt(ray_ratio); }
// The exact bar (the accuracy reference of a 2D colour bar) exists only in 2D.
inline bool exact_bar_applies(const View& view) { return std::holds_alternative<View2D>(view); }
// What the window shows differently: in 2D the image is a colour bar and the scene lies flat in the
// overhead view; in 3D the image is square-screened and an observer view shows the camera in space.
inline bool image_is_bar(const View& view) { return std::holds_alternative<View2D>(view); }
inline bool has_observer(const View& view) { return std::holds_alternative<View3D>(view); }
// The camera this view's sizes give for an orbit (res and mistakes applied by the caller's constructor).
inline Camera2D camera_for(const View2D& view, const Orbit2D& orbit, const ClassicMistakes& mistakes) {
  return Camera2D(view.max_pixels, orbit, mistakes);
}
inline Camera3D camera_for(const View3D& view, const Orbit3D& orbit, const ClassicMistakes& mistakes) {
  return Camera3D(view.max_columns, view.max_rows, orbit, mistakes);
}

// The views a scene file and the command line open with: the file's kind on screen (first), the other kind
// placed by the same flags, its scene as the setup has it (switch_dimension fills an empty one with the demo).
struct OpenedViews {
  View on_screen;
  View other;
};
OpenedViews views_from_setup(const ViewSetup& setup);
// The fast casters on a view: the 2D scene as it is, the 3D scene as `packed` (pack_scene: packing is not a
// cast's cost, so the caller packs once per scene).
void pack_scene(const View& view, PackedScene3D& packed);
void cast_view(const View& view, const PackedScene3D& packed, ColourMap& map, const CastOptions& options,
               CastStats* stats);
// The scene's own rules (raycam/scene.h's validate): throws std::invalid_argument.
void validate(const View& view);
// The scene file holding a view's scene and a camera preset (for saving and for the checker's case).
SceneFile scene_file_of(const View& view, const CameraPreset& camera);

// The names the window shows (the inspector, the figures): the built-in demo is raycam's own scene (scenes/
// classic2d.json and classic3d.json name its objects in English), so its names follow the window's language;
// a file's names stay as written.
std::string shown_object_name(Language language, const View& view, std::size_t id);
// The view's scene with those names (for a figure drawn in the window's language).
Scene2D scene_as_shown(Language language, const View2D& view);
Scene3D scene_as_shown(Language language, const View3D& view);

}  // namespace raycam::session
