#include "app_state.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <glm/trigonometric.hpp>
#include <stdexcept>
#include <string>

#include "raycam/view_setup.h"
#include "text.h"

namespace raycam::session {

void adopt_view_setup(AppState& state, const ViewSetup& setup) {
  state.file = setup.file;
  state.other_scene_path.clear();  // the new file's scene is of one kind: the other kind's is the demo
  ++state.scene_version;  // new objects: what was packed or uploaded from the old ones is stale
  state.scene_path = setup.scene_path;
  state.dimension = setup.dimension;
  state.orbit2d = setup.camera2d.orbit();
  state.orbit3d = setup.camera3d.orbit();
  state.res = setup.dimension == 2 ? setup.camera2d.res() : setup.camera3d.res_columns();
  state.max_pixels_2d = setup.camera2d.max_pixels();
  state.max_columns_3d = setup.camera3d.max_columns();
  state.max_rows_3d = setup.camera3d.max_rows();
  state.preset_orbit2d = state.orbit2d;
  state.preset_orbit3d = state.orbit3d;
  state.preset_res = state.res;
  state.overhead_fit_pending = true;
}

void reset_camera(AppState& state) {
  if (state.dimension == 2)
    state.orbit2d = state.preset_orbit2d;
  else
    state.orbit3d = state.preset_orbit3d;
  state.res = state.preset_res;
  state.overhead_fit_pending = true;
  state.cameras_dirty = true;
}

void place_cameras(AppState& state) {
  // One Camera per change, M_d composed once in its constructor. The arccos route re-derives the angles
  // from P and C as the handout's free placement does (the mistake near a pole).
  if (state.dimension == 2) {
    const Orbit2D& o = state.orbit2d;
    const Orbit2D orbit = state.arccos_route
                              ? free_orbit(orbit_screen_centre(o), o.target, o.df, AngleRoute::handout_arccos)
                              : o;
    Camera2D camera(state.max_pixels_2d, orbit, state.mistakes);
    camera.set_res(state.res);
    state.camera2d = camera;
  } else {
    const Orbit3D& o = state.orbit3d;
    const Orbit3D orbit = state.arccos_route
                              ? free_orbit(orbit_screen_centre(o), o.target, o.df, AngleRoute::handout_arccos)
                              : o;
    Camera3D camera(state.max_columns_3d, state.max_rows_3d, orbit, state.mistakes);
    camera.set_res(state.res);
    state.camera3d = camera;
  }
}

bool uses_reference_caster(const AppState& state) {
  return needs_reference_caster(state.accuracy.options, state.accuracy.exact && state.dimension == 2);
}

namespace {
// The pin follows res: it keeps its canonical point (its pixel's centre, as a fraction of the image's width
// and height, taken in the image it was pinned in), and each new image pins the pixel that covers that point,
// so changing res or a coarse preview during a drag never drops it nor lets it drift.
void remember_pin_point(AppState& state) {
  if (!state.pinned_pixel) {
    state.pin_point.reset();
    return;
  }
  const bool moved_by_user = !state.pin_point || state.pinned_pixel->row != state.pin_placed.row ||
                             state.pinned_pixel->column != state.pin_placed.column;
  if (moved_by_user && state.map.width > 0 && state.map.height > 0)
    state.pin_point = glm::dvec2((state.pinned_pixel->column + 0.5) / state.map.width,
                                 (state.pinned_pixel->row + 0.5) / state.map.height);
}
void place_pin(AppState& state) {
  if (!state.pinned_pixel || !state.pin_point) return;
  const auto cell = [](double fraction, int count) {
    return std::clamp(int(std::floor(fraction * count)), 0, std::max(count - 1, 0));
  };
  state.pinned_pixel = PixelIndex{cell(state.pin_point->y, state.map.height), cell(state.pin_point->x, state.map.width)};
  state.pin_placed = *state.pinned_pixel;
}
}  // namespace

bool recast_if_needed(AppState& state, bool interacting) {
  if (!state.cameras_dirty && !(state.refine_pending && !interacting)) return false;
  try {
    place_cameras(state);
  } catch (const std::exception& error) {  // a parameter out of range: keep the last image, say why
    set_message(state, MessageSource::camera, true, tr_reason(error.what()));
    state.cameras_dirty = false;
    return false;
  }
  const bool is_2d = state.dimension == 2;
  const double rays = is_2d ? state.camera2d.pixel_count() : double(state.camera3d.columns()) * state.camera3d.rows();
  // Per ray, not per object: the accelerated casters' cost follows what the pixels see, not the object count.
  const double predicted_ms = rays * state.ns_per_ray * 1e-6;
  state.refine_pending = interacting && predicted_ms > kInteractiveBudgetMs;
  if (state.refine_pending) {  // fewer rays in proportion: res scales both sides in 3D
    const double factor = is_2d ? kInteractiveBudgetMs / predicted_ms : std::sqrt(kInteractiveBudgetMs / predicted_ms);
    if (is_2d) state.camera2d.set_res(std::max(state.res * factor, 1.0 / state.max_pixels_2d));
    else
      state.camera3d.set_res(std::max(state.res * factor, 1.0 / active_max_side(state)));
  }
  remember_pin_point(state);
  // A new scene is packed once, before the clock starts: packing 10⁵ spheres (14 ms, their clusters) is not a
  // cast's cost, and counted in it, it would have shown a cast 7 times slower and made the next drag coarser.
  if (!is_2d && state.packed_version != state.scene_version) {
    state.packed3d.pack(state.file.scene3d);
    state.packed_version = state.scene_version;
  }
  const auto start = std::chrono::steady_clock::now();
  bool cast = false;
  if (uses_reference_caster(state)) {
    AccuracyFlags knobs = state.accuracy;
    knobs.exact = knobs.exact && is_2d;
    try {
      state.map = is_2d ? render_with_accuracy(state.camera2d, state.file.scene2d, knobs)
                        : render_with_accuracy(state.camera3d, state.file.scene3d, knobs);
      const long long objects = active_object_count(state);
      state.stats = CastStats{static_cast<long long>(rays),
                              static_cast<long long>(rays) * objects * knobs.options.samples_per_pixel, 0, 0};
      cast = true;
    } catch (const std::invalid_argument& error) {  // e.g. the exact bar refuses a huge scene: say so, draw fast
      set_message(state, MessageSource::caster, true,
                  tr_reason(error.what()) + tr(" (drawn with the fast caster)"));
    }
  }
  if (!cast) {
    CastOptions options = state.cast_options;
    options.formula = state.accuracy.options.formula;
    if (is_2d) {
      cast_primary_rays(state.camera2d, state.file.scene2d, state.map, options, &state.stats);
    } else {
      cast_primary_rays(state.camera3d, state.packed3d, state.map, options, &state.stats);
    }
  }
  state.cast_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!state.refine_pending && state.stats.rays >= 10000) state.ns_per_ray = state.cast_ms * 1e6 / double(state.stats.rays);
  state.cameras_dirty = false;
  place_pin(state);
  ++state.map_version;
  ++state.cast_count;
  return true;
}

