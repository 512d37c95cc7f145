#include "app_state.h"

#include <chrono>
#include <cmath>
#include <exception>
#include <glm/trigonometric.hpp>
#include <stdexcept>
#include <string>

#include "raycam/view_setup.h"
#include "text.h"

namespace raycam::ui {

void adopt_view_setup(AppState& state, const ViewSetup& setup) {
  state.file = setup.file;
  state.scene_path = setup.scene_path;
  state.dimension = setup.dimension;
  state.orbit2d = setup.camera2d.orbit();
  state.orbit3d = setup.camera3d.orbit();
  state.res = setup.dimension == 2 ? setup.camera2d.res() : setup.camera3d.res_columns();
  state.max_pixels_2d = setup.camera2d.max_pixels();
  state.max_columns_3d = setup.camera3d.max_columns();
  state.max_rows_3d = setup.camera3d.max_rows();
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

bool recast_if_needed(AppState& state, bool interacting) {
  if (!state.cameras_dirty && !(state.refine_pending && !interacting)) return false;
  try {
    place_cameras(state);
  } catch (const std::exception& error) {  // a parameter out of range: keep the last image, say why
    state.message = error.what();
    state.message_is_error = true;
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
    else state.camera3d.set_res(std::max(state.res * factor, 1.0 / std::max(state.max_columns_3d, state.max_rows_3d)));
  }
  const auto start = std::chrono::steady_clock::now();
  bool cast = false;
  if (uses_reference_caster(state)) {
    AccuracyFlags knobs = state.accuracy;
    knobs.exact = knobs.exact && is_2d;
    try {
      state.map = is_2d ? render_with_accuracy(state.camera2d, state.file.scene2d, knobs)
                        : render_with_accuracy(state.camera3d, state.file.scene3d, knobs);
      const long long objects = is_2d ? state.file.scene2d.circles.size() : state.file.scene3d.spheres.size();
      state.stats = CastStats{static_cast<long long>(rays),
                              static_cast<long long>(rays) * objects * knobs.options.samples_per_pixel, 0, 0};
      cast = true;
    } catch (const std::invalid_argument& error) {  // e.g. the exact bar refuses a huge scene: say so, draw fast
      state.message = std::string(error.what()) + " (drawn with the fast caster)";
      state.message_is_error = true;
    }
  }
  if (!cast) {
    CastOptions options = state.cast_options;
    options.formula = state.accuracy.options.formula;
    if (is_2d) cast_primary_rays(state.camera2d, state.file.scene2d, state.map, options, &state.stats);
    else cast_primary_rays(state.camera3d, state.file.scene3d, state.map, options, &state.stats);
  }
  state.cast_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!state.refine_pending && state.stats.rays >= 10000) state.ns_per_ray = state.cast_ms * 1e6 / double(state.stats.rays);
  state.cameras_dirty = false;
  ++state.map_version;
  ++state.cast_count;
  return true;
}

bool open_scene(AppState& state, const std::string& path) {
  try {
    ViewFlags flags;
    flags.scene_path = path;
    const ViewSetup setup = make_view_setup(flags);
    if (setup.dimension == 2) validate(setup.file.scene2d);
    else validate(setup.file.scene3d);
    adopt_view_setup(state, setup);
    state.pinned_pixel.reset();
    state.construction_step = -1;
    ++state.scene_version;
    state.cameras_dirty = true;
    state.message = trf("opened %s", path.c_str());
    state.message_is_error = false;
    return true;
  } catch (const std::exception& error) {
    state.message = error.what();  // the scene on screen stays as it was
    state.message_is_error = true;
    return false;
  }
}

bool save_preset(AppState& state, const std::string& path) {
  try {
    place_cameras(state);
    SceneFile file = state.file;
    file.camera = state.dimension == 2 ? preset_of(state.camera2d) : preset_of(state.camera3d);
    if (state.arccos_route) {  // save what the student set, not what the mistake produced
      file.camera.theta_deg = glm::degrees(state.dimension == 2 ? state.orbit2d.theta : state.orbit3d.theta);
      if (state.dimension == 3) file.camera.phi_deg = glm::degrees(state.orbit3d.phi);
    }
    save_scene_file(file, path);
    state.message = trf("saved the camera preset to %s", path.c_str());
    state.message_is_error = false;
    return true;
  } catch (const std::exception& error) {
    state.message = error.what();
    state.message_is_error = true;
    return false;
  }
}

void switch_dimension(AppState& state, int dimension) {
  if (dimension == state.dimension) return;
  if (!state.scene_path.empty()) {  // a file holds one kind of scene: use the demo of the other kind
    state.scene_path.clear();
    state.message = trf("switched to the built-in %dD demo scene", dimension);
    state.message_is_error = false;
  }
  state.file.dimension = dimension;
  if (dimension == 2 && state.file.scene2d.circles.empty()) state.file.scene2d = demo_scene_2d();
  if (dimension == 3 && state.file.scene3d.spheres.empty()) state.file.scene3d = demo_scene_3d();
  state.dimension = dimension;
  state.construction_step = -1;
  state.pinned_pixel.reset();
  ++state.scene_version;
  state.cameras_dirty = true;
}

int construction_steps(const AppState& state) {
  return state.dimension == 2 ? kConstructionSteps2D : kConstructionSteps3D;
}

}  // namespace raycam::ui
