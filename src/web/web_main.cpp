// raycam in a browser page: the options come from the page's address (?lang=fr|en, ?scene=NAME of scenes/)
// and the browser's language, the frame is the desktop's (web_host.cpp), and a few functions are callable
// from JavaScript (the file picker, the browser tests).
#include <emscripten.h>
#include <imgui_internal.h>
#include <unistd.h>

#include <algorithm>
#include <map>
#include <memory>
#include <cstdio>
#include <vector>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "session/app_options.h"
#include "session/app_state.h"
#include "flags/flag_values.h"
#include "ui/panels.h"
#include "raycam/ray_caster.h"
#include "raycam/image_files.h"
#include "raycam/language.h"
#include "raycam/scene.h"
#include "raycam/view_setup.h"
#include "web/scene_loading.h"
#include "session/shown_files.h"
#include "session/text.h"
#include "web/web_host.h"

namespace {
// The value of `key` in the page address's query, or nothing.
std::string query_value(const char* key) {
  char* value = reinterpret_cast<char*>(EM_ASM_INT(
      {
        const found = new URLSearchParams(window.location.search).get(UTF8ToString($0));
        return found === null ? 0 : allocateUTF8(found);
      },
      key));
  if (!value) return {};
  std::string text(value);
  std::free(value);
  return text;
}

std::string browser_language() {
  char* value = reinterpret_cast<char*>(EM_ASM_INT({ return allocateUTF8(navigator.language || "en"); }));
  std::string text(value);
  std::free(value);
  return text;
}

std::string last_error;

// The ids of a view's primary rays (as `raycam-cli render --ids` casts them) written to `ids_path`; 0, or 1
// with last_error set.
int write_view_ids(const raycam::session::View& view, const char* ids_path) {
  try {
    raycam::session::validate(view);
    raycam::write_ids(std::visit([](const auto& v) { return raycam::cast_primary_rays(v.camera, v.scene, raycam::CastOptions{}); },
                                 view),
                      ids_path);
    return 0;
  } catch (const std::exception& error) {
    last_error = error.what();
    return 1;
  }
}
}  // namespace