std::string cannot_open_message(const std::string& path, const std::string& reason) {
  const std::string shown = tr_reason(reason);
  return reason.find(path) == std::string::npos ? trf("cannot open %s: %s", path.c_str(), shown.c_str())
                                                : trf("cannot open: %s", shown.c_str());
}

bool open_scene(AppState& state, const std::string& path) {
  if (path.empty()) {  // Open with an empty box: what to do, not "cannot open: : ..."
    set_message(state, MessageSource::files, true, tr("type a scene file's path in the box, then Open"));
    return false;
  }
  try {
    ViewFlags flags;
    flags.scene_path = path;
    const ViewSetup setup = make_view_setup(flags);
    if (setup.dimension == 2) validate(setup.file.scene2d);
    else validate(setup.file.scene3d);
    adopt_view_setup(state, setup);
    state.pinned_pixel.reset();
    state.construction_step = -1;
    state.cameras_dirty = true;
    state.path_input = path;
    state.save_path.clear();  // Save as starts empty: never the file just opened unless the user types it
    state.overwrite_pending.clear();
    set_message(state, MessageSource::files, false, trf("opened %s", path.c_str()));
    return true;
  } catch (const std::exception& error) {
    // The scene, the camera and the Open box stay as they were; the message names the file and the reason.
    state.path_input = state.scene_path;
    set_message(state, MessageSource::files, true, cannot_open_message(path, error.what()));
    return false;
  }
}

