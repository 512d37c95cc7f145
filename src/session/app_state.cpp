#include "session/app_state.h"

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
#include "session/shown_files.h"
#include "session/text.h"

namespace raycam::session {

void adopt_view_setup(Lesson& state, Display& display, const ViewSetup& setup) {
  OpenedViews views = views_from_setup(setup);  // the file's scene is of one kind: the other's is the demo
  state.view = std::move(views.on_screen);
  state.other_view = std::move(views.other);
  ++state.scene_version;  // new objects: what was packed or uploaded from the old ones is stale
  state.opened_version = state.scene_version;
  state.res = std::visit([](const auto& view) { return res_of(view.camera); }, state.view);
  // The rows' res of a non-square 3D preset (the handout's second resolution variable; a 2D setup has none:
  // its file and flags refuse a second res).
  state.res_rows = setup.file.camera.res_rows;
  state.preset_res = state.res;
  state.preset_res_rows = state.res_rows;
  display.overhead_fit_pending = true;
}

void reset_camera(Lesson& state, Display& display) {
  std::visit([](auto& view) { view.orbit = view.preset; }, state.view);
  state.res = state.preset_res;
  state.res_rows = state.preset_res_rows;
  display.overhead_fit_pending = true;
  state.cameras_dirty = true;
}

void place_cameras(Lesson& state) {
  // One Camera per change, M_d composed once in its constructor. The arccos route re-derives the angles
  // from P and C as the handout's free placement does (the mistake near a pole).
  std::visit(
      [&](auto& view) {
        auto orbit = view.orbit;
        if (state.arccos_route)
          orbit = free_orbit(orbit_screen_centre(orbit), orbit.target, orbit.df, AngleRoute::handout_arccos);
        auto camera = camera_for(view, orbit, state.mistakes);
        set_res_of(camera, state.res, state.res_rows);
        view.camera = camera;
      },
      state.view);
}

bool uses_reference_caster(const Lesson& state) {
  return needs_reference_caster(state.accuracy.options, state.accuracy.exact && exact_bar_applies(state.view));
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
    set_message(state, MessageSource::camera, true, tr_reason(state.language, error.what()));
    state.cameras_dirty = false;
    return false;
  }
  const double rays = std::visit([](const auto& view) { return ray_count(view.camera); }, state.view);
  // Per ray, not per object: the accelerated casters' cost follows what the pixels see, not the object count.
  const double predicted_ms = rays * state.ns_per_ray * 1e-6;
  state.refine_pending = interacting && predicted_ms > kInteractiveBudgetMs;
  if (state.refine_pending)  // fewer rays in proportion: res scales one side in 2D, both in 3D
    std::visit(
        [&](auto& view) {
          const double factor = side_factor(view, kInteractiveBudgetMs / predicted_ms);
          const double least = 1.0 / max_side(view);
          const std::optional<double> rows =
              state.res_rows ? std::optional<double>(std::max(*state.res_rows * factor, least)) : std::nullopt;
          set_res_of(view.camera, std::max(state.res * factor, least), rows);
        },
        state.view);
  remember_pin_point(state);
  // A new scene is packed once, before the clock starts: packing 10⁵ spheres (14 ms, their clusters) is not a
  // cast's cost, and counted in it, it would have shown a cast 7 times slower and made the next drag coarser.
  if (state.packed_version != state.scene_version) {
    pack_scene(state.view, state.packed3d);
    state.packed_version = state.scene_version;
  }
  const auto start = std::chrono::steady_clock::now();
  bool cast = false;
  if (uses_reference_caster(state)) {
    AccuracyFlags knobs = state.accuracy;
    knobs.exact = knobs.exact && exact_bar_applies(state.view);
    try {
      state.map = std::visit([&](const auto& view) { return render_with_accuracy(view.camera, view.scene, knobs); },
                             state.view);
      const long long objects = active_object_count(state);
      state.stats = CastStats{static_cast<long long>(rays),
                              static_cast<long long>(rays) * objects * knobs.options.samples_per_pixel, 0, 0};
      cast = true;
    } catch (const std::invalid_argument& error) {  // e.g. the exact bar refuses a huge scene: say so, draw fast
      set_message(state, MessageSource::caster, true,
                  tr_reason(state.language, error.what()) + tr(state.language, " (drawn with the fast caster)"));
    }
  }
  if (!cast) {
    CastOptions options = state.cast_options;
    options.formula = state.accuracy.options.formula;
    cast_view(state.view, state.packed3d, state.map, options, &state.stats);
  }
  state.cast_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!state.refine_pending && state.stats.rays >= 10000) state.ns_per_ray = state.cast_ms * 1e6 / double(state.stats.rays);
  state.cameras_dirty = false;
  place_pin(state);
  ++state.map_version;
  ++state.cast_count;
  return true;
}