extern "C" {
// The file picker's file (written into the page's file system by the page's script): opened as if dropped.
EMSCRIPTEN_KEEPALIVE void raycam_open_file(const char* path) {
  raycam::web::open_scene_in_steps(raycam::web::page_state(), path);  // with progress (scene_loading.h)
}

// The ids `raycam-cli render --ids` writes for a scene file (its camera as the file says), written to
// `ids_path`; returns 0, or 1 with raycam_last_error() saying why (the CLI's message).
EMSCRIPTEN_KEEPALIVE int raycam_render_ids(const char* scene_path, const char* ids_path) {
  try {
    raycam::ViewFlags flags;
    flags.scene_path = std::string(scene_path);
    return write_view_ids(raycam::session::views_from_setup(raycam::make_view_setup(flags)).on_screen, ids_path);
  } catch (const std::exception& error) {
    last_error = error.what();
    return 1;
  }
}
// The same for the scene and camera on screen (the browser tests: a file opened by the picker's route).
EMSCRIPTEN_KEEPALIVE int raycam_shown_ids(const char* ids_path) {
  return write_view_ids(raycam::web::page_state().view, ids_path);
}
// For scripts/bench_web.py: a 3D scene file's camera at side×side pixels, cast as `raycam-cli bench speed
// --scene FILE --size side` casts it (the automatic caster, the page's one thread). Prepared once per scene
// (parsed, packed and warmed up: the browser compiles WebAssembly quickly first and optimises the code that
// runs often later, as the native bench warms up before it measures), then timed by the script, which also
// reads the page thread's CPU time around raycam_time_prepared_cast from /proc: on a loaded machine the wall
// time counts other programs' turns on the core, the CPU time (as the native bench's) does not.
struct PreparedCast {
  raycam::ViewSetup setup;
  raycam::PackedScene3D packed;  // packed once, as the bench and the app do
  raycam::ColourMap map;         // reused, as the bench reuses its map
  long long casts_timed = 0;     // by the last raycam_time_prepared_cast
};
static std::unique_ptr<PreparedCast> prepared;

// Returns 0, or -1 with raycam_last_error() saying why (the file does not open).
EMSCRIPTEN_KEEPALIVE int raycam_prepare_cast(const char* scene_path, int side) {
  try {
    raycam::ViewFlags flags;
    flags.scene_path = std::string(scene_path);
    flags.camera.size = std::vector<int>{side};
    prepared.reset();  // the previous scene's memory first
    auto next = std::make_unique<PreparedCast>();
    next->setup = raycam::make_view_setup(flags);
    next->packed.pack(next->setup.file.scene3d);
    for (const double start = emscripten_get_now(); emscripten_get_now() - start < 500.0;)
      raycam::cast_primary_rays(next->setup.camera3d, next->packed, next->map);
    prepared = std::move(next);
    return 0;
  } catch (const std::exception& error) {
    last_error = error.what();
    return -1;
  }
}

// The median wall time in milliseconds of a cast of the prepared scene over `repeats` samples, each timing
// casts for at least 20 ms (the browser's clock counts in steps of 0.1 ms); -1 when none is prepared.
EMSCRIPTEN_KEEPALIVE double raycam_time_prepared_cast(int repeats) {
  if (!prepared) return -1.0;
  PreparedCast& p = *prepared;
  std::vector<double> times;
  p.casts_timed = 0;
  for (int i = 0; i < std::max(1, repeats); ++i) {
    const double start = emscripten_get_now();
    int casts = 0;
    double elapsed = 0.0;
    for (; elapsed < 20.0; elapsed = emscripten_get_now() - start, ++casts)
      raycam::cast_primary_rays(p.setup.camera3d, p.packed, p.map);
    times.push_back(elapsed / casts);
    p.casts_timed += casts;
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

// How many casts the last raycam_time_prepared_cast ran (the script divides the CPU time by it).
EMSCRIPTEN_KEEPALIVE double raycam_casts_timed() { return prepared ? double(prepared->casts_timed) : 0.0; }

EMSCRIPTEN_KEEPALIVE const char* raycam_last_error() { return last_error.c_str(); }

// The message the app's status line shows now (the browser tests read the page's errors here).
// Frames drawn since the page opened (the browser test checks that an idle page draws none).
EMSCRIPTEN_KEEPALIVE double raycam_frames_drawn() { return double(raycam::web::page_state().frame_count); }

EMSCRIPTEN_KEEPALIVE const char* raycam_status_message() { return raycam::web::page_state().message.c_str(); }

// 1 when the status line's window shows a scrollbar (what it holds is taller than the line).
EMSCRIPTEN_KEEPALIVE int raycam_status_line_scrolls() {
  const ImGuiWindow* status = ImGui::FindWindowByName("##status");
  return status && (status->ScrollbarY || status->ScrollMax.y > 0.0f) ? 1 : 0;
}

// What the last frame showed, as JSON, for the browser tests: the 3D camera's parameters, the M_d its table
// showed (column-major), whether the image it drew is the colour map of the camera now (the map's version
// and a fresh cast of that camera), where the image was and the θ slider.
EMSCRIPTEN_KEEPALIVE const char* raycam_shown_frame() {
  static std::string json;
  const raycam::session::AppState& state = raycam::web::page_state();
  const raycam::ui::FrameLayout& layout = raycam::web::page_layout();
  const raycam::Orbit3D& o = view3d(state).orbit;
  char number[64];
  const auto add = [&](const char* key, double value) {
    std::snprintf(number, sizeof number, "%.17g", value);
    json += std::string("\"") + key + "\": " + number + ", ";
  };
  json = "{";
  add("dimension", dimension(state));
  add("theta", o.theta);
  add("phi", o.phi);
  add("d", o.d);
  add("df", o.df);
  add("font_scale", state.font_scale);
  add("recording", state.recording ? 1 : 0);
  add("recording_seconds", state.recording_seconds);
  json += "\"target\": [";
  for (int i = 0; i < 3; ++i) {
    std::snprintf(number, sizeof number, "%.17g", o.target[i]);
    json += std::string(i ? ", " : "") + number;
  }
  json += "], \"placement\": [";
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      std::snprintf(number, sizeof number, "%.17g", layout.shown.placement[c][r]);
      json += std::string(c || r ? ", " : "") + number;
    }
  json += "], ";
  add("shown_map_version", double(layout.shown.map_version));
  add("map_version", double(state.map_version));
  const raycam::ColourMap fresh =
      std::visit([](const auto& view) { return raycam::cast_primary_rays(view.camera, view.scene); }, state.view);
  add("map_is_the_camera_s", fresh.ids == state.map.ids ? 1 : 0);
  add("map_width", state.map.width);
  add("map_height", state.map.height);
  const auto rect = [&](const char* key, float x, float y, float w, float h) {
    std::snprintf(number, sizeof number, "[%.3f, %.3f, %.3f, %.3f]", x, y, w, h);
    json += std::string("\"") + key + "\": " + number + ", ";
  };
  rect("image", layout.image.x, layout.image.y, layout.image.w, layout.image.h);
  rect("overhead", layout.overhead.x, layout.overhead.y, layout.overhead.w, layout.overhead.h);
  if (const raycam::ui::WidgetRects* widgets = raycam::web::page_panels().widget_rects) {
    json += "\"widgets\": {";
    for (const auto& [id, r] : *widgets) rect(id.c_str(), r.x0, r.y0, r.x1 - r.x0, r.y1 - r.y0);
    json += "\"end\": 0}, ";
  }
  const raycam::session::CameraCheck& check = raycam::web::page_check();
  json += "\"check_status\": \"" + check.status() + "\", ";
  json += std::string("\"check_state\": \"") + raycam::session::verdict_state_name(check.verdict_state()) + "\", ";
  const raycam::session::CheckHeader header = raycam::session::check_header(raycam::web::page_state().language, check.progress());
  json += "\"check_header\": \"" + (header.forms.empty() ? std::string() : header.forms.front()) + "\", ";
  add("check_wrong_pixels", double(check.wrong_pixels()));
  json += std::string("\"fullscreen_button\": \"") +
          raycam::session::tr(state.language, raycam::ui::fullscreen_label(state)) + "\", ";
  json += "\"end\": 0}";
  return json.c_str();
}

// Check my camera's answer file (the page's answer picker wrote it here): graded at once, against the case
// downloaded last (what the student's program answered), not the camera on screen if it moved since: the
// panel then shows the verdict greyed, for an earlier camera (camera_check.h).
EMSCRIPTEN_KEEPALIVE void raycam_check_answer(const char* path) {
  raycam::web::page_check().give_answer(path);
  raycam::web::wake_page();
}

// The check's clear button, for the browser tests.
EMSCRIPTEN_KEEPALIVE void raycam_clear_check() {
  raycam::web::page_check().clear();
  raycam::web::wake_page();
}

// The check's "Download this camera's case" button, for the browser tests.
EMSCRIPTEN_KEEPALIVE void raycam_download_case() {
  raycam::web::page_check().request().download_case = true;
  raycam::web::wake_page();
}

// Save as under `path`, as a desktop Save as asks (never replacing without asking): in the page the file
// becomes a download, and a name saved twice downloads twice (the browser keeps both). For the browser tests.
EMSCRIPTEN_KEEPALIVE int raycam_save_as(const char* path) {
  const bool saved = raycam::session::save_preset_as(raycam::web::page_state(), path, false) ==
                     raycam::session::SaveAsOutcome::saved;
  raycam::web::wake_page();
  return saved ? 1 : 0;
}
}

int main() {
  chdir("/home/web_user");  // the app writes relative paths here: web_host.cpp offers them as downloads
  raycam::session::AppOptions options;
  options.demo_on_bad_scene = true;
  // Every bad part of the address is shown in the page, each with its reason (a student fixing one would
  // meet the next only after reloading); the other parts still apply.
  std::vector<std::string> errors;
  const auto apply = [&errors](auto&& part) {
    try {
      part();
    } catch (const std::exception& reason) {
      errors.push_back(reason.what());
    }
  };
  apply([&] {
    const std::string lang = query_value("lang");
    if (!lang.empty()) options.language = raycam::parse_language_flag(lang, "?lang");
  });
  if (!options.language)
    options.language = raycam::language_from_code(browser_language()).value_or(raycam::Language::en);
  apply([&] {
    // As --font-scale, with its rule and its words: the projector's size in a bookmark.
    const std::string scale = query_value("scale");
    if (scale.empty()) return;
    const auto rule = raycam::flags::number_in({raycam::session::kFontScaleOptionMin, raycam::session::kFontScaleOptionMax});
    options.font_scale = float(raycam::flags::checked_value(rule, scale, "?scale"));
  });
  const std::string scene = query_value("scene");
  if (!scene.empty()) options.view.scene_path = "/scenes/" + scene;
  static raycam::session::AppState state;
  bool made = false;
  apply([&] {
    state = raycam::session::make_app_state(options);
    made = true;
  });
  if (!made) {  // the demo scene then
    options.view.scene_path.reset();
    state = raycam::session::make_app_state(options);
  }
  raycam::ui::PanelState panels = raycam::ui::panel_state_for(options, state);
  static raycam::ui::WidgetRects widget_rects;  // where the sliders are: the tests' hook
  panels.widget_rects = &widget_rects;
  // A ?scene= that did not open is named as the student named it (NAME, not the page's /scenes/NAME).
  state.message = raycam::session::with_file_shown(raycam::session::kPageHost, state.message,
                                                   options.view.scene_path.value_or(""));
  if (!errors.empty()) {
    state.message.clear();
    for (const std::string& error : errors) {
      std::fprintf(stderr, "raycam: error: %s\n", error.c_str());
      state.message += (state.message.empty() ? "" : "; ") + raycam::session::tr_reason(state.language, error);
    }
    state.message_is_error = true;
  }
  raycam::web::run_page(state, panels);
}