bool save_preset(AppState& state, const std::string& path) {
  try {
    place_cameras(state);
    SceneFile file = state.file;
    file.camera = active_preset(state);
    if (state.arccos_route) {  // save what the student set, not what the mistake produced
      file.camera.theta_deg = glm::degrees(active_orbit(state).theta);
      if (state.dimension == 3) file.camera.phi_deg = glm::degrees(state.orbit3d.phi);
    }
    save_scene_file(file, path);
    set_message(state, MessageSource::files, false, trf("saved the camera preset to %s", path.c_str()));
    return true;
  } catch (const std::exception& error) {
    set_message(state, MessageSource::files, true, trf("cannot save: %s", tr_reason(error.what()).c_str()));
    return false;
  }
}

bool save_preset_as(AppState& state, std::string path, bool overwrite) {
  // `path` is a copy: the Replace button passes state.overwrite_pending itself, cleared on the next line.
  state.overwrite_pending.clear();
  if (path.empty()) {
    set_message(state, MessageSource::files, true, tr("Save as: type the path of the file to write"));
    return false;
  }
  if (!overwrite && std::filesystem::exists(path)) {
    state.overwrite_pending = path;  // the panel asks; nothing is written yet
    return false;
  }
  return save_preset(state, path);
}

void set_message(AppState& state, MessageSource source, bool is_error, std::string text) {
  state.message = std::move(text);
  state.message_is_error = is_error;
  state.message_source = source;
}

std::string next_screenshot_path(const std::string& directory) {
  for (int i = 1;; ++i) {
    char name[64];
    std::snprintf(name, sizeof name, "raycam-screenshot-%03d.png", i);
    const std::filesystem::path path = std::filesystem::path(directory) / name;
    if (!std::filesystem::exists(path) || i >= 99999) return path.lexically_normal().string();
  }
}

void request_screenshot(AppState& state) {
  std::error_code ignored;
  state.screenshot_path =
      std::filesystem::absolute(next_screenshot_path(), ignored).lexically_normal().string();
  state.request_screenshot = true;
}

std::string window_title(const AppState& state) {
  const std::string scene = state.scene_path.empty()
                                ? std::string(tr("demo scene"))
                                : std::filesystem::path(state.scene_path).filename().string();
  return "raycam — " + std::to_string(state.dimension) + "D — " + scene;
}

void switch_dimension(AppState& state, int dimension) {
  if (dimension == state.dimension) return;
  std::swap(state.scene_path, state.other_scene_path);
  if (state.scene_path.empty() && !state.other_scene_path.empty())  // leaving a file for the other kind's demo
    set_message(state, MessageSource::camera, false, trf("switched to the built-in %dD demo scene", dimension));
  state.file.dimension = dimension;
  if (dimension == 2 && state.file.scene2d.circles.empty()) state.file.scene2d = demo_scene_2d();
  if (dimension == 3 && state.file.scene3d.spheres.empty()) state.file.scene3d = demo_scene_3d();
  state.dimension = dimension;
  state.overhead_fit_pending = true;
  state.construction_step = -1;
  state.pinned_pixel.reset();
  ++state.scene_version;
  state.cameras_dirty = true;
}

SharedOrbit<double> active_orbit(AppState& state) {
  if (state.dimension == 2) return {state.orbit2d.theta, state.orbit2d.d, state.orbit2d.df};
  return {state.orbit3d.theta, state.orbit3d.d, state.orbit3d.df};
}

SharedOrbit<const double> active_orbit(const AppState& state) {
  if (state.dimension == 2) return {state.orbit2d.theta, state.orbit2d.d, state.orbit2d.df};
  return {state.orbit3d.theta, state.orbit3d.d, state.orbit3d.df};
}

glm::dvec2 active_target_xy(const AppState& state) {
  return state.dimension == 2 ? state.orbit2d.target : glm::dvec2(state.orbit3d.target);
}

int active_max_side(const AppState& state) {
  return state.dimension == 2 ? state.max_pixels_2d : std::max(state.max_columns_3d, state.max_rows_3d);
}

std::size_t active_object_count(const AppState& state) {
  return state.dimension == 2 ? state.file.scene2d.circles.size() : state.file.scene3d.spheres.size();
}

CameraPreset active_preset(const AppState& state) {
  return state.dimension == 2 ? preset_of(state.camera2d) : preset_of(state.camera3d);
}

int construction_steps(const AppState& state) {
  return state.dimension == 2 ? kConstructionSteps2D : kConstructionSteps3D;
}

}  // namespace raycam::session