std::string cannot_open_message(Language language, const std::string& path, const std::string& reason) {
  const std::string shown = tr_reason(language, reason);
  return reason.find(path) == std::string::npos ? trf(language, "cannot open %s: %s", path.c_str(), shown.c_str())
                                                : trf(language, "cannot open: %s", shown.c_str());
}

bool open_scene(AppState& state, const std::string& path) {
  return open_scene(state, path, [&] { return load_scene_file(path); });
}

bool open_scene(AppState& state, const std::string& path, const std::function<SceneFile()>& read) {
  if (path.empty()) {  // Open with an empty box: what to do, not "cannot open: : ..."
    set_message(state, MessageSource::files, true, tr(state.language, "type a scene file's path in the box, then Open"));
    return false;
  }
  try {
    ViewFlags flags;
    flags.scene_path = path;
    const ViewSetup setup = make_view_setup(flags, read());
    validate(views_from_setup(setup).on_screen);  // before anything changes: a bad file leaves the state as it was
    adopt_view_setup(state, state, setup);
    state.pinned_pixel.reset();
    state.construction_step = -1;
    state.construction_fraction = 1.0;
    state.mistake_look_at.clear();  // a "show me" pointed at the old scene's objects
    state.cameras_dirty = true;
    ++state.scene_opens;
    set_message(state, MessageSource::files, false, trf(state.language, "opened %s", shown_file_name(state.host, path).c_str()));
    return true;
  } catch (const std::exception& error) {
    // The scene and the camera stay as they were; the Open box keeps what was typed (a typo is fixed in
    // place, not retyped); the message names the file and the reason.
    set_message(state, MessageSource::files, true,
                with_file_shown(state.host, cannot_open_message(state.language, path, error.what()), path));
    return false;
  }
}

bool save_preset(AppState& state, const std::string& path) {
  try {
    place_cameras(state);
    CameraPreset preset = active_preset(state);
    if (state.arccos_route) {  // save what the student set, not what the mistake produced
      preset.theta_deg = glm::degrees(active_orbit(state).theta);
      if (const auto* view = std::get_if<View3D>(&state.view)) preset.phi_deg = glm::degrees(view->orbit.phi);
    }
    const SceneFile file = scene_file_of(state.view, preset);
    save_scene_file(file, path);
    set_message(state, MessageSource::files, false,
                trf(state.language, state.host.files_are_downloads ? "asked the browser to save the camera preset as %s"
                                                                   : "saved the camera preset to %s",
                    shown_file_name(state.host, path).c_str()));
    return true;
  } catch (const std::exception& error) {
    set_message(state, MessageSource::files, true,
                with_file_shown(state.host, trf(state.language, "cannot save: %s", tr_reason(state.language, error.what()).c_str()), path));
    return false;
  }
}

SaveAsOutcome save_preset_as(AppState& state, const std::string& path, bool overwrite) {
  if (path.empty()) {
    set_message(state, MessageSource::files, true, tr(state.language, "Save as: type the path of the file to write"));
    return SaveAsOutcome::failed;
  }
  // A download never replaces anything: the browser keeps both files.
  if (!overwrite && !state.host.files_are_downloads && std::filesystem::exists(path))
    return SaveAsOutcome::needs_yes;  // nothing is written yet
  return save_preset(state, path) ? SaveAsOutcome::saved : SaveAsOutcome::failed;
}

void toggle_maximised(Display& display, ShownView view) {
  display.maximised = display.maximised == view ? ShownView::all : view;
}

void set_message(Messages& messages, MessageSource source, bool is_error, std::string text) {
  messages.message = std::move(text);
  messages.message_is_error = is_error;
  messages.message_source = source;
  messages.message_since = -1.0;  // a new message (or the same one again) is read from its start
}

bool age_message(Messages& messages, double now) {
  if (messages.message.empty()) return false;
  if (messages.message_since < 0.0) messages.message_since = now;
  if (messages.message_is_error) return false;
  if (now - messages.message_since < kConfirmationSeconds) return true;
  messages.message.clear();
  return false;
}

std::string next_screenshot_path(Language language, const std::string& directory) {
  for (int i = 1;; ++i) {
    char name[64];
    std::snprintf(name, sizeof name, "%s-%03d.png", tr(language, "raycam-screenshot"), i);
    const std::filesystem::path path = std::filesystem::path(directory) / name;
    if (!std::filesystem::exists(path) || i >= 99999) return path.lexically_normal().string();
  }
}

void request_screenshot(HostLink& host, Language language) {
  std::error_code ignored;
  host.requests.ask(HostRequestKind::screenshot,
                    std::filesystem::absolute(next_screenshot_path(language), ignored).lexically_normal().string());
}

std::string window_title(const Lesson& state) {
  const std::string scene = scene_path(state).empty() ? std::string(tr(state.language, "demo scene"))
                                                      : std::filesystem::path(scene_path(state)).filename().string();
  return "raycam — " + std::to_string(dimension(state)) + "D — " + scene;
}

void switch_dimension(AppState& state, int dimension) {
  if (dimension == session::dimension(state)) return;
  const bool left_a_file = !scene_path(state).empty();
  // The note that the view on screen is the demo goes with it: left there, it would still say "demo" over
  // the file the switch comes back to.
  const std::string demo_note = trf(state.language, "switched to the built-in %dD demo scene", dimension_of(state.view));
  if (!state.message_is_error && state.message == demo_note) state.message.clear();
  std::swap(state.view, state.other_view);
  if (scene_path(state).empty() && left_a_file)  // leaving a file for the other kind's demo
    set_message(state, MessageSource::camera, false, trf(state.language, "switched to the built-in %dD demo scene", dimension));
  std::visit(overloaded{[](View2D& view) { if (view.scene.circles.empty()) view.scene = demo_scene_2d(); },
                        [](View3D& view) { if (view.scene.spheres.empty()) view.scene = demo_scene_3d(); }},
             state.view);
  state.overhead_fit_pending = true;
  state.construction_step = -1;
  state.construction_fraction = 1.0;
  state.pinned_pixel.reset();
  ++state.scene_version;
  state.cameras_dirty = true;
}

int dimension(const Lesson& state) { return dimension_of(state.view); }

namespace {
template <class Wanted, class State>
auto& view_of_kind(State& state) {  // the one of the two views that is of this kind
  auto* on_screen = std::get_if<Wanted>(&state.view);
  return on_screen ? *on_screen : std::get<Wanted>(state.other_view);
}
}  // namespace
View2D& view2d(Lesson& state) { return view_of_kind<View2D>(state); }
const View2D& view2d(const Lesson& state) { return view_of_kind<View2D>(state); }
View3D& view3d(Lesson& state) { return view_of_kind<View3D>(state); }
const View3D& view3d(const Lesson& state) { return view_of_kind<View3D>(state); }

const std::string& scene_path(const Lesson& state) {
  return std::visit([](const auto& view) -> const std::string& { return view.scene_path; }, state.view);
}

SharedOrbit<double> active_orbit(Lesson& state) {
  return std::visit([](auto& view) { return SharedOrbit<double>{view.orbit.theta, view.orbit.d, view.orbit.df}; },
                    state.view);
}

SharedOrbit<const double> active_orbit(const Lesson& state) {
  return std::visit(
      [](const auto& view) { return SharedOrbit<const double>{view.orbit.theta, view.orbit.d, view.orbit.df}; },
      state.view);
}

glm::dvec2 active_target_xy(const Lesson& state) {
  return std::visit([](const auto& view) { return glm::dvec2(view.orbit.target); }, state.view);
}

int active_max_side(const Lesson& state) {
  return std::visit([](const auto& view) { return max_side(view); }, state.view);
}

std::size_t active_object_count(const Lesson& state) {
  return std::visit([](const auto& view) { return objects_of(view.scene).size(); }, state.view);
}

CameraPreset active_preset(const Lesson& state) {
  return std::visit([](const auto& view) { return preset_of(view.camera); }, state.view);
}

int construction_steps(const Lesson& state) {
  return std::visit([](const auto& view) { return view.kConstructionSteps; }, state.view);
}

}  // namespace raycam::session
